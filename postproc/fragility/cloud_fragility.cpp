#include "postproc/fragility/cloud_fragility.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <vector>

#include "postproc/fragility/binomial_interval.hpp"
#include "postproc/fragility/fit_diagnostics.hpp"
#include "postproc/fragility/lognormal_fit.hpp"

namespace blockfrag {

FragilityCurve fragility_from_samples(const std::vector<double>& im,
                                      const std::vector<bool>& exceeded, std::size_t bins) {
  if (im.size() != exceeded.size())
    throw FitError("cloud fragility: im and exceeded differ in size");
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  // The fit: samples grouped by their exact intensity.
  std::map<double, std::pair<std::int64_t, std::int64_t>> groups;  // im -> (trials, exceedances)
  for (std::size_t i = 0; i < im.size(); ++i) {
    auto& [trials, exceedances] = groups[im[i]];
    ++trials;
    if (exceeded[i]) ++exceedances;
  }
  std::vector<double> distinct;
  std::vector<std::int64_t> trials, exceedances;
  for (const auto& [x, counts] : groups) {
    distinct.push_back(x);
    trials.push_back(counts.first);
    exceedances.push_back(counts.second);
  }
  const LognormalFit fit = fit_lognormal_fragility(distinct, trials, exceedances);

  // The display bins: equal widths in ln IM from the smallest intensity to the largest.
  FragilityCurve curve;
  curve.median = curve.beta = curve.log_likelihood = nan;
  curve.fit_status = fit_status_name(fit.status);
  curve.median_low = fit.median_low;
  curve.median_high = fit.median_high;
  if (fit.status == FitStatus::ok) {
    curve.median = fit.median;
    curve.beta = fit.beta;
    curve.log_likelihood = fit.log_likelihood;
    const StandardErrors errors = fit_standard_errors(distinct, trials, exceedances, fit);
    curve.median_se = errors.median;
    curve.beta_se = errors.beta;
  }
  if (im.empty() || bins == 0) return curve;
  const double low = std::log(distinct.front()), high = std::log(distinct.back());
  const double width = high > low ? (high - low) / static_cast<double>(bins) : 1.0;
  std::vector<double> log_sum(bins, 0.0), bin_expected(bins, 0.0);
  std::vector<std::int64_t> bin_trials(bins, 0), bin_exceedances(bins, 0);
  for (std::size_t i = 0; i < im.size(); ++i) {
    const double position = (std::log(im[i]) - low) / width;
    const auto k = std::min(bins - 1, static_cast<std::size_t>(std::max(0.0, position)));
    log_sum[k] += std::log(im[i]);
    ++bin_trials[k];
    if (exceeded[i]) ++bin_exceedances[k];
    if (fit.status == FitStatus::ok) {
      bin_expected[k] +=
          0.5 * std::erfc(-std::log(im[i] / fit.median) / (fit.beta * std::sqrt(2.0)));
    }
  }
  std::vector<double> expected;
  for (std::size_t k = 0; k < bins; ++k) {
    const std::int64_t n = bin_trials[k], z = bin_exceedances[k];
    if (n == 0) continue;
    curve.im.push_back(std::exp(log_sum[k] / static_cast<double>(n)));
    curve.trials.push_back(n);
    curve.exceedances.push_back(z);
    curve.probability.push_back(static_cast<double>(z) / static_cast<double>(n));
    const ProportionInterval interval = wilson_interval(z, n, 0.95);
    curve.ci_low.push_back(interval.low);
    curve.ci_high.push_back(interval.high);
    expected.push_back(bin_expected[k]);
  }
  // Goodness of fit over the display bins (Hosmer & Lemeshow's grouping): each bin's expected
  // exceedances are the sum of its samples' fitted probabilities.
  if (fit.status == FitStatus::ok) {
    const GoodnessOfFit gof =
        goodness_of_fit(curve.im, curve.trials, curve.exceedances, fit.median, fit.beta, expected);
    curve.deviance = gof.deviance;
    curve.gof_dof = gof.dof;
    curve.gof_p_value = gof.p_value;
    curve.max_misfit = gof.max_misfit;
  }
  return curve;
}

}  // namespace blockfrag
