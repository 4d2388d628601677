#include "mpi_driver/parallel/study_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

namespace blockfrag {

StudyLock::StudyLock(const std::filesystem::path& output) : path_(output) {
  path_ += ".lock";
  const int fd = ::open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0) return;
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
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
