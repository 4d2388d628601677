#include "postproc/fragility/binomial_interval.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <gsl/gsl_cdf.h>

namespace blockfrag {
namespace {

void check_arguments(std::int64_t successes, std::int64_t trials, double confidence) {
  if (trials <= 0)
    throw IntervalError("binomial interval: trials must be > 0 (got " + std::to_string(trials) +
                        ")");
  if (successes < 0 || successes > trials)
    throw IntervalError("binomial interval: successes must lie in [0, " + std::to_string(trials) +
                        "] (got " + std::to_string(successes) + ")");
  if (!(confidence > 0.0 && confidence < 1.0))
    throw IntervalError("binomial interval: confidence must lie in (0, 1) (got " +
                        std::to_string(confidence) + ")");
}

// The p with cdf(p) = target for a continuous increasing cdf on [0, 1] with 0 < target < 1.
// gsl_cdf_beta_Pinv is not used: it fails to converge for ordinary arguments (Beta(3, 258) at
// 0.975, i.e. 2 of 260) and then calls the GSL error handler, whose default aborts the process.
// gsl_cdf_beta_P instead returns NaN when its continued fraction does not converge.
// Illinois regula falsi with a bisection fallback: never leaves the bracket, stops at a relative
// width of a few ulps, and a tiny root (1 of 10^8 trials: 2.5e-10) costs some 30 bisections.
template <class Cdf>
double invert_cdf(const Cdf& cdf, double target) {
  double low = 0.0, high = 1.0;
  double f_low = -target, f_high = 1.0 - target;
  int side = 0;
  for (int iteration = 0; iteration < 300; ++iteration) {
    const double width = high - low;
    if (width <= 4.0 * std::numeric_limits<double>::epsilon() * high) break;
    double p = low + f_low * width / (f_low - f_high);
    if (!(p > low + 0.01 * width && p < high - 0.01 * width)) p = low + 0.5 * width;
    const double f = cdf(p) - target;
    if (!std::isfinite(f))
      throw IntervalError(
          "Clopper-Pearson interval: the incomplete beta function did not converge");
    if (f == 0.0) return p;
    if (f < 0.0) {
      low = p;
      f_low = f;
      if (side == -1) f_high *= 0.5;
      side = -1;
    } else {
      high = p;
      f_high = f;
      if (side == 1) f_low *= 0.5;
      side = 1;
    }
  }
  return low + 0.5 * (high - low);
}

}  // namespace

ProportionInterval wilson_interval(std::int64_t successes, std::int64_t trials, double confidence) {
  check_arguments(successes, trials, confidence);
  const double n = static_cast<double>(trials);
  const double p = static_cast<double>(successes) / n;
  const double z = gsl_cdf_ugaussian_Qinv(0.5 * (1.0 - confidence));
  const double z2_n = z * z / n;
  const double centre = (p + 0.5 * z2_n) / (1.0 + z2_n);
  const double half_width = z / (1.0 + z2_n) * std::sqrt(p * (1.0 - p) / n + 0.25 * z2_n / n);
  // At 0 and n successes the bound is exactly 0 or 1; the formula gets it only up to rounding.
  return {successes == 0 ? 0.0 : std::max(0.0, centre - half_width),
          successes == trials ? 1.0 : std::min(1.0, centre + half_width)};
}

ProportionInterval clopper_pearson_interval(std::int64_t successes, std::int64_t trials,
                                            double confidence) {
  check_arguments(successes, trials, confidence);
  const double tail = 0.5 * (1.0 - confidence);
  const double x = static_cast<double>(successes);
  const double n = static_cast<double>(trials);
  // The bounds are the tail quantile of Beta(x, n - x + 1) and the 1 - tail quantile of
  // Beta(x + 1, n - x); solving for them directly keeps their full relative accuracy near 0.
  const double low =
      successes == 0
          ? 0.0
          : invert_cdf([&](double q) { return gsl_cdf_beta_P(q, x, n - x + 1.0); }, tail);
  const double high =
      successes == trials
          ? 1.0
          : invert_cdf([&](double q) { return gsl_cdf_beta_P(q, x + 1.0, n - x); }, 1.0 - tail);
  return {low, high};
}

ProportionInterval binomial_interval(IntervalMethod method, std::int64_t successes,
                                     std::int64_t trials, double confidence) {
  switch (method) {
    case IntervalMethod::wilson: return wilson_interval(successes, trials, confidence);
    case IntervalMethod::clopper_pearson:
      return clopper_pearson_interval(successes, trials, confidence);
  }
  throw IntervalError("binomial interval: unknown method");
}

}  // namespace blockfrag
