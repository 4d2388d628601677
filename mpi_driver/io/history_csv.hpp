// A simulation's time history as CSV, one HistoryRow per line under the header
//   t,x,y,theta,vx,vy,omega,mode,friction_per_weight,normal_per_weight
// with each double written as the shortest text that reads back to the same bits.
#pragma once

#include <filesystem>
#include <ostream>
#include <string_view>
#include <vector>

#include "engine/summary.hpp"

namespace blockfrag {

inline constexpr std::string_view kHistoryCsvHeader =
    "t,x,y,theta,vx,vy,omega,mode,friction_per_weight,normal_per_weight\n";

void write_history_csv(std::ostream& out, const std::vector<HistoryRow>& rows);

// Whether the regular file at path is a history CSV (it starts with the header): the one kind of
// file `simulate --history` replaces (mpi_driver/io/output_target.hpp).
bool is_history_csv(const std::filesystem::path& path);

// Replaces the file atomically (mpi_driver/io/atomic_file.hpp): never left half written.
// Throws FileError when it cannot be written.
void write_history_csv_file(const std::filesystem::path& path, const std::vector<HistoryRow>& rows);

}  // namespace blockfrag
