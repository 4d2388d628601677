// How far one simulation's outputs are from the reference's, and the statistics of a setting over
// the suite.
#pragma once

#include <vector>

#include "engine/summary.hpp"

namespace blockfrag {

// Absolute errors against the reference. A failed simulation has every error +inf. The first impact
// time: 0 when neither run has an impact, +inf when only one has.
struct OutputErrors {
  double max_abs_theta = 0.0;      // rad
  double final_theta = 0.0;        // rad
  double final_slide = 0.0;        // m
  double first_impact_time = 0.0;  // s
  bool wrong_verdict = false;      // overturned differs from the reference (or the run failed)
  bool failed = false;
};

OutputErrors output_errors(const Summary& reference, const Summary& candidate);

// The accuracy in max |theta| the production default must reach on every scene of the suite.
inline constexpr double max_abs_theta_target = 1e-6;  // rad

// One setting over the whole suite (every per-scene vector indexed like the suite).
struct SettingStatistics {
  OutputErrors max_error;       // the largest error of each output over the scenes (flags: any)
  OutputErrors median_error;    // the median of each output's errors (flags unused)
  long scenes_over_target = 0;  // scenes whose error in max |theta| exceeds max_abs_theta_target
  long wrong_verdicts = 0;
  double wrong_verdict_rate = 0.0;  // wrong_verdicts / scenes
  long failures = 0;
  double median_seconds = 0.0;  // time per scene
  double p95_seconds = 0.0;
  double median_rhs_evaluations = 0.0;  // per scene
  double mean_rhs_evaluations = 0.0;
  double median_steps = 0.0;
};

SettingStatistics setting_statistics(const std::vector<OutputErrors>& errors,
                                     const std::vector<double>& seconds,
                                     const std::vector<long>& rhs_evaluations,
                                     const std::vector<long>& steps);

}  // namespace blockfrag
