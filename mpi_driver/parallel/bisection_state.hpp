// A spectrum's bisection on disk between rounds (OUTPUT.bisection): every bracket as it stands at
// the start of a round, tied to the spectrum by its config hash. Written whole and atomically
// (atomic_file.hpp) before the round's midpoints are evaluated, so a run killed at any instant
// resumes at the start of that round, or of the previous one; a trailing checksum catches any other
// damage.
//
// Layout (native byte order, like the checkpoint): "BFBISE01" | u64 config hash | i64 round |
// i64 bracket count | the brackets as raw bytes (mpi_driver/study/spectrum_bisection.hpp) |
// u64 FNV-1a of everything before it.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "mpi_driver/study/spectrum_bisection.hpp"

namespace blockfrag {

struct BisectionState {
  std::uint64_t config_hash = 0;
  std::int64_t round = 0;  // the round about to run
  std::vector<SpectrumBracket> brackets;
};

std::string encode_bisection_state(const BisectionState& state);
// Throws CheckpointError (naming source) for a truncated, damaged or foreign file, more than
// max_brackets brackets, or a bracket that is not one of `frequencies` frequencies.
BisectionState decode_bisection_state(std::string_view bytes, const std::string& source,
                                      std::int64_t max_brackets, std::int64_t frequencies);

void write_bisection_state(const std::filesystem::path& path, const BisectionState& state);
// nullopt when there is no file at path. The program's own file: a link or anything but a regular
// file there is refused (CheckpointError), as is one larger than max_brackets brackets.
std::optional<BisectionState> read_bisection_state(const std::filesystem::path& path,
                                                   std::int64_t max_brackets,
                                                   std::int64_t frequencies);

// OUTPUT.bisection, next to the output.
std::filesystem::path bisection_state_path_for(const std::filesystem::path& output);

}  // namespace blockfrag
