#include "mpi_driver/io/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <thread>

#include <sys/stat.h>

namespace blockfrag {
namespace {

std::string system_error_text(const std::string& what, const std::filesystem::path& path) {
  return what + " " + path.string() + ": " + std::strerror(errno);
}

void fsync_path(const std::filesystem::path& path, int flags) {
  const int fd = ::open(path.c_str(), flags | O_CLOEXEC);
  if (fd < 0) throw FileError(system_error_text("cannot open", path));
  const int status = ::fsync(fd);
  ::close(fd);
  if (status != 0) throw FileError(system_error_text("cannot fsync", path));
}

std::filesystem::path folder_of(const std::filesystem::path& path) {
  const auto parent = path.parent_path();
  return parent.empty() ? std::filesystem::path(".") : parent;
}

std::string temporary_prefix(const std::filesystem::path& target) {
  return target.filename().string() + ".tmp.";
}

// A name nobody else has or can guess: mkstemp makes the file (exclusively) and it is removed at
// once, so that the writer can create it exclusively in turn (HDF5 cannot take a descriptor).
std::filesystem::path fresh_temporary_name(const std::filesystem::path& target) {
  std::string name = (folder_of(target) / (temporary_prefix(target) + "XXXXXX")).string();
  const int fd = ::mkstemp(name.data());
  if (fd < 0) throw FileError(system_error_text("cannot create a temporary file next to", target));
  ::close(fd);
  ::unlink(name.c_str());
  return name;
}

// The commands check their targets before any work (output_target.hpp, claim_output); this is
// the last look, just before the rename, for something put at the name since: a rename would
// replace a link, a FIFO or a device node (/dev/null, as root) as readily as a file.
void refuse_to_rename_over_special_file(const std::filesystem::path& path) {
  struct stat status {};
  if (::lstat(path.c_str(), &status) == 0 && !S_ISREG(status.st_mode)) {
    throw FileError("refusing to replace " + path.string() +
                    ": it is not a regular file (something was put there during the run)");
  }
}

}  // namespace

int create_exclusively(const std::filesystem::path& path) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
  if (fd < 0) throw FileError(system_error_text("cannot create", path));
  return fd;
}

void replace_file_atomically(
    const std::filesystem::path& path,
    const std::function<void(const std::filesystem::path&)>& write_temporary,
    const AtomicWriteHooks& hooks) {
  const auto temporary = fresh_temporary_name(path);
  try {
    try {
      write_temporary(temporary);
      fsync_path(temporary, O_RDONLY | O_NOFOLLOW);
    } catch (const FileFailure& failure) {
      throw FileError("cannot write " + path.string() + ": " + failure.what());
    }
    if (hooks.pause_before_rename_s > 0.0) {
      std::this_thread::sleep_for(std::chrono::duration<double>(hooks.pause_before_rename_s));
    }
    refuse_to_rename_over_special_file(path);
    if (std::rename(temporary.c_str(), path.c_str()) != 0) {
      throw FileError(system_error_text("cannot rename " + temporary.string() + " to", path));
    }
  } catch (...) {
    ::unlink(temporary.c_str());
    throw;
  }
  fsync_path(folder_of(path), O_RDONLY | O_DIRECTORY);
}

void write_file_atomically(const std::filesystem::path& path, std::string_view bytes,
                           const AtomicWriteHooks& hooks) {
  replace_file_atomically(
      path,
      [&](const std::filesystem::path& temporary) {
        const int fd = create_exclusively(temporary);
        std::size_t done = 0;
        while (done < bytes.size()) {
          const ssize_t wrote = ::write(fd, bytes.data() + done, bytes.size() - done);
          if (wrote < 0 && errno == EINTR) continue;
          if (wrote < 0) {
            const std::string why = temporary.string() + ": " + std::strerror(errno);
            ::close(fd);
            throw FileError(why);
          }
          done += static_cast<std::size_t>(wrote);
        }
        if (::close(fd) != 0) throw FileError(temporary.string() + ": " + std::strerror(errno));
      },
      hooks);
}

std::optional<std::string> folder_write_problem(const std::filesystem::path& target) {
  const auto folder = folder_of(target);
  std::error_code error;
  if (!std::filesystem::is_directory(folder, error)) {
    return "the folder " + folder.string() + " does not exist";
  }
  std::string probe = (folder / (temporary_prefix(target) + "XXXXXX")).string();
  const int fd = ::mkstemp(probe.data());
  if (fd < 0)
    return "cannot create a file in the folder " + folder.string() + " (" + std::strerror(errno) +
           ")";
  ::close(fd);
  ::unlink(probe.c_str());
  return std::nullopt;
}

int remove_stale_temporaries(const std::filesystem::path& target) {
  const std::string prefix = temporary_prefix(target);
  int removed = 0;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(folder_of(target), error)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind(prefix, 0) != 0 || name.size() != prefix.size() + 6) continue;
    struct stat status {};
    if (::lstat(entry.path().c_str(), &status) == 0 && S_ISREG(status.st_mode) &&
        ::unlink(entry.path().c_str()) == 0) {
      ++removed;
    }
  }
  return removed;
}

}  // namespace blockfrag
