#include "mpi_driver/config/reservoir_json.hpp"

#include <string>

#include "engine/number_text.hpp"

namespace blockfrag {

const char* hydrodynamic_name(Hydrodynamic hydrodynamic) {
  switch (hydrodynamic) {
    case Hydrodynamic::none: return "none";
    case Hydrodynamic::westergaard: return "westergaard";
  }
  return "unknown";
}

const char* uplift_rule_name(UpliftRule rule) {
  switch (rule) {
    case UpliftRule::none: return "none";
    case UpliftRule::unchanged: return "unchanged";
    case UpliftRule::zero_in_gap: return "zero_in_gap";
    case UpliftRule::full_head_in_gap: return "full_head_in_gap";
  }
  return "unknown";
}

std::optional<Reservoir> read_reservoir(ObjectReader reader, std::optional<double> lowest_y) {
  if (!reader.valid()) return std::nullopt;
  Reservoir reservoir;
  const auto level = reader.required_number("level", Range::of(domain::reservoir_level));
  reservoir.level = level.value_or(reservoir.level);
  const auto depth = reader.number("depth", Range::of(domain::reservoir_depth));
  reservoir.depth = depth.value_or(reservoir.depth);
  reservoir.density =
      reader.number_or("density", reservoir.density, Range::of(domain::water_density));
  if (const auto name = reader.choice("hydrodynamic", {"none", "westergaard"})) {
    reservoir.hydrodynamic = *name == "none" ? Hydrodynamic::none : Hydrodynamic::westergaard;
  }
  if (const auto name =
          reader.choice("uplift", {"none", "unchanged", "zero_in_gap", "full_head_in_gap"})) {
    if (*name == "none") reservoir.uplift = UpliftRule::none;
    if (*name == "zero_in_gap") reservoir.uplift = UpliftRule::zero_in_gap;
    if (*name == "full_head_in_gap") reservoir.uplift = UpliftRule::full_head_in_gap;
  }
  reservoir.uplift_area_factor = reader.number_or(
      "uplift_area_factor", reservoir.uplift_area_factor, Range::of(domain::uplift_area_factor));
  const bool depth_valid = depth || !reader.has("depth");
  if (level && lowest_y && depth_valid && !(reservoir.depth >= reservoir.level - *lowest_y)) {
    reader.add_error("depth",
                     "must be >= the water's depth at the block, level minus the block's "
                     "lowest y (" +
                         format_number(reservoir.level - *lowest_y) + " m) (got " +
                         format_number(reservoir.depth) + ")");
  }
  reader.finish();
  return reservoir;
}

nlohmann::json reservoir_to_json(const Reservoir& reservoir) {
  return {{"level", reservoir.level},
          {"depth", reservoir.depth},
          {"density", reservoir.density},
          {"hydrodynamic", hydrodynamic_name(reservoir.hydrodynamic)},
          {"uplift", uplift_rule_name(reservoir.uplift)},
          {"uplift_area_factor", reservoir.uplift_area_factor}};
}

}  // namespace blockfrag
