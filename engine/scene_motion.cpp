#include "engine/scene_motion.hpp"

namespace blockfrag {

GroundMotionPieces scene_motion(const Scene& scene) { return GroundMotionPieces(scene.ground_motion); }

}  // namespace blockfrag
