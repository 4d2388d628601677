// The horizontal ground motion a scene's block feels, as pieces the integrator can step through.
#pragma once

#include "engine/ground_motion.hpp"
#include "engine/scene.hpp"

namespace blockfrag {

GroundMotionPieces scene_motion(const Scene& scene);

}  // namespace blockfrag
