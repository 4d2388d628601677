#include "mpi_driver/config/dam_json.hpp"

#include <string>

#include "engine/motion/dam_crest.hpp"
#include "engine/motion/scene_motion.hpp"
#include "engine/number_text.hpp"

namespace blockfrag {

namespace {

// Fenves & Chopra's reservoir and foundation. Each damping is below 1 alone, but the crest filter
// needs their sum with the dam's own below 1 too.
void read_interaction(ObjectReader& reader, DamCrest& dam) {
  const Range ratio = Range::of(domain::dam_period_ratio);
  const Range added = Range::of(domain::dam_added_damping);
  dam.reservoir_period_ratio =
      reader.number_or("reservoir_period_ratio", dam.reservoir_period_ratio, ratio);
  dam.reservoir_damping = reader.number_or("reservoir_damping", dam.reservoir_damping, added);
  dam.foundation_period_ratio =
      reader.number_or("foundation_period_ratio", dam.foundation_period_ratio, ratio);
  dam.foundation_damping = reader.number_or("foundation_damping", dam.foundation_damping, added);
  const double damping = dam_mode(dam).damping;
  if (!(damping < 1.0)) {
    reader.errors().add(reader.path(),
                        "the damping with the reservoir and foundation, damping / "
                        "(reservoir_period_ratio foundation_period_ratio^3) + reservoir_damping + "
                        "foundation_damping, must be < 1 (got " +
                            format_number(damping) + ")");
  }
}

// Fenves & Chopra's keys are written only when they change the dam, so a scene without them keeps
// its canonical form (and a study its hash).
void write_interaction(const DamCrest& dam, nlohmann::json& out) {
  const DamCrest defaults;
  if (dam.reservoir_period_ratio != defaults.reservoir_period_ratio) {
    out["reservoir_period_ratio"] = dam.reservoir_period_ratio;
  }
  if (dam.reservoir_damping != defaults.reservoir_damping) {
    out["reservoir_damping"] = dam.reservoir_damping;
  }
  if (dam.foundation_period_ratio != defaults.foundation_period_ratio) {
    out["foundation_period_ratio"] = dam.foundation_period_ratio;
  }
  if (dam.foundation_damping != defaults.foundation_damping) {
    out["foundation_damping"] = dam.foundation_damping;
  }
}

}  // namespace

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
  read_interaction(reader, dam);
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
  write_interaction(dam, out);
  return out;
}

std::optional<std::string> crest_history_problem(const Scene& scene) {
  if (!scene.dam) return std::nullopt;
  const CrestExtent crest = scene_crest_extent(scene);
  if (crest.nodes <= kMaxCrestNodes) return std::nullopt;
  const double period = dam_mode(*scene.dam).period;
  const bool lengthened = period != dam_period(*scene.dam);
  return "the dam's period (" + format_number(period) +
         (lengthened ? " s, with its reservoir and foundation" : " s") +
         ") is too short for the run (" + format_number(crest.horizon) +
         " s): the crest motion would need " + std::to_string(crest.nodes) +
         " nodes (one per period / 100), more than " + std::to_string(kMaxCrestNodes) +
         "; give a longer period, or a duration or max_duration that ends the run sooner";
}

}  // namespace blockfrag
