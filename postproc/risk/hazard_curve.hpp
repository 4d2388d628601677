// A site's seismic hazard curve: the mean annual rate lambda(x) at which the intensity measure
// exceeds x, known at a list of intensities. Between them it is a power law (straight in log-log,
// the way hazard curves are drawn and interpolated), except on a segment whose far end has rate
// 0, where the rate falls linearly in ln x (a power law cannot reach 0).
#pragma once

#include <string>
#include <vector>

#include "engine/errors.hpp"

namespace blockfrag {

struct HazardCurve {
  std::vector<double> im;           // increasing, finite, > 0; at least two
  std::vector<double> annual_rate;  // of exceeding im: finite, >= 0, non-increasing, first > 0
};

// Throws ContractViolation saying what is wrong with a curve that breaks the rules above (the
// readers check a user's file and name its lines first).
void check_hazard_curve(const HazardCurve& curve);

// lambda(x) for im.front() <= x <= im.back(), interpolated as above.
double hazard_rate(const HazardCurve& curve, double x);

// The slope -d lambda / d ln x at x in segment i (im[i] <= x <= im[i + 1]): the density in ln x
// of the motions that occur, which the fragility weighs.
double hazard_density(const HazardCurve& curve, std::size_t segment, double x);

}  // namespace blockfrag
