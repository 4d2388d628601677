#include "postproc/fragility/fragility_curve.hpp"

#include <limits>
#include <utility>

#include "postproc/fragility/binomial_interval.hpp"
#include "postproc/fragility/fit_diagnostics.hpp"
#include "postproc/fragility/lognormal_fit.hpp"

namespace blockfrag {

FragilityCurve fragility_from_counts(std::vector<double> im, std::vector<std::int64_t> trials,
                                     std::vector<std::int64_t> exceedances) {
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  FragilityCurve curve;
  curve.im = std::move(im);
  curve.trials = std::move(trials);
  curve.exceedances = std::move(exceedances);
  for (std::size_t k = 0; k < curve.im.size(); ++k) {
    const auto n = curve.trials[k], z = curve.exceedances[k];
    curve.probability.push_back(n > 0 ? static_cast<double>(z) / static_cast<double>(n) : nan);
    const auto interval = n > 0 ? wilson_interval(z, n, 0.95) : ProportionInterval{nan, nan};
    curve.ci_low.push_back(interval.low);
    curve.ci_high.push_back(interval.high);
  }
  const LognormalFit fit = fit_lognormal_fragility(curve.im, curve.trials, curve.exceedances);
  fill_lognormal_fit(curve, fit, curve.im, curve.trials, curve.exceedances);
  if (fit.status == FitStatus::ok) {
    fill_goodness_of_fit(
        curve, goodness_of_fit(curve.im, curve.trials, curve.exceedances, fit.median, fit.beta));
  }
  return curve;
}

void fill_lognormal_fit(FragilityCurve& curve, const LognormalFit& fit, std::span<const double> im,
                        std::span<const std::int64_t> trials,
                        std::span<const std::int64_t> exceedances) {
  curve.median = curve.beta = curve.log_likelihood = std::numeric_limits<double>::quiet_NaN();
  curve.fit_status = fit_status_name(fit.status);
  curve.median_low = fit.median_low;
  curve.median_high = fit.median_high;
  if (fit.status != FitStatus::ok) return;
  curve.median = fit.median;
  curve.beta = fit.beta;
  curve.log_likelihood = fit.log_likelihood;
  const StandardErrors errors = fit_standard_errors(im, trials, exceedances, fit);
  curve.median_se = errors.median;
  curve.beta_se = errors.beta;
}

void fill_goodness_of_fit(FragilityCurve& curve, const GoodnessOfFit& gof) {
  curve.deviance = gof.deviance;
  curve.gof_dof = gof.dof;
  curve.gof_p_value = gof.p_value;
  curve.max_misfit = gof.max_misfit;
}

}  // namespace blockfrag
