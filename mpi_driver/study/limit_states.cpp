#include "mpi_driver/study/limit_states.hpp"

#include <cmath>
#include <utility>

#include "engine/errors.hpp"
#include "postproc/fragility/cloud_fragility.hpp"

namespace blockfrag {

bool exceeds(const LimitState& state, const SampleRecord& record, double alpha) {
  switch (state.kind) {
    case LimitStateKind::overturning: return record.overturned != 0;
    case LimitStateKind::max_rotation:
      return record.overturned != 0 || record.max_abs_theta / alpha > state.threshold;
    case LimitStateKind::residual_slide: return std::abs(record.final_slide) > state.threshold;
  }
  return false;
}

FragilityCurve fragility_curve(const StudyConfig& config, const LimitState& state,
                               const std::vector<SampleRecord>& records,
                               const std::vector<double>& alphas, const std::vector<double>& ims) {
  if (config.intensity.cloud) {
    if (ims.size() != records.size())
      throw ContractViolation("a cloud's fragility needs every sample's intensity");
    std::vector<double> im;
    std::vector<bool> exceeded;
    for (std::size_t i = 0; i < records.size(); ++i) {
      if (records[i].status != static_cast<std::int64_t>(SampleStatus::ok)) continue;
      im.push_back(ims[i]);
      exceeded.push_back(exceeds(state, records[i], alphas[i]));
    }
    return fragility_from_samples(im, exceeded);
  }
  const std::size_t levels = config.intensity.levels.size();
  std::vector<std::int64_t> trials(levels, 0), exceedances(levels, 0);
  for (std::size_t i = 0; i < records.size(); ++i) {
    const auto& record = records[i];
    if (record.status != static_cast<std::int64_t>(SampleStatus::ok)) continue;
    const auto level = static_cast<std::size_t>(record.index) / config.samples_per_level;
    ++trials[level];
    if (exceeds(state, record, alphas[i])) ++exceedances[level];
  }
  return fragility_from_counts(config.intensity.levels, std::move(trials), std::move(exceedances));
}

}  // namespace blockfrag
