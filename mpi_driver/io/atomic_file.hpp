// Replacing a file so that a reader, or a restart after kill -9 at any instant, finds either the
// old content or the new one, never a mix: write a temporary file next to it, fsync it, rename it
// over the target, fsync the folder (the rename itself is only durable once the directory entry is
// on disk).
//
// The temporary file gets a fresh unguessable name (TARGET.tmp.XXXXXX) and is created exclusively
// (O_CREAT | O_EXCL, which never follows a symbolic link): nothing planted in a shared folder can
// make a write land in another file. A writer that fails removes its temporary file; one killed
// leaves it, and remove_stale_temporaries() clears such leftovers (the caller holds the study's
// lock, so no other writer of the target is running).
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

#include "engine/errors.hpp"

namespace blockfrag {

class FileError : public FileFailure {
 public:
  using FileFailure::FileFailure;
};

struct AtomicWriteHooks {
  // Test hook: seconds to sleep after the temporary file is complete and before the rename, so a
  // test can land a kill inside the write.
  double pause_before_rename_s = 0.0;
};

// write_temporary must create the file at the path it is given exclusively (the path does not
// exist: create_exclusively() below, or HDF5's H5F_ACC_EXCL), write the complete content and close
// it; then the file is fsynced and renamed over path.
void replace_file_atomically(
    const std::filesystem::path& path,
    const std::function<void(const std::filesystem::path&)>& write_temporary,
    const AtomicWriteHooks& hooks = {});

void write_file_atomically(const std::filesystem::path& path, std::string_view bytes,
                           const AtomicWriteHooks& hooks = {});

// Opens a new file for writing with O_CREAT | O_EXCL | O_NOFOLLOW (mode 0644 before the umask):
// fails if anything, a link included, is already there. Returns the descriptor.
int create_exclusively(const std::filesystem::path& path);

// Why `target` could not be written, found before any work: its folder is missing, or a file
// cannot be created in it (read-only, /proc, no permission). nullopt when it can.
std::optional<std::string> folder_write_problem(const std::filesystem::path& target);

// Removes the temporary files a killed writer of `target` left (TARGET.tmp.*, regular files only;
// a link or anything else there is left alone). Returns how many it removed.
int remove_stale_temporaries(const std::filesystem::path& target);

}  // namespace blockfrag
