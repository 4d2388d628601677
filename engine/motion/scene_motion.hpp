// The ground motion a scene's block feels, as pieces the integrator can step through.
#pragma once

#include <cstddef>

#include "engine/motion/ground_motion.hpp"
#include "engine/scene/scene.hpp"

namespace blockfrag {

// Horizontal: lambda, the ground's acceleration over -g (through the dam crest when there is one).
GroundMotionPieces scene_motion(const Scene& scene);
// Vertical: lambda_v, the ground's upward acceleration over g (at the foundation: the dam filter is
// horizontal only).
GroundMotionPieces scene_vertical_motion(const Scene& scene);

// Where the run stops at the latest: the scene's duration, or (settling) its max_duration, or
// kSettleAllowance after the last of its motions ends.
double run_end_time(const Scene& scene, const GroundMotionPieces& motion,
                    const GroundMotionPieces& vertical);

// The crest history a scene's run needs: its nodes, which scene_motion refuses beyond
// kMaxCrestNodes (engine/tolerances.hpp), and the time it covers (s). None without a dam.
struct CrestExtent {
  std::size_t nodes = 0;
  double horizon = 0.0;
};
CrestExtent scene_crest_extent(const Scene& scene);

}  // namespace blockfrag
