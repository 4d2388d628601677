#include "mpi_driver/study/fragility_tally.hpp"

#include <algorithm>
#include <limits>

#include "mpi_driver/study/limit_states.hpp"
#include "postproc/fragility/curve_set.hpp"

namespace blockfrag {

FragilityTally::FragilityTally(const StudyConfig& config)
    : config_(config),
      trials_(
          config.limit_states.size(),
          std::vector<std::int64_t>(config.intensity.cloud ? 0 : config.intensity.level_count())),
      exceedances_(trials_),
      cloud_exceeded_(config.limit_states.size()),
      im_low_(std::numeric_limits<double>::infinity()),
      im_high_(-std::numeric_limits<double>::infinity()) {}

void FragilityTally::add(const SampleRecord& record, double alpha, double im) {
  im_low_ = std::min(im_low_, im);
  im_high_ = std::max(im_high_, im);
  if (record.status != static_cast<std::int64_t>(SampleStatus::ok)) return;
  const std::size_t states = config_.limit_states.size();
  if (config_.intensity.cloud) {
    cloud_im_.push_back(im);
    for (std::size_t k = 0; k < states; ++k) {
      cloud_exceeded_[k].push_back(exceeds(config_.limit_states[k], record, alpha));
    }
    return;
  }
  const auto level = static_cast<std::size_t>(record.index) / config_.samples_per_level;
  for (std::size_t k = 0; k < states; ++k) {
    ++trials_[k][level];
    if (exceeds(config_.limit_states[k], record, alpha)) ++exceedances_[k][level];
  }
}

StudyFragility FragilityTally::finish() const {
  StudyFragility fragility;
  for (std::size_t k = 0; k < config_.limit_states.size(); ++k) {
    const LimitState& state = config_.limit_states[k];
    const IntensityMeasure& measure = config_.intensity;
    if (measure.cloud) {
      fragility.curves.push_back(cloud_curve(config_, state, cloud_im_, cloud_exceeded_[k]));
    } else if (measure.surface()) {
      const std::size_t n2 = measure.periods.size();
      fragility.curves.push_back(stripe_curve(config_, state, summed_over_im2(trials_[k], n2),
                                              summed_over_im2(exceedances_[k], n2)));
      fragility.surfaces.push_back(
          surface_from_counts(measure.levels, measure.periods, trials_[k], exceedances_[k]));
    } else {
      fragility.curves.push_back(stripe_curve(config_, state, trials_[k], exceedances_[k]));
    }
  }
  fragility.severity = severity_order(fragility.curves);
  if (config_.intensity.cloud) {
    fragility.nested.status = "not fitted for a cloud";
  } else {
    std::vector<NestedStateData> data;
    for (const std::size_t k : fragility.severity) {
      const FragilityCurve& curve = fragility.curves[k];
      if (curve.fit_status != "ok") continue;
      data.push_back({curve.im, curve.trials, curve.exceedances});
      fragility.nested_states.push_back(k);
    }
    fragility.nested = fit_nested_lognormal(data);
  }
  if (im_low_ <= im_high_)
    fragility.crossings = crossing_pairs(fragility.curves, im_low_, im_high_);
  return fragility;
}

}  // namespace blockfrag
