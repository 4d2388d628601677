// The work-precision study: every scene of a suite with every solver setting, each compared with a
// tight reference and timed.
//
// The reference of a scene is the adaptive Dormand-Prince method at reference_tolerance (1e-14: the
// tightest at which its agreement with the paper's RK4 still improves; 1e-15 is at round-off). It
// is checked against GSL's rk8pd (another method, another code) at the same tolerance, and that
// check is reported beside the study. GSL's event times come from a cubic Hermite interpolant over
// long steps, so the check bounds the reference loosely (about 1e-8 s in event times); the paper's
// RK4 at dt = 0.00025 s, a row of the study, agrees with the reference far more closely.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "engine/scene/scene.hpp"
#include "engine/summary.hpp"
#include "mpi_driver/accuracy/accuracy_metrics.hpp"
#include "mpi_driver/accuracy/accuracy_settings.hpp"
#include "mpi_driver/accuracy/accuracy_suite.hpp"

namespace blockfrag {

// One scene's result and its cost per run.
struct TimedRun {
  Summary summary;
  double seconds = 0.0;  // per run
  long repeats = 0;      // runs per timed batch
};

// Runs the scene once (a warm-up whose summary is kept), then times batches of k runs, k chosen so
// a batch takes at least min_batch_seconds, and keeps the fastest batch's time per run: the cost
// the scene itself needs, least disturbed by whatever else the machine is doing.
TimedRun timed_run(const Scene& scene, double min_batch_seconds, int batches = 3);

struct AccuracyStudyOptions {
  std::vector<SolverSetting> settings = full_accuracy_settings();
  double reference_tolerance = 1e-14;
  double min_batch_seconds = 2e-3;
  // Called before each scene with its name (progress for a long run); may be empty.
  std::function<void(const std::string&)> progress;
};

struct SettingResult {
  SolverSetting setting;
  std::vector<TimedRun> runs;        // per scene
  std::vector<OutputErrors> errors;  // per scene, against the reference
  SettingStatistics statistics;
};

struct AccuracyStudy {
  SolverSetting reference_setting;
  SolverSetting check_setting;
  std::vector<std::string> scene_names;
  std::vector<std::string> scene_categories;
  std::vector<Summary> reference;          // per scene
  std::vector<Summary> check;              // per scene
  std::vector<OutputErrors> check_errors;  // check against reference, per scene
  SettingStatistics check_statistics;      // of check_errors (its times are the check's)
  std::vector<SettingResult> settings;
  double min_batch_seconds = 0.0;
};

// Per-scene errors and statistics of `runs` against `reference`.
SettingResult evaluate_setting(const SolverSetting& setting, std::vector<TimedRun> runs,
                               const std::vector<Summary>& reference);

AccuracyStudy run_accuracy_study(const AccuracySuite& suite, const AccuracyStudyOptions& options);

}  // namespace blockfrag
