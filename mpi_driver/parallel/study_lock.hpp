// One run per output at a time: two runs of the same study (a resubmitted batch job while the old
// one still runs) would overwrite each other's checkpoints. Rank 0 holds an advisory lock (flock)
// on OUTPUT.lock for the whole run; the kernel releases it when the process ends in any way,
// kill -9 included, so a stale lock never blocks a resume. A run that ends removes the lock file
// while it still holds it; one that opened the name just before then holds a lock on a file no
// longer there, which it notices (the name now leads to another file or none) and opens the name
// again: two runs never both hold the lock.
//
// The lock file is named after the output's canonical folder (symbolic links and ".." resolved),
// so two spellings of one output take one lock; it is opened without following a link, so a link
// planted at its name cannot make the lock create or touch another file.
#pragma once

#include <filesystem>
#include <string>

namespace blockfrag {

class StudyLock {
 public:
  // Tries to take the lock without waiting.
  explicit StudyLock(const std::filesystem::path& output);
  ~StudyLock();
  StudyLock(const StudyLock&) = delete;
  StudyLock& operator=(const StudyLock&) = delete;

  bool held() const { return fd_ >= 0; }
  // Not held because another process holds it (as opposed to a lock file that cannot be used).
  bool busy() const { return busy_; }
  // Why the lock could not be taken when it is neither held nor busy.
  const std::string& problem() const { return problem_; }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
  int fd_ = -1;
  bool busy_ = false;
  std::string problem_;
};

}  // namespace blockfrag
