#include "postproc/fragility/fit_diagnostics.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include <gsl/gsl_cdf.h>

#include "postproc/fragility/normal_probability.hpp"

namespace blockfrag {
namespace {

// z ln(z / e), 0 when z = 0.
double term(double z, double expected) { return z > 0 ? z * std::log(z / expected) : 0.0; }

}  // namespace

StandardErrors fit_standard_errors(std::span<const double> im, std::span<const std::int64_t> trials,
                                   std::span<const std::int64_t> exceedances,
                                   const LognormalFit& fit) {
  if (fit.status != FitStatus::ok) throw FitError("standard errors need a fit with status ok");
  // The Hessian of ln L in (ln median, ln beta) by central differences: ln L is smooth and its
  // curvature changes over the scale of the parameters themselves, so a step of 1e-4 in each log
  // gives the second derivatives to about 1e-8 of their size.
  const double h = 1e-4;
  const double u0 = std::log(fit.median), v0 = std::log(fit.beta);
  const auto ll = [&](double u, double v) {
    return lognormal_log_likelihood(im, trials, exceedances, std::exp(u), std::exp(v));
  };
  const double f0 = ll(u0, v0);
  const double huu = (ll(u0 + h, v0) - 2 * f0 + ll(u0 - h, v0)) / (h * h);
  const double hvv = (ll(u0, v0 + h) - 2 * f0 + ll(u0, v0 - h)) / (h * h);
  const double huv =
      (ll(u0 + h, v0 + h) - ll(u0 + h, v0 - h) - ll(u0 - h, v0 + h) + ll(u0 - h, v0 - h)) /
      (4 * h * h);
  // The observed information is minus the Hessian; its inverse is the covariance.
  const double det = huu * hvv - huv * huv;
  const double var_u = -hvv / det, var_v = -huu / det;
  return {fit.median * std::sqrt(var_u), fit.beta * std::sqrt(var_v)};
}

GoodnessOfFit goodness_of_fit(std::span<const double> im, std::span<const std::int64_t> trials,
                              std::span<const std::int64_t> exceedances, double median, double beta,
                              std::span<const double> expected_exceedances) {
  GoodnessOfFit gof{0.0, -2, std::numeric_limits<double>::quiet_NaN(), 0.0};
  for (std::size_t j = 0; j < im.size(); ++j) {
    const auto n = static_cast<double>(trials[j]), z = static_cast<double>(exceedances[j]);
    if (n <= 0) continue;
    ++gof.dof;
    const double expected = expected_exceedances.empty()
                                ? n * normal_cdf(std::log(im[j] / median) / beta)
                                : expected_exceedances[j];
    gof.deviance += 2 * (term(z, expected) + term(n - z, n - expected));
    gof.max_misfit = std::max(gof.max_misfit, std::abs(z / n - expected / n));
  }
  gof.dof = std::max(gof.dof, 0);
  if (gof.dof >= 1) gof.p_value = gsl_cdf_chisq_Q(gof.deviance, gof.dof);
  return gof;
}

}  // namespace blockfrag
