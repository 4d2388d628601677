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
  curve.median = curve.beta = curve.log_likelihood = nan;
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
    const StandardErrors errors =
        fit_standard_errors(curve.im, curve.trials, curve.exceedances, fit);
    curve.median_se = errors.median;
    curve.beta_se = errors.beta;
    const GoodnessOfFit gof =
        goodness_of_fit(curve.im, curve.trials, curve.exceedances, fit.median, fit.beta);
    curve.deviance = gof.deviance;
    curve.gof_dof = gof.dof;
    curve.gof_p_value = gof.p_value;
    curve.max_misfit = gof.max_misfit;
  }
  return curve;
}

}  // namespace blockfrag
