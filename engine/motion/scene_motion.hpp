// The ground motion a scene's block feels, as pieces the integrator can step through.
#pragma once

#include "engine/motion/ground_motion.hpp"
#include "engine/scene/scene.hpp"

namespace blockfrag {

// Horizontal: lambda, the ground's acceleration over -g (through the dam crest when there is one).
GroundMotionPieces scene_motion(const Scene& scene);
// Vertical: lambda_v, the ground's upward acceleration over g (at the foundation: the dam filter is
// horizontal only).
GroundMotionPieces scene_vertical_motion(const Scene& scene);

}  // namespace blockfrag
