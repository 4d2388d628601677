#include "mpi_driver/parallel/study_lock.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include <sys/file.h>

namespace blockfrag {
namespace {

std::filesystem::path canonical_lock_path(const std::filesystem::path& output) {
  const auto parent = output.parent_path();
  std::error_code error;
  const auto folder = std::filesystem::canonical(parent.empty() ? "." : parent, error);
  return (error ? parent : folder) / (output.filename().string() + ".lock");
}

}  // namespace

StudyLock::StudyLock(const std::filesystem::path& output) : path_(canonical_lock_path(output)) {
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
  fd_ = fd;
}

StudyLock::~StudyLock() {
  if (fd_ < 0) return;
  // Unlinked while still held: a run that opens the name afterwards gets a fresh file and its own
  // lock, which is right since this run is over.
  ::unlink(path_.c_str());
  ::close(fd_);
}

}  // namespace blockfrag
