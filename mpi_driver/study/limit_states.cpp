#include "mpi_driver/study/limit_states.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "engine/errors.hpp"
#include "postproc/fragility/cloud_fragility.hpp"
#include "sampling/philox_stream.hpp"

namespace blockfrag {

bool exceeds(const LimitState& state, const SampleRecord& record, double alpha) {
  const bool lost = record.overturned != 0 || record.fell != 0;
  if (lost && state.overturned_exceeds) return true;
  switch (state.kind) {
    case LimitStateKind::overturning: return lost;
    case LimitStateKind::max_rotation: return record.max_abs_theta / alpha > state.threshold;
    case LimitStateKind::residual_slide: return std::abs(record.final_slide) > state.threshold;
    // NaN (no factor: the block does not stand at rest at the end) compares false.
    case LimitStateKind::post_earthquake_unstable:
      return record.post_earthquake_safety_factor < state.threshold;
  }
  return false;
}

namespace {

// A cloud's bootstrap resamples every sample: at most this many draws in all (about a minute).
constexpr double kMaxCloudBootstrapDraws = 2e8;
// A stripe study's resample draws every level's count and refits over every level: at most this
// many levels times resamples (about 2 s), so a grid of thousands of levels is not held up by it.
constexpr double kMaxStripeBootstrapLevelResamples = 1e6;

// The resamples the config asks for, or fewer when each costs `per_resample` of a budget.
int affordable_resamples(const StudyConfig& config, double budget, std::size_t per_resample) {
  const double affordable = budget / std::max<double>(1.0, static_cast<double>(per_resample));
  return static_cast<int>(std::min<double>(config.bootstrap_resamples, affordable));
}

}  // namespace

UniformDraw bootstrap_uniforms(std::uint64_t seed, const std::string& limit_state) {
  const std::uint32_t stream = stream_id("bootstrap/" + limit_state);
  return [seed, stream](std::uint64_t resample, std::uint64_t draw) {
    return uniform_open01(seed, stream, resample, static_cast<std::uint32_t>(draw));
  };
}

FragilityCurve stripe_curve(const StudyConfig& config, const LimitState& state,
                            std::vector<std::int64_t> trials,
                            std::vector<std::int64_t> exceedances) {
  FragilityCurve curve =
      fragility_from_counts(config.intensity.levels, std::move(trials), std::move(exceedances));
  const int resamples =
      affordable_resamples(config, kMaxStripeBootstrapLevelResamples, curve.im.size());
  if (curve.fit_status == "ok" && resamples > 0) {
    curve.bootstrap = bootstrap_stripes(curve.im, curve.trials, curve.exceedances, resamples,
                                        bootstrap_uniforms(config.seed, state.name));
  }
  return curve;
}

FragilityCurve cloud_curve(const StudyConfig& config, const LimitState& state,
                           const std::vector<double>& im, const std::vector<bool>& exceeded) {
  FragilityCurve curve = fragility_from_samples(im, exceeded);
  const int resamples = affordable_resamples(config, kMaxCloudBootstrapDraws, im.size());
  if (curve.fit_status == "ok" && resamples > 0) {
    curve.bootstrap =
        bootstrap_cloud(im, exceeded, resamples, bootstrap_uniforms(config.seed, state.name));
  }
  return curve;
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
    return cloud_curve(config, state, im, exceeded);
  }
  const std::size_t levels = config.intensity.levels.size();
  std::vector<std::int64_t> trials(levels, 0), exceedances(levels, 0);
  for (std::size_t i = 0; i < records.size(); ++i) {
    const auto& record = records[i];
    if (record.status != static_cast<std::int64_t>(SampleStatus::ok)) continue;
    const auto level = config.intensity.first_level(static_cast<std::size_t>(record.index) /
                                                    config.samples_per_level);
    ++trials[level];
    if (exceeds(state, record, alphas[i])) ++exceedances[level];
  }
  return stripe_curve(config, state, std::move(trials), std::move(exceedances));
}

}  // namespace blockfrag
