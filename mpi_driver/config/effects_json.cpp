#include "mpi_driver/config/effects_json.hpp"

#include "engine/contact/model_choice.hpp"
#include "engine/errors.hpp"

namespace blockfrag {

Effects read_effects(const nlohmann::json* value, const JsonPointer& path, ConfigErrors& errors) {
  Effects effects;
  if (value == nullptr) return effects;
  if (value->is_string()) {
    if (*value != "auto") errors.add(path, "must be \"auto\" or a list of effects");
    return effects;
  }
  if (!value->is_array() || value->empty()) {
    errors.add(path, "must be \"auto\" or a non-empty list of effects");
    return effects;
  }
  effects = {
      .automatic = false, .rocking = false, .sliding = false, .impact = false, .flight = false};
  bool readable = true;
  for (std::size_t i = 0; i < value->size(); ++i) {
    const auto name = read_choice((*value)[i], path / i, errors,
                                  {"rocking", "sliding", "impact", "flight", "vertical"});
    if (!name) {
      readable = false;
      continue;
    }
    bool& flag = *name == "rocking"   ? effects.rocking
                 : *name == "sliding" ? effects.sliding
                 : *name == "impact"  ? effects.impact
                 : *name == "flight"  ? effects.flight
                                      : effects.vertical;
    if (flag) errors.add(path / i, "\"" + *name + "\" is listed twice");
    flag = true;
  }
  if (!readable) return effects;
  try {
    model_named_by(effects);
  } catch (const InvalidInput& refused) {
    errors.add(path, std::string(refused.what()).substr(std::string("invalid scene: ").size()));
  }
  return effects;
}

nlohmann::json effects_to_json(const Effects& effects) {
  if (effects.automatic) return "auto";
  return model_effects(effects.vertical ? Model::full_vertical : model_named_by(effects));
}

}  // namespace blockfrag
