#include "mpi_driver/config/dam_json.hpp"

#include <string>

#include "engine/motion/dam_crest.hpp"
#include "engine/motion/scene_motion.hpp"
#include "engine/number_text.hpp"

namespace blockfrag {

std::optional<DamCrest> read_dam(ObjectReader reader) {
  if (!reader.valid()) return std::nullopt;
  DamCrest dam;
  const bool by_period = reader.has("period");
  const bool has_height = reader.has("height"), has_modulus = reader.has("elastic_modulus");
  const bool by_size = has_height || has_modulus;
  if (by_period && by_size) {
    reader.add_error("period", "give either period or height and elastic_modulus, not both");
  } else if (by_period) {
    dam.stiffness = DamPeriod{reader.required_number("period", Range::of(domain::dam_period))
                                  .value_or(DamPeriod{}.period)};
  } else if (by_size) {
    DamSize size;
    size.height =
        reader.required_number("height", Range::of(domain::dam_height)).value_or(size.height);
    size.elastic_modulus =
        reader.required_number("elastic_modulus", Range::of(domain::elastic_modulus))
            .value_or(size.elastic_modulus);
    dam.stiffness = size;
  } else {
    reader.errors().add(reader.path(), "needs period, or height and elastic_modulus");
  }
  // Underdamped: the crest filter is the damped oscillator's closed form for zeta < 1.
  dam.damping = reader.number_or("damping", dam.damping, Range::of(domain::dam_damping));
  dam.participation =
      reader.number_or("participation", dam.participation, Range::of(domain::participation));
  reader.finish();
  return dam;
}

nlohmann::json dam_to_json(const DamCrest& dam) {
  nlohmann::json out = {{"damping", dam.damping}, {"participation", dam.participation}};
  if (const auto* given = std::get_if<DamPeriod>(&dam.stiffness)) {
    out["period"] = given->period;
  } else {
    const auto& size = std::get<DamSize>(dam.stiffness);
    out["height"] = size.height;
    out["elastic_modulus"] = size.elastic_modulus;
  }
  return out;
}

std::optional<std::string> crest_history_problem(const Scene& scene) {
  if (!scene.dam) return std::nullopt;
  const CrestExtent crest = scene_crest_extent(scene);
  if (crest.nodes <= kMaxCrestNodes) return std::nullopt;
  return "the dam's period (" + format_number(dam_period(*scene.dam)) +
         " s) is too short for the run (" + format_number(crest.horizon) +
         " s): the crest motion would need " + std::to_string(crest.nodes) +
         " nodes (one per period / 100), more than " + std::to_string(kMaxCrestNodes) +
         "; give a longer period, or a duration or max_duration that ends the run sooner";
}

}  // namespace blockfrag
