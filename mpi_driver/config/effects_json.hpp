// The scene's "effects": "auto" or a list of effect names, and back.
#pragma once

#include <nlohmann/json.hpp>

#include "engine/scene/scene.hpp"
#include "mpi_driver/config/config_reader.hpp"

namespace blockfrag {

// Absent means "auto". Unknown names, repeats and sets that name no model are errors at the path.
Effects read_effects(const nlohmann::json* value, const JsonPointer& path, ConfigErrors& errors);
nlohmann::json effects_to_json(const Effects& effects);

}  // namespace blockfrag
