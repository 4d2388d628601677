// A study's progress on disk: which samples are done and their records, tied to the config by its
// hash. Written whole and atomically (see atomic_file.hpp), so a kill at any instant leaves either
// the previous checkpoint or the new one; a trailing checksum catches any other damage.
//
// Layout (native byte order: a checkpoint is resumed on the machine type that wrote it):
//   "BFCKPT01" | u64 config hash | i64 total samples | i64 record count | records | u64 FNV-1a of
//   everything before it.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "engine/errors.hpp"
#include "mpi_driver/io/atomic_file.hpp"
#include "mpi_driver/study/study_record.hpp"

namespace blockfrag {

class CheckpointError : public InvalidInput {
 public:
  using InvalidInput::InvalidInput;
};

struct CheckpointState {
  std::uint64_t config_hash = 0;
  std::int64_t total_samples = 0;
  std::vector<SampleRecord> done;  // any order; each index at most once
};

std::string encode_checkpoint(const CheckpointState& state);
// Throws CheckpointError (naming source) for a truncated, damaged or foreign file.
CheckpointState decode_checkpoint(std::string_view bytes, const std::string& source);

void write_checkpoint(const std::filesystem::path& path, const CheckpointState& state,
                      const AtomicWriteHooks& hooks = {});
// nullopt when there is no checkpoint at path (a fresh start). The checkpoint is the program's own
// file: a link, a FIFO or anything but a regular file there is refused (CheckpointError), as is a
// file larger than a checkpoint of total_samples records can be.
std::optional<CheckpointState> read_checkpoint(const std::filesystem::path& path,
                                               std::int64_t total_samples);

// The checkpoint that belongs to an output file: OUTPUT.checkpoint, next to it.
std::filesystem::path checkpoint_path_for(const std::filesystem::path& output);

}  // namespace blockfrag
