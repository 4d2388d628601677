// What a scene document's reading reports: the ConfigError's what(), or "(accepted)".
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "mpi_driver/config/config_reader.hpp"
#include "mpi_driver/config/scene_json.hpp"

namespace blockfrag::testing {

inline std::string scene_errors(const nlohmann::json& document,
                                const std::string& source = "scene.json") {
  try {
    scene_from_json(document, source);
  } catch (const ConfigError& error) {
    return error.what();
  }
  return "(accepted)";
}

}  // namespace blockfrag::testing
