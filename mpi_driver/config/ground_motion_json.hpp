// A scene's "ground_motion" and "vertical_motion", and back. "type" selects the motion and its
// keys (mpi_driver/config/scene_fields.hpp's MotionKeys); a record's "file" is read here, with
// mpi_driver/config/record_file.hpp, so a record that cannot be used is refused with the scene.
#pragma once

#include <filesystem>

#include <nlohmann/json.hpp>

#include "engine/scene/scene.hpp"
#include "mpi_driver/config/config_reader.hpp"

namespace blockfrag {

// Errors are recorded at their paths; a record's relative "file" is taken from base_folder.
GroundMotion read_ground_motion(ObjectReader reader, const std::filesystem::path& base_folder);

// Every key of the motion's type, defaults filled in (a pulse's centre t0 too).
nlohmann::json ground_motion_to_json(const GroundMotion& motion);

}  // namespace blockfrag
