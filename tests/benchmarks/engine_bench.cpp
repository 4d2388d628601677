// Per-scene cost of a few representative scenes of configs/accuracy_suite.json with each method,
// side by side in one run: the paper's RK4 at dt = 0.00025 s, the production default (adaptive
// 1e-8), the adaptive method at a looser 1e-6, and GSL's rkf45 and rk8pd at 1e-8. Counters report
// the steps and right-hand-side evaluations of one run. The accuracy each setting buys is measured
// by `blockfrag accuracy` (docs/accuracy.md), not here.
#include <filesystem>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "engine/simulate.hpp"
#include "mpi_driver/accuracy/accuracy_settings.hpp"
#include "mpi_driver/accuracy/accuracy_suite.hpp"

namespace blockfrag {
namespace {

const char* const representative_scenes[] = {"paper_example",     "rock_free_release",
                                             "slide_rectangular", "sliderock_cosine",
                                             "bounce_cosine_e09", "overturn_cosine"};

const SolverSetting compared_settings[] = {{Method::rk4, 2.5e-4},
                                           {Method::adaptive, 1e-8},
                                           {Method::adaptive, 1e-6},
                                           {Method::gsl_rkf45, 1e-8},
                                           {Method::gsl_rk8pd, 1e-8}};

void run_scene(benchmark::State& state, Scene scene) {
  Summary summary;
  for (auto _ : state) {
    summary = simulate(scene);
    benchmark::DoNotOptimize(summary);
  }
  if (summary.status != Status::ok) state.SkipWithError(summary.status_reason.c_str());
  state.counters["steps"] = static_cast<double>(summary.steps);
  state.counters["rhs_evaluations"] = static_cast<double>(summary.rhs_evaluations);
}

// Registered before main runs, grouped by scene so each scene's methods are read side by side.
const bool registered = [] {
  const AccuracySuite suite = read_accuracy_suite(std::filesystem::path(BLOCKFRAG_SOURCE_DIR) /
                                                  "configs/accuracy_suite.json");
  for (const char* name : representative_scenes) {
    for (const auto& entry : suite.scenes) {
      if (entry.name != name) continue;
      for (const SolverSetting& setting : compared_settings) {
        Scene scene = entry.scene;
        scene.solver = with_setting(scene.solver, setting);
        benchmark::RegisterBenchmark((entry.name + "/" + setting_label(setting)).c_str(), run_scene,
                                     scene)
            ->Unit(benchmark::kMicrosecond);
      }
    }
  }
  return true;
}();

}  // namespace
}  // namespace blockfrag
