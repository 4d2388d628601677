// `blockfrag statics SCENE.json [--coefficient K] [--summary-json]`: the scene's block at rest
// under its reservoir (engine/water/block_statics.hpp): its weight and water loads, the ground
// accelerations at which it starts to slide or rock either way, and at a seismic coefficient K the
// pseudo-static safety factors. A short report, or exactly one JSON object
// (mpi_driver/io/statics_json.hpp). Per metre of dam when the block's mass is per metre.
#pragma once

#include <filesystem>
#include <optional>
#include <ostream>

namespace blockfrag {

struct StaticsOptions {
  std::filesystem::path scene_path;
  std::optional<double> coefficient;  // K >= 0
  bool summary_json = false;
};

// Returns 0. Throws ConfigError for a bad scene, InputFileError when it cannot be read.
int run_statics(const StaticsOptions& options, std::ostream& out);

}  // namespace blockfrag
