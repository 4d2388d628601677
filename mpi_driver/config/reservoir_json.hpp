// The scene's "reservoir" (engine/scene/reservoir.hpp), and back:
//   {"level": 16.7, "depth": 100.0, "density": 1000.0, "hydrodynamic": "westergaard",
//    "uplift": "unchanged", "uplift_area_factor": 1.0}
// level is required; the others default as above. An absent "reservoir" is no water.
#pragma once

#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "engine/scene/scene.hpp"
#include "mpi_driver/config/config_reader.hpp"

namespace blockfrag {

// Errors are recorded at their paths; the depth is checked against the block's lowest point
// (lowest_y, the block's vertices' frame) when the level is valid: the reservoir is at least as
// deep as the water against the block.
std::optional<Reservoir> read_reservoir(ObjectReader reader, std::optional<double> lowest_y);
// Every key, defaults included (a scene with a reservoir names all of it in its canonical form).
nlohmann::json reservoir_to_json(const Reservoir& reservoir);

std::string hydrodynamic_name(Hydrodynamic hydrodynamic);
std::string uplift_rule_name(UpliftRule rule);

}  // namespace blockfrag
