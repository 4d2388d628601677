// A fragility curve from a cloud: every sample carries its own intensity (a record run as recorded)
// and whether it exceeded the limit state. The lognormal fit maximises the per-sample Bernoulli
// likelihood: the binomial fit of lognormal_fit.hpp with the samples grouped by their exact
// intensity (one trial per distinct value, as a rule), so it has the binned fit's separation and
// degenerate-data checks. For display, the samples are also grouped into bins of equal width in
// ln IM, each with its empirical probability and Wilson interval.
#pragma once

#include <cstddef>
#include <vector>

#include "postproc/fragility/fragility_curve.hpp"

namespace blockfrag {

// im[i] > 0 and finite; the curve's im, trials, exceedances, probability and intervals are the
// display bins (empty bins left out, each at the geometric mean of its samples' intensities);
// median, beta, log_likelihood and the fit's status are the per-sample fit's.
FragilityCurve fragility_from_samples(const std::vector<double>& im,
                                      const std::vector<bool>& exceeded, std::size_t bins = 10);

}  // namespace blockfrag
