// What `blockfrag risk` reads of a study output: its fits (fragility_fits.hpp, with every check
// export makes), and for each limit state the counts behind its points and its bootstrap:
//   /                  attribute config (JSON text): its "seed", the bootstrap's random numbers'
//   /fragility         attribute scaling: "stripes" or "none (a cloud ...)"
//   /fragility/<name>  datasets trials, exceedances (one per level of im: integers, 0 <=
//                      exceedances <= trials); attribute bootstrap_resamples (the resamples run,
//                      0 to 100,000; absent: none)
// read in a child process, as export reads the fits (isolated_fits.hpp).
#pragma once

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <vector>

#include "mpi_driver/io/fragility_fits.hpp"

namespace blockfrag {

struct StateCounts {
  std::vector<std::int64_t> trials;  // per level of the state's im
  std::vector<std::int64_t> exceedances;
  int bootstrap_resamples = 0;
};

struct RiskStudy {
  FragilityFits fits;
  std::vector<StateCounts> counts;  // per fits.states
  std::uint64_t seed = 0;
  bool cloud = false;  // points are display bins; the bootstrap resampled samples
};

// Throws InvalidInput naming the file and the object, as read_fragility_fits does, and for
// counts or a config that break the layout above; also when reading crashes HDF5, takes more than
// 1 GB or longer than `limit` (read_in_child.hpp).
RiskStudy read_risk_study_isolated(const std::filesystem::path& path,
                                   std::chrono::milliseconds limit);

}  // namespace blockfrag
