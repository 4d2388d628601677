#include "postproc/fragility/fragility_curve.hpp"

#include <limits>
#include <utility>

#include "postproc/fragility/binomial_interval.hpp"
#include "postproc/fragility/lognormal_fit.hpp"

namespace blockfrag {

FragilityCurve fragility_from_counts(std::vector<double> im, std::vector<std::int64_t> trials,
                                     std::vector<std::int64_t> exceedances) {
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  FragilityCurve curve{std::move(im),
                       std::move(trials),
                       std::move(exceedances),
                       {},
                       {},
                       {},
                       nan,
                       nan,
                       nan,
                       {},
                       nan,
                       nan};
  for (std::size_t k = 0; k < curve.im.size(); ++k) {
    const auto n = curve.trials[k], z = curve.exceedances[k];
    curve.probability.push_back(n > 0 ? static_cast<double>(z) / static_cast<double>(n) : nan);
    const auto interval = n > 0 ? wilson_interval(z, n, 0.95) : ProportionInterval{nan, nan};
    curve.ci_low.push_back(interval.low);
    curve.ci_high.push_back(interval.high);
  }
  const LognormalFit fit = fit_lognormal_fragility(curve.im, curve.trials, curve.exceedances);
  curve.fit_status = fit_status_name(fit.status);
  curve.median_low = fit.median_low;
  curve.median_high = fit.median_high;
  if (fit.status == FitStatus::ok) {
    curve.median = fit.median;
    curve.beta = fit.beta;
    curve.log_likelihood = fit.log_likelihood;
  }
  return curve;
}

}  // namespace blockfrag
