#include "mpi_driver/accuracy/accuracy_study.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "engine/simulate.hpp"

namespace blockfrag {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

Scene with_solver(Scene scene, const SolverSetting& setting) {
  scene.solver = with_setting(scene.solver, setting);
  return scene;
}

}  // namespace

TimedRun timed_run(const Scene& scene, double min_batch_seconds, int batches) {
  TimedRun run;
  const auto warm_up_start = Clock::now();
  run.summary = simulate(scene);
  const double first = seconds_since(warm_up_start);
  run.repeats = first >= min_batch_seconds
                    ? 1
                    : static_cast<long>(std::ceil(min_batch_seconds / std::max(first, 1e-9)));
  run.seconds = first;
  for (int batch = 0; batch < batches; ++batch) {
    const auto start = Clock::now();
    for (long i = 0; i < run.repeats; ++i) simulate(scene);
    run.seconds = std::min(run.seconds, seconds_since(start) / static_cast<double>(run.repeats));
  }
  return run;
}

SettingResult evaluate_setting(const SolverSetting& setting, std::vector<TimedRun> runs,
                               const std::vector<Summary>& reference) {
  SettingResult result{setting, std::move(runs), {}, {}};
  std::vector<double> seconds;
  std::vector<long> rhs_evaluations, steps;
  for (std::size_t i = 0; i < result.runs.size(); ++i) {
    const TimedRun& run = result.runs[i];
    result.errors.push_back(output_errors(reference.at(i), run.summary));
    seconds.push_back(run.seconds);
    rhs_evaluations.push_back(run.summary.rhs_evaluations);
    steps.push_back(run.summary.steps);
  }
  result.statistics = setting_statistics(result.errors, seconds, rhs_evaluations, steps);
  return result;
}

AccuracyStudy run_accuracy_study(const AccuracySuite& suite, const AccuracyStudyOptions& options) {
  AccuracyStudy study;
  study.reference_setting = {Method::adaptive, options.reference_tolerance};
  study.check_setting = {Method::gsl_rk8pd, options.reference_tolerance};
  study.min_batch_seconds = options.min_batch_seconds;

  // Scene by scene, every setting back to back: a change in the machine's load while the study runs
  // then touches all settings of a scene alike instead of skewing whole settings against each
  // other.
  std::vector<TimedRun> check_runs;
  std::vector<std::vector<TimedRun>> runs(options.settings.size());
  for (const SuiteScene& entry : suite.scenes) {
    if (options.progress) options.progress(entry.name);
    study.scene_names.push_back(entry.name);
    study.scene_categories.push_back(entry.category);
    study.reference.push_back(simulate(with_solver(entry.scene, study.reference_setting)));
    // The check is run once, untimed in effect: its cost is not the point.
    check_runs.push_back(timed_run(with_solver(entry.scene, study.check_setting), 0.0, 0));
    for (std::size_t k = 0; k < options.settings.size(); ++k) {
      runs[k].push_back(
          timed_run(with_solver(entry.scene, options.settings[k]), options.min_batch_seconds));
    }
  }
  const SettingResult check =
      evaluate_setting(study.check_setting, std::move(check_runs), study.reference);
  for (const TimedRun& run : check.runs) study.check.push_back(run.summary);
  study.check_errors = check.errors;
  study.check_statistics = check.statistics;
  for (std::size_t k = 0; k < options.settings.size(); ++k) {
    study.settings.push_back(
        evaluate_setting(options.settings[k], std::move(runs[k]), study.reference));
  }
  return study;
}

}  // namespace blockfrag
