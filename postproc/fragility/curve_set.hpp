// A study's limit states as damage states of one component: in order of severity (a more severe
// state has a larger median), and with the fitted curves that cross, which cannot be damage states
// of one component (P(DS >= k) must not exceed P(DS >= k - 1) at any intensity).
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

#include "postproc/fragility/fragility_curve.hpp"

namespace blockfrag {

// Indices of the curves from least to most severe: by fitted median; a curve without a fit goes
// by where the data place its median (the middle of median_low and median_high, in logs), after
// the fitted ones it ties with. Equal medians keep the curves' order.
std::vector<std::size_t> severity_order(const std::vector<FragilityCurve>& curves);

// Where two lognormal curves cross: Phi(ln(x / m1) / b1) = Phi(ln(x / m2) / b2) at
// ln x = (b2 ln m1 - b1 ln m2) / (b2 - b1); none (NaN) for equal betas and different medians.
double crossing_intensity(double median1, double beta1, double median2, double beta2);

// The pairs (i < j) of fitted curves that cross at an intensity inside [low, high].
std::vector<std::pair<std::size_t, std::size_t>> crossing_pairs(
    const std::vector<FragilityCurve>& curves, double low, double high);

}  // namespace blockfrag
