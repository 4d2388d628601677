#include "mpi_driver/config/reservoir_json.hpp"

#include <string>

#include "engine/number_text.hpp"
#include "mpi_driver/config/scene_fields.hpp"

namespace blockfrag {

std::string hydrodynamic_name(Hydrodynamic hydrodynamic) {
  return std::string(hydrodynamic_names.name(hydrodynamic));
}

std::string uplift_rule_name(UpliftRule rule) { return std::string(uplift_rule_names.name(rule)); }

std::optional<Reservoir> read_reservoir(ObjectReader reader, std::optional<double> lowest_y) {
  if (!reader.valid()) return std::nullopt;
  Reservoir reservoir;
  const FieldsRead read = read_fields<Reservoir>(reader, scene_fields::reservoir, reservoir);
  const bool depth_valid = read.valid("depth") || !reader.has("depth");
  if (read.valid("level") && lowest_y && depth_valid &&
      !(reservoir.depth >= reservoir.level - *lowest_y)) {
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
  nlohmann::json out = nlohmann::json::object();
  write_fields<Reservoir>(reservoir, scene_fields::reservoir, out);
  return out;
}

}  // namespace blockfrag
