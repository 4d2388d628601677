// The records of a running study on disk, OUTPUT.records next to the output: sample i's record at
// a fixed place (a header, then i * sizeof(SampleRecord)), written as chunks complete. Rank 0 then
// holds no record in memory, whatever the study's size; the checkpoint only lists which samples
// are done, and the spool is fsynced before each checkpoint, so every sample a checkpoint calls
// done has its record on disk. Records written after the last checkpoint are computed and written
// again on resume.
//
// Layout (native byte order, like the checkpoint): "BFRECS01" | u64 config hash | i64 total
// samples | i64 record size | records. A sparse file: unwritten records take no disk.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>

#include "engine/errors.hpp"
#include "mpi_driver/study/study_record.hpp"

namespace blockfrag {

// The file at the spool's place is not a spool of this study (or not a regular file).
class RecordSpoolError : public InvalidInput {
 public:
  using InvalidInput::InvalidInput;
};

class RecordSpool {
 public:
  enum class Mode {
    fresh,   // a new study: create the file, or reuse a spool a killed run of any study left
    resume,  // the checkpoint's study: the file must exist with this hash and total
  };
  // Never follows a link; refuses anything but a regular file, and a file without a spool's
  // header (someone else's file is never overwritten).
  RecordSpool(const std::filesystem::path& path, std::uint64_t config_hash,
              std::int64_t total_samples, Mode mode);
  ~RecordSpool();
  RecordSpool(const RecordSpool&) = delete;
  RecordSpool& operator=(const RecordSpool&) = delete;

  // Consecutive records, the first at its own index.
  void write(std::span<const SampleRecord> records);
  // The records of samples [first, first + out.size()); an unwritten one reads as zeros.
  void read(std::int64_t first, std::span<SampleRecord> out) const;
  // Makes every write so far durable (before a checkpoint names those samples done).
  void sync();
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
  std::int64_t total_ = 0;
  int fd_ = -1;
};

// The config hash in the header of the records file at path, without changing it; nullopt when
// nothing is there, or an empty file (a run killed as it created it, which RecordSpool reuses).
// Throws RecordSpoolError for what RecordSpool refuses: a link, anything but a regular file, a file
// without a records file's header.
std::optional<std::uint64_t> read_record_spool_hash(const std::filesystem::path& path);

// OUTPUT.records, next to the output.
std::filesystem::path record_spool_path_for(const std::filesystem::path& output);

}  // namespace blockfrag
