// A spectrum's "minimum_overturning" key: how finely each frequency's minimum overturning amplitude
// is refined below what the map and its bisection find (mpi_driver/study/minimum_overturning.hpp
// says how; docs/spectra.md documents the keys).
//   "minimum_overturning": {"tolerance": 1e-3, "resolution": 1e-3, "near_overturning": 0.5,
//                           "max_midpoints": 1000}
#pragma once

#include <cstdint>

#include <nlohmann/json.hpp>

#include "mpi_driver/config/config_reader.hpp"

namespace blockfrag {

struct MinimumOverturningSettings {
  // Relative, in amplitude ratio: the minimum's final bracket is at most this wide times its upper
  // end.
  double tolerance = 1e-3;
  // Relative: an interval probed below the minimum is halved while it is wider than this times its
  // upper end (a band narrower than that can be missed).
  double resolution = 1e-3;
  // An interval between two standing amplitudes is probed while max |theta| / alpha at one of its
  // ends reaches this: the response is near overturning there, and a band may lie between.
  double near_overturning = 0.5;
  // Midpoints per frequency at most (the bisection of the minimum and the probes together).
  std::int64_t max_midpoints = 1000;
};

// Reads the key (inert reader: the defaults). Errors go to the reader's ConfigErrors.
MinimumOverturningSettings read_minimum_overturning(ObjectReader reader);

// {"max_midpoints": ..., "near_overturning": ..., "resolution": ..., "tolerance": ...}, every value
// written out.
nlohmann::json minimum_overturning_to_json(const MinimumOverturningSettings& settings);

}  // namespace blockfrag
