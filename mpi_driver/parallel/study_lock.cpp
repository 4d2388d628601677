#include "mpi_driver/parallel/study_lock.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include <sys/file.h>
#include <sys/stat.h>

namespace blockfrag {
namespace {

std::filesystem::path canonical_lock_path(const std::filesystem::path& output) {
  const auto parent = output.parent_path();
  std::error_code error;
  const auto folder = std::filesystem::canonical(parent.empty() ? "." : parent, error);
  return (error ? parent : folder) / (output.filename().string() + ".lock");
}

// Whether the descriptor's file is still the one at path: a run that ends unlinks its lock file
// while it holds it, so a run that opened the name just before finds, once it holds the lock, that
// it locked a file nobody else will open again.
bool lock_file_still_named(int fd, const std::filesystem::path& path) {
  struct stat opened {
  }, named{};
  return ::fstat(fd, &opened) == 0 && ::lstat(path.c_str(), &named) == 0 &&
         opened.st_dev == named.st_dev && opened.st_ino == named.st_ino;
}

}  // namespace

StudyLock::StudyLock(const std::filesystem::path& output) : path_(canonical_lock_path(output)) {
  for (;;) {
    const int fd = ::open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
    if (fd < 0) {
      problem_ = errno == ELOOP
                     ? "is a symbolic link (refused: the lock must be the program's own file)"
                     : std::string("cannot be opened: ") + std::strerror(errno);
      return;
    }
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
      busy_ = errno == EWOULDBLOCK;
      if (!busy_) problem_ = std::string("cannot be locked: ") + std::strerror(errno);
      ::close(fd);
      return;
    }
    if (lock_file_still_named(fd, path_)) {
      fd_ = fd;
      return;
    }
    ::close(fd);  // the file of a run that has just ended: open the name again
  }
}

StudyLock::~StudyLock() {
  if (fd_ < 0) return;
  // Unlinked while still held, so that no other run holds this file by then; a run that opened
  // it before the unlink sees that it is gone (lock_file_still_named) and tries again.
  ::unlink(path_.c_str());
  ::close(fd_);
}

}  // namespace blockfrag
