// `blockfrag bench SCENE.json [--repeat N]`: the cost of one scene. Runs it once to warm up, then N
// times, timing each run, and prints exactly one JSON object:
//   {"scene": ..., "solver": {...}, "repeat": N, "median_us": ..., "min_us": ..., "max_us": ...,
//    "steps": ..., "rhs_evaluations": ..., "summary": {...}}
// "solver" is the solver actually used (a scene that names none gets SolverSettings' default);
// "summary" is summary_to_json of the run (every run gives the same one).
#pragma once

#include <filesystem>
#include <ostream>

namespace blockfrag {

// Every run's time is kept for the median: a million runs keep 8 MB.
inline constexpr long kMaxBenchRepeats = 1'000'000;

struct BenchOptions {
  std::filesystem::path scene_path;
  long repeat = 20;
};

// Returns 0, or exit_code_simulation_failed (exit_codes.hpp) when the scene's status is
// "failed" (the JSON is still printed). Throws ConfigError for a bad scene.
int run_bench(const BenchOptions& options, std::ostream& out);

}  // namespace blockfrag
