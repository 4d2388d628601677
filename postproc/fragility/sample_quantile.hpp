// The q-quantile of a sample, as the bootstrap's intervals, the risk's intervals and the accuracy
// study's medians take it.
#pragma once

#include <vector>

namespace blockfrag {

// The q-quantile (0 <= q <= 1) with linear interpolation between order statistics (Hyndman & Fan
// type 7, numpy's default); NaN for no values. +inf values sort last.
double sample_quantile(std::vector<double> values, double q);

}  // namespace blockfrag
