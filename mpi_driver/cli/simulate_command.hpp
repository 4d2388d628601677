// `blockfrag simulate SCENE.json [--summary-json] [--history FILE.csv] [--history-interval
// SECONDS]`: one scene, its summary on stdout (a short report, or exactly one JSON object), and
// optionally its time history as CSV.
#pragma once

#include <filesystem>
#include <optional>
#include <ostream>

#include "engine/scene/scene.hpp"
#include "engine/summary.hpp"
#include "mpi_driver/cli/exit_codes.hpp"

namespace blockfrag {

struct SimulateOptions {
  std::filesystem::path scene_path;
  bool summary_json = false;
  std::optional<std::filesystem::path> history_path;
  double history_interval = 0.005;  // s
};

// Runs the command and returns its exit code: 0, or exit_code_simulation_failed. Throws
// ConfigError for a bad scene, InputFileError when the scene cannot be read and FileError
// when the history cannot be written.
int run_simulate(const SimulateOptions& options, std::ostream& out);

// The human-readable report: verdict, rotation against alpha, onset times, impacts, modes.
void write_simulate_report(std::ostream& out, const Scene& scene, const Summary& summary);

}  // namespace blockfrag
