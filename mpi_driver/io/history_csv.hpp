// A simulation's time history as CSV, one HistoryRow per line under the header
//   t,x,y,theta,vx,vy,omega,mode,friction_per_weight,normal_per_weight
// with each double written as the shortest text that reads back to the same bits.
#pragma once

#include <filesystem>
#include <ostream>
#include <vector>

#include "engine/summary.hpp"

namespace blockfrag {

void write_history_csv(std::ostream& out, const std::vector<HistoryRow>& rows);

// Replaces the file atomically (mpi_driver/io/atomic_file.hpp): never left half written.
// Throws FileError when it cannot be written.
void write_history_csv_file(const std::filesystem::path& path, const std::vector<HistoryRow>& rows);

}  // namespace blockfrag
