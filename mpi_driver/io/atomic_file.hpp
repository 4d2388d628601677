// Replacing a file so that a reader, or a restart after kill -9 at any instant, finds either the
// old content or the new one, never a mix: write PATH.tmp, fsync it, rename it over PATH, fsync
// the folder (the rename itself is only durable once the directory entry is on disk).
#pragma once

#include <filesystem>
#include <functional>
#include <string_view>

#include "engine/errors.hpp"

namespace blockfrag {

class FileError : public FileFailure {
 public:
  using FileFailure::FileFailure;
};

// PATH.tmp: the one temporary name per target, so a leftover from a killed writer is simply
// overwritten by the next attempt.
std::filesystem::path temporary_path_for(const std::filesystem::path& path);

struct AtomicWriteHooks {
  // Test hook: seconds to sleep after the temporary file is complete and before the rename, so a
  // test can land a kill inside the write.
  double pause_before_rename_s = 0.0;
};

// write_temporary writes the complete content into the path it is given (with any library:
// stdio, HDF5, ...) and closes it; then the file is fsynced and renamed over path.
void replace_file_atomically(const std::filesystem::path& path,
                             const std::function<void(const std::filesystem::path&)>& write_temporary,
                             const AtomicWriteHooks& hooks = {});

void write_file_atomically(const std::filesystem::path& path, std::string_view bytes,
                           const AtomicWriteHooks& hooks = {});

// Throws FileError when the file cannot be read.
std::string read_whole_file(const std::filesystem::path& path);

}  // namespace blockfrag
