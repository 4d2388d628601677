#include "mpi_driver/config/dam_json.hpp"

#include <string>
#include <type_traits>
#include <variant>

#include "engine/motion/dam_crest.hpp"
#include "engine/motion/scene_motion.hpp"
#include "engine/number_text.hpp"
#include "engine/tolerances.hpp"
#include "mpi_driver/config/scene_fields.hpp"

namespace blockfrag {

namespace {

// Each of Fenves & Chopra's dampings is below 1 alone, but the crest filter needs their sum with
// the dam's own below 1 too.
void check_interaction(ObjectReader& reader, const DamCrest& dam) {
  const double damping = dam_mode(dam).damping;
  if (!(damping < 1.0)) {
    reader.errors().add(reader.path(),
                        "the damping with the reservoir and foundation, damping / "
                        "(reservoir_period_ratio foundation_period_ratio^3) + reservoir_damping + "
                        "foundation_damping, must be < 1 (got " +
                            format_number(damping) + ")");
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
    DamPeriod period;
    read_fields<DamPeriod>(reader, scene_fields::dam_period, period);
    dam.stiffness = period;
  } else if (by_size) {
    DamSize size;
    read_fields<DamSize>(reader, scene_fields::dam_size, size);
    dam.stiffness = size;
  } else {
    reader.errors().add(reader.path(), "needs period, or height and elastic_modulus");
  }
  // Underdamped: the crest filter is the damped oscillator's closed form for zeta < 1.
  read_fields<DamCrest>(reader, scene_fields::dam, dam);
  check_interaction(reader, dam);
  reader.finish();
  return dam;
}

nlohmann::json dam_to_json(const DamCrest& dam) {
  nlohmann::json out = nlohmann::json::object();
  write_fields<DamCrest>(dam, scene_fields::dam, out);
  std::visit(
      [&out](const auto& stiffness) {
        using Stiffness = std::decay_t<decltype(stiffness)>;
        if constexpr (std::is_same_v<Stiffness, DamPeriod>) {
          write_fields<DamPeriod>(stiffness, scene_fields::dam_period, out);
        } else {
          write_fields<DamSize>(stiffness, scene_fields::dam_size, out);
        }
      },
      dam.stiffness);
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
