// A spectrum's minimum refinement on disk between rounds (OUTPUT.minimum): every frequency's
// segments and midpoints spent as they stand at the start of a round, tied to the spectrum by its
// config hash. Written whole and atomically (atomic_file.hpp) before the round's midpoints are
// evaluated, as the bisection state is (bisection_state.hpp), so a run killed at any instant
// resumes at the start of that round, or of the previous one; a trailing checksum catches any other
// damage.
//
// Layout (native byte order): "BFMINI01" | u64 config hash | i64 round | i64 frequencies |
// i64 segment count | i64 midpoints per frequency | the segments as raw bytes
// (mpi_driver/study/minimum_overturning.hpp) | u64 FNV-1a of everything before it.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "mpi_driver/study/minimum_overturning.hpp"

namespace blockfrag {

std::string encode_minimum_refinement(const MinimumRefinement& refinement);
// Throws CheckpointError (naming source) for a truncated, damaged or foreign file, one of another
// number of frequencies than `frequencies`, more than max_segments segments, or a segment that the
// refinement could not have written.
MinimumRefinement decode_minimum_refinement(std::string_view bytes, const std::string& source,
                                            std::int64_t max_segments, std::int64_t frequencies);

void write_minimum_refinement(const std::filesystem::path& path,
                              const MinimumRefinement& refinement);
// nullopt when there is no file at path. The program's own file: a link or anything but a regular
// file there is refused (CheckpointError), as is one larger than max_segments segments.
std::optional<MinimumRefinement> read_minimum_refinement(const std::filesystem::path& path,
                                                         std::int64_t max_segments,
                                                         std::int64_t frequencies);

// OUTPUT.minimum, next to the output.
std::filesystem::path minimum_refinement_path_for(const std::filesystem::path& output);

}  // namespace blockfrag
