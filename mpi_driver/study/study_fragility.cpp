#include "mpi_driver/study/study_fragility.hpp"

#include <cmath>
#include <limits>

#include "postproc/fragility/binomial_interval.hpp"
#include "postproc/fragility/lognormal_fit.hpp"

namespace blockfrag {
namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

}  // namespace

bool exceeds(const LimitState& state, const SampleRecord& record, double alpha) {
  switch (state.kind) {
    case LimitStateKind::overturning: return record.overturned != 0;
    case LimitStateKind::max_rotation: return record.overturned != 0 || record.max_abs_theta / alpha > state.threshold;
    case LimitStateKind::residual_slide: return std::abs(record.final_slide) > state.threshold;
  }
  return false;
}

FragilityCurve fragility_curve(const StudyConfig& config, const LimitState& state,
                               const std::vector<SampleRecord>& records, const std::vector<double>& alphas) {
  const std::size_t levels = config.intensity.levels.size();
  FragilityCurve curve{config.intensity.levels, std::vector<std::int64_t>(levels, 0),
                       std::vector<std::int64_t>(levels, 0), {}, {}, {}, nan, nan, nan, {}, nan, nan};
  for (std::size_t i = 0; i < records.size(); ++i) {
    const auto& record = records[i];
    if (record.status != static_cast<std::int64_t>(SampleStatus::ok)) continue;
    const auto level = static_cast<std::size_t>(record.index) / config.samples_per_level;
    ++curve.trials[level];
    if (exceeds(state, record, alphas[i])) ++curve.exceedances[level];
  }
  for (std::size_t k = 0; k < levels; ++k) {
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
