// The limit states of a study fitted jointly with one common beta: P_k(x) = Phi(ln(x / theta_k) /
// beta), maximising the sum of every state's binomial log-likelihood over (theta_1 .. theta_K,
// beta). Curves of one beta never cross (P_k - P_l has the sign of ln(theta_l / theta_k) at every
// x), so they are damage states of one component a loss tool can subtract, where separate fits
// (lognormal_fit.hpp), each with its own beta, cross somewhere. The maximum is found on the profile
// likelihood: for a given beta each theta_k maximises its own state's concave log-likelihood in
// ln theta_k; beta maximises their sum.
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace blockfrag {

struct NestedStateData {
  std::vector<double> im;  // > 0 and finite
  std::vector<std::int64_t> trials;
  std::vector<std::int64_t> exceedances;
};

struct NestedFit {
  static constexpr double nan = std::numeric_limits<double>::quiet_NaN();

  std::string status = "no limit state";  // "ok", or why there is no fit
  std::vector<double> median;             // per state given
  std::vector<double> median_se;          // asymptotic, from the observed information
  double beta = nan;
  double beta_se = nan;
  double log_likelihood = nan;  // with the binomial coefficients, summed over the states

  bool ok() const { return status == "ok"; }
};

// Each state must have a separate fit (exceedances at some level, not at every one, and
// overlapping proportions): the caller passes those. The common beta is looked for in
// [0.005, 10]; a maximum at either end is reported as such, not as a fit, and more than 5,000
// levels over the states (a second's work) are not fitted.
NestedFit fit_nested_lognormal(const std::vector<NestedStateData>& states);

}  // namespace blockfrag
