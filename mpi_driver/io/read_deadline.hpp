// A time limit on reading an input file through a library that may never return: HDF5 1.10 loops
// forever on some damaged files (a global heap collection whose object 0 has size 0, found by
// tests/fuzz/hdf5_reader_fuzzer.cpp; tests/data/fuzz_findings/hdf5_global_heap_loop.h5), and a
// call that does not return cannot throw. If the guarded read has not finished in time, the guard
// says so on stderr, naming the file, and ends the process with the caller's exit code (the bad
// input's); a command guards only reads that come before it writes anything, so nothing is lost.
#pragma once

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>

namespace blockfrag {

class ReadDeadline {
 public:
  ReadDeadline(std::string file, std::chrono::milliseconds limit, int exit_code);
  // The read is over (done or thrown): the guard stops.
  ~ReadDeadline();
  ReadDeadline(const ReadDeadline&) = delete;
  ReadDeadline& operator=(const ReadDeadline&) = delete;

 private:
  std::mutex mutex_;
  std::condition_variable finished_;
  bool done_ = false;
  std::thread watcher_;
};

}  // namespace blockfrag
