// The scene's "dam": the block stands on a gravity dam's crest (engine/motion/dam_crest.hpp), and
// back.
#pragma once

#include <optional>

#include <nlohmann/json.hpp>

#include "engine/scene/scene.hpp"
#include "mpi_driver/config/config_reader.hpp"

namespace blockfrag {

// {"period": s} or {"height": m, "elastic_modulus": Pa}, with "damping" (0.05) and
// "participation" (1). An absent "dam" is no dam; errors are recorded at their paths.
std::optional<DamCrest> read_dam(ObjectReader reader);
nlohmann::json dam_to_json(const DamCrest& dam);

}  // namespace blockfrag
