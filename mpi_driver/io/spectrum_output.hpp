// An overturning spectrum's HDF5 output, written by rank 0 once the map and every bisection are
// done, through a fresh temporary file, fsync, rename and fsync of the folder (atomic_file.hpp).
// docs/spectra.md documents every dataset and attribute; in short:
//
//   /            attributes config (canonical JSON), config_hash, blockfrag_version, pulse, alpha,
//                tan_alpha, R, p, g, the definitions of the two ratios, units
//   /map         frequency_ratio[nf], amplitude_ratio[na], pulse_time_s[nf], amplitude_g[na];
//                verdict, impacts, max_abs_theta, overturn_time [nf][na]
//   /boundary    one entry per crossing: frequency_index, frequency_ratio, amplitude_ratio,
//                amplitude_low, amplitude_high, direction, verdict_low, verdict_high, iterations,
//                state
//   /minimum_overturning   one entry per frequency: frequency_ratio, amplitude_ratio (refined),
//                amplitude_low, amplitude_high, verdict_high, map_amplitude_ratio (the map's
//                lowest onset, unrefined), state, midpoints
//
// Everything but the root's blockfrag_version depends only on the config.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include "mpi_driver/config/spectrum_config.hpp"
#include "mpi_driver/io/record_spool.hpp"
#include "mpi_driver/study/minimum_overturning.hpp"
#include "mpi_driver/study/spectrum_bisection.hpp"

namespace blockfrag {

// What the output holds, in numbers, for the run's last message.
struct SpectrumTally {
  std::int64_t points = 0, overturned = 0, failed = 0;
  std::int64_t onsets = 0, island_edges = 0;  // crossings by direction
  std::int64_t converged = 0;                 // crossings bisected to the tolerance
  // Frequencies whose minimum: the refinement found below the map's lowest onset; was found to its
  // tolerance (state 1); lies below the grid; is uncertain (a failed point, or max_midpoints).
  std::int64_t minima_lowered = 0, minima_found = 0, minima_below_grid = 0, minima_uncertain = 0;
};

// The spool holds every map point's record; brackets are the final crossings, minimum the final
// minimum refinement.
SpectrumTally write_spectrum_output(const std::filesystem::path& path, const SpectrumConfig& config,
                                    const RecordSpool& spool,
                                    const std::vector<SpectrumBracket>& brackets,
                                    const MinimumRefinement& minimum);

}  // namespace blockfrag
