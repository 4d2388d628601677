// Reading an untrusted file through a library that is not safe on it, in a child process: HDF5
// 1.10 reads freed memory iterating a damaged object header's attributes, reads outside its
// buffers converting a malformed type and loops forever on a damaged global heap (all found by
// tests/fuzz/hdf5_reader_fuzzer.cpp; tests/data/fuzz_findings/). A child that dies by a signal or
// has not finished within the limit (it is killed) leaves the parent's memory as it was, and is
// reported as the damaged file it read.
#pragma once

#include <chrono>
#include <cstddef>
#include <functional>
#include <string>

namespace blockfrag {

// Whether the child's address space is limited: AddressSanitizer reserves terabytes of it for its
// shadow memory, so a sanitized build runs the child without the limit.
#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool child_memory_limited = false;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr bool child_memory_limited = false;
#else
inline constexpr bool child_memory_limited = true;
#endif
#else
inline constexpr bool child_memory_limited = true;
#endif

// Runs `read` in a forked child, its address space limited to `memory_bytes` (a damaged file can
// make HDF5 allocate what the file declares: 6 GB for a 17 kB file), and returns the text it
// returned. An InvalidInput the child throws is thrown again here with its message, another
// exception as Error; a child killed by a signal, out of memory, or still reading after `limit`
// is an InvalidInput naming `file`. Call it before any thread or MPI is started (fork copies only
// the calling thread).
std::string read_in_child(const std::string& file, std::chrono::milliseconds limit,
                          std::size_t memory_bytes, const std::function<std::string()>& read);

}  // namespace blockfrag
