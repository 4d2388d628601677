// What a lognormal fragility fit is worth: the standard errors of its median and beta from the
// observed information (the curvature of ln L at the maximum), and how far the data leave the
// lognormal shape (the deviance against the saturated binomial model and its chi-square p-value).
#pragma once

#include <cstdint>
#include <span>

#include "postproc/fragility/lognormal_fit.hpp"

namespace blockfrag {

struct StandardErrors {
  double median;  // of the median, in the intensity's unit
  double beta;
};

// From the inverse of the observed information in (ln median, ln beta), by the delta method:
// SE(median) = median SE(ln median), SE(beta) = beta SE(ln beta). The same data as the fit; the fit
// must have status ok.
StandardErrors fit_standard_errors(std::span<const double> im, std::span<const std::int64_t> trials,
                                   std::span<const std::int64_t> exceedances,
                                   const LognormalFit& fit);

struct GoodnessOfFit {
  // 2 sum_j [z ln(z / (n p)) + (n - z) ln((n - z) / (n (1 - p)))], 0 ln 0 = 0: twice the log
  // likelihood ratio of the saturated model (p_j = z_j / n_j) to the fit.
  double deviance;
  int dof;         // levels with trials - 2
  double p_value;  // P(chi-square with dof degrees of freedom > deviance); NaN when dof < 1
  // The largest |z_j / n_j - p_j| over the levels with trials: how far the points leave the curve.
  double max_misfit;
};

// The expected counts are sum_j of the fitted probabilities: `expected_exceedances[j]` when given
// (a cloud's display bins, whose samples sit at different intensities), n_j Phi(ln(x_j / median) /
// beta) otherwise.
GoodnessOfFit goodness_of_fit(std::span<const double> im, std::span<const std::int64_t> trials,
                              std::span<const std::int64_t> exceedances, double median, double beta,
                              std::span<const double> expected_exceedances = {});

}  // namespace blockfrag
