#include "engine/scene_motion.hpp"

#include "engine/dam_crest.hpp"

namespace blockfrag {

GroundMotionPieces scene_motion(const Scene& scene) {
  GroundMotionPieces foundation(scene.ground_motion, scene.g);
  if (!scene.dam) return foundation;
  return dam_crest_motion(foundation, *scene.dam, scene.duration, scene.g);
}

}  // namespace blockfrag
