#include "mpi_driver/io/read_deadline.hpp"

#include <cstdio>
#include <cstdlib>
#include <utility>

#include "mpi_driver/config/input_file.hpp"

namespace blockfrag {

ReadDeadline::ReadDeadline(std::string file, std::chrono::milliseconds limit, int exit_code)
    : watcher_([this, file = std::move(file), limit, exit_code] {
        std::unique_lock lock(mutex_);
        if (finished_.wait_for(lock, limit, [this] { return done_; })) return;
        // The reading thread is stuck inside the library: no exception can reach main().
        std::fprintf(stderr,
                     "blockfrag: %s: still not read after %g s: a damaged file (HDF5 does not "
                     "finish reading it)\n",
                     printable_excerpt(file, 200).c_str(),
                     std::chrono::duration<double>(limit).count());
        std::fflush(stderr);
        std::_Exit(exit_code);
      }) {}

ReadDeadline::~ReadDeadline() {
  {
    const std::lock_guard lock(mutex_);
    done_ = true;
  }
  finished_.notify_one();
  watcher_.join();
}

}  // namespace blockfrag
