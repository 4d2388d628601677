#include "mpi_driver/config/minimum_overturning_json.hpp"

namespace blockfrag {

// The largest max_midpoints: with the grid's 100,000 frequencies, rank 0 keeps at most this many
// probed intervals per frequency in memory.
constexpr double kMaxMinimumMidpoints = 100'000;

MinimumOverturningSettings read_minimum_overturning(ObjectReader reader) {
  MinimumOverturningSettings settings;
  settings.tolerance = reader.number_or("tolerance", settings.tolerance, Range::closed(1e-9, 0.1));
  settings.resolution =
      reader.number_or("resolution", settings.resolution, Range::closed(1e-9, 0.1));
  settings.near_overturning =
      reader.number_or("near_overturning", settings.near_overturning, Range::closed(0.0, 1.0));
  settings.max_midpoints =
      reader.integer_or("max_midpoints", settings.max_midpoints,
                        Range::closed(1, kMaxMinimumMidpoints).labelled("1", "100000"));
  reader.finish();
  return settings;
}

nlohmann::json minimum_overturning_to_json(const MinimumOverturningSettings& settings) {
  return {{"tolerance", settings.tolerance},
          {"resolution", settings.resolution},
          {"near_overturning", settings.near_overturning},
          {"max_midpoints", settings.max_midpoints}};
}

}  // namespace blockfrag
