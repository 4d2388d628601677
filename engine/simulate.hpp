// The engine's entry point: one scene in, its summary (and optionally its time history) out.
#pragma once

#include <vector>

#include "engine/scene/scene.hpp"
#include "engine/summary.hpp"

namespace blockfrag {

// Never throws for a physically odd scene: failures (a budget exceeded) come back as
// Summary::status. Throws InvalidInput for a scene that breaks the scene's rules
// (engine/errors.hpp).
Summary simulate(const Scene& scene);

// Where a run of the scene stops at the latest (s): its duration, or for a settling run its
// max_duration or the default cap after the last excitation. Throws InvalidInput for an invalid
// scene.
double scene_run_end_time(const Scene& scene);

struct SimulationWithHistory {
  Summary summary;
  std::vector<HistoryRow> history;  // rows at t = 0, dt, 2 dt, ... and the end time
  std::vector<ImpactRecord> impacts;
};
SimulationWithHistory simulate_with_history(const Scene& scene, double output_interval);

}  // namespace blockfrag
