#include "engine/contact/model_choice.hpp"

#include <algorithm>

#include "engine/errors.hpp"

namespace blockfrag {

const char* model_name(Model model) {
  switch (model) {
    case Model::at_rest: return "at_rest";
    case Model::newmark_sliding: return "newmark_sliding";
    case Model::housner_rocking: return "housner_rocking";
    case Model::full: return "full";
    case Model::full_vertical: return "full_vertical";
  }
  return "unknown";
}

std::vector<const char*> model_effects(Model model) {
  switch (model) {
    case Model::at_rest: return {};
    case Model::newmark_sliding: return {"sliding"};
    case Model::housner_rocking: return {"rocking", "impact"};
    case Model::full: return {"rocking", "sliding", "impact", "flight"};
    case Model::full_vertical: return {"rocking", "sliding", "impact", "flight", "vertical"};
  }
  return {};
}

Model model_named_by(const Effects& effects) {
  if (effects.automatic) return Model::full;
  const Effects& e = effects;
  if (e.rocking && e.sliding && e.impact && e.flight) return Model::full;
  if (e.vertical) {
    throw InvalidInput(
        "invalid scene: effects: vertical ground motion needs the full model (rocking, sliding, "
        "impact, flight)");
  }
  if (e.rocking && !e.sliding && !e.flight) return Model::housner_rocking;
  if (e.sliding && !e.rocking && !e.impact && !e.flight) return Model::newmark_sliding;
  throw InvalidInput(
      "invalid scene: effects name no model: use [\"rocking\"] or [\"rocking\", \"impact\"] "
      "(Housner), [\"sliding\"] (Newmark), all of rocking, sliding, impact, flight (full), or "
      "\"auto\"");
}

Model choose_model(const Scene& scene, const GroundMotionPieces& motion,
                   const BlockGeometry& geometry) {
  if (!std::holds_alternative<NoMotion>(scene.vertical_motion)) return Model::full_vertical;
  if (!scene.effects.automatic) return model_named_by(scene.effects);
  const double mu = scene.contact.friction;
  const double tip =
      std::min(geometry.tip_threshold(Corner::left), geometry.tip_threshold(Corner::right));
  // A block released tilted or turning is already rocking.
  if (scene.initial.theta != 0.0 || scene.initial.omega != 0.0) return Model::full;
  if (motion.peak_abs_lambda() < std::min(mu, tip)) return Model::at_rest;
  if (mu < tip && mu <= geometry.flat_slide_friction_limit()) return Model::newmark_sliding;
  return Model::full;
}

}  // namespace blockfrag
