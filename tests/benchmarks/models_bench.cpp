// What each model costs on the same scenes: Housner's rocking block, Newmark's sliding block,
// "auto" and the full model, each over one grid of 36 scenes (slender to stocky blocks, low to high
// friction, pulses from below onset to overturning). Time is per scene (items are scenes); the
// counters give the steps and right-hand-side evaluations per scene. Compare ratios within one run.
#include <vector>

#include <benchmark/benchmark.h>

#include "engine/simulate.hpp"

namespace blockfrag {
namespace {

std::vector<Scene> scene_grid(const Effects& effects) {
  std::vector<Scene> scenes;
  for (const double aspect : {0.2, 0.5, 1.5}) {
    for (const double mu : {0.3, 0.7}) {
      for (const double amplitude : {0.1, 0.4, 1.0}) {
        for (const double period : {0.5, 1.5}) {
          Scene scene;
          scene.effects = effects;
          scene.block = {aspect * 1.0, 1.0, 1.0};
          scene.contact = {mu, 0.7};
          scene.ground_motion = SinePulse{amplitude, period, 2.0};
          scene.duration = 5.0;
          scenes.push_back(scene);
        }
      }
    }
  }
  return scenes;
}

void run_grid(benchmark::State& state, Effects effects) {
  const std::vector<Scene> scenes = scene_grid(effects);
  long steps = 0, rhs = 0;
  for (auto _ : state) {
    steps = rhs = 0;
    for (const Scene& scene : scenes) {
      const Summary summary = simulate(scene);
      steps += summary.steps;
      rhs += summary.rhs_evaluations;
      benchmark::DoNotOptimize(summary);
    }
  }
  state.SetItemsProcessed(state.iterations() * static_cast<long>(scenes.size()));
  const double n = static_cast<double>(scenes.size());
  state.counters["steps_per_scene"] = static_cast<double>(steps) / n;
  state.counters["rhs_per_scene"] = static_cast<double>(rhs) / n;
}

const bool registered = [] {
  const auto add = [](const char* name, Effects effects) {
    benchmark::RegisterBenchmark(name, run_grid, effects)->Unit(benchmark::kMicrosecond);
  };
  add("models/housner_rocking",
      {.automatic = false, .rocking = true, .sliding = false, .impact = true, .flight = false});
  add("models/newmark_sliding",
      {.automatic = false, .rocking = false, .sliding = true, .impact = false, .flight = false});
  add("models/auto", {});
  add("models/full", {.automatic = false});
  return true;
}();

}  // namespace
}  // namespace blockfrag
