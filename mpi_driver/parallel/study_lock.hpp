// One run per output at a time: two runs of the same study (a resubmitted batch job while the old
// one still runs) would overwrite each other's checkpoints. Rank 0 holds an advisory lock
// (flock) on OUTPUT.lock for the whole run; the kernel releases it when the process ends in any
// way, kill -9 included, so a stale lock never blocks a resume.
#pragma once

#include <filesystem>

namespace blockfrag {

class StudyLock {
 public:
  // Tries to take the lock without waiting; held() says whether it succeeded.
  explicit StudyLock(const std::filesystem::path& output);
  ~StudyLock();
  StudyLock(const StudyLock&) = delete;
  StudyLock& operator=(const StudyLock&) = delete;

  bool held() const { return fd_ >= 0; }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
  int fd_ = -1;
};

}  // namespace blockfrag
