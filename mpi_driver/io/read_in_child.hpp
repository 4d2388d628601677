// Reading an untrusted file through a library that is not safe on it, in a child process: HDF5
// 1.10 reads freed memory iterating a damaged object header's attributes, reads outside its
// buffers converting a malformed type and loops forever on a damaged global heap (all found by
// tests/fuzz/hdf5_reader_fuzzer.cpp; tests/data/fuzz_findings/). A child that dies by a signal or
// has not finished within the limit (it is killed) leaves the parent's memory as it was, and is
// reported as the damaged file it read.
#pragma once

#include <chrono>
#include <functional>
#include <string>

namespace blockfrag {

// Runs `read` in a forked child and returns the text it returned. An InvalidInput the child
// throws is thrown again here with its message, another exception as Error; a child killed by a
// signal, or still reading after `limit`, is an InvalidInput naming `file`. Call it before any
// thread or MPI is started (fork copies only the calling thread).
std::string read_in_child(const std::string& file, std::chrono::milliseconds limit,
                          const std::function<std::string()>& read);

}  // namespace blockfrag
