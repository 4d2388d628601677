// A study's progress on disk: which samples are done, as ranges of indices, tied to the config by
// its hash. Their records are in the record spool (mpi_driver/io/record_spool.hpp), fsynced before
// the checkpoint is written. Written whole and atomically (see atomic_file.hpp), so a kill at any
// instant leaves either the previous checkpoint or the new one; a trailing checksum catches any
// other damage. Its size is in the number of ranges, not of samples.
//
// Layout (native byte order: a checkpoint is resumed on the machine type that wrote it):
//   "BFCKPT02" | u64 config hash | i64 total samples | i64 range count | (i64 first, i64 count)
//   per range | u64 FNV-1a of everything before it.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "engine/errors.hpp"
#include "mpi_driver/io/atomic_file.hpp"
#include "mpi_driver/parallel/index_ranges.hpp"

namespace blockfrag {

class CheckpointError : public InvalidInput {
 public:
  using InvalidInput::InvalidInput;
};

struct CheckpointState {
  std::uint64_t config_hash = 0;
  std::int64_t total_samples = 0;
  std::vector<IndexRange> done;  // sorted, disjoint, not empty, inside [0, total_samples)
};

// The most ranges a checkpoint may hold: far more than a run leaves (about two per rank and
// restart), few enough that a damaged or hostile file cannot exhaust memory.
constexpr std::int64_t kMaxCheckpointRanges = std::int64_t{1} << 20;

std::string encode_checkpoint(const CheckpointState& state);
// Throws CheckpointError (naming source) for a truncated, damaged or foreign file, and for one
// written by a blockfrag that kept the records in the checkpoint (format BFCKPT01).
CheckpointState decode_checkpoint(std::string_view bytes, const std::string& source);

void write_checkpoint(const std::filesystem::path& path, const CheckpointState& state,
                      const AtomicWriteHooks& hooks = {});
// nullopt when there is no checkpoint at path (a fresh start). The checkpoint is the program's own
// file: a link, a FIFO or anything but a regular file there is refused (CheckpointError), as is a
// file larger than kMaxCheckpointRanges ranges.
std::optional<CheckpointState> read_checkpoint(const std::filesystem::path& path);

// The checkpoint that belongs to an output file: OUTPUT.checkpoint, next to it.
std::filesystem::path checkpoint_path_for(const std::filesystem::path& output);

}  // namespace blockfrag
