// Which model a scene runs: the one its effects name, or for "auto" the cheapest one that gives the
// full model's answer for these inputs.
#pragma once

#include "engine/motion/ground_motion.hpp"
#include "engine/scene/block_geometry.hpp"
#include "engine/scene/scene.hpp"
#include "engine/summary.hpp"

namespace blockfrag {

// Throws InvalidInput for a set of effects that names no model.
Model model_named_by(const Effects& effects);

// Whether the effects' model has the rocking impacts a rocking restitution sets: "auto", the full
// model and Housner's with impact (Housner's without impact changes the pivot without loss, and
// Newmark's never rocks).
inline bool has_rocking_impacts(const Effects& effects) {
  return effects.automatic || (effects.rocking && effects.impact);
}

// "auto" prunes only what is impossible:
// - the ground never reaches friction or either tipping threshold: the block rests throughout;
// - friction is below both tipping thresholds and below the flat-sliding limit (mu <= a/b for a
//   rectangle): from rest it can only slide, and sliding flat it stays flat, so it never rocks,
//   impacts or flies (Shenton): Newmark's model is exact.
// Friction above the largest lambda does not rule out sliding: a rocking block's friction demand
// includes the centripetal and angular terms, and impacts slip. So anything else runs in full.
Model choose_model(const Scene& scene, const GroundMotionPieces& motion,
                   const BlockGeometry& geometry);

}  // namespace blockfrag
