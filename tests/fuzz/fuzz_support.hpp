// What the fuzz targets (tests/fuzz/*_fuzzer.cpp) share: a private temporary folder, the outcome
// rules (InvalidInput is an expected answer; any other exception is a finding) and the guard that
// keeps a fuzzed config from naming files outside that folder.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <typeinfo>

#include <nlohmann/json.hpp>

#include "engine/errors.hpp"

namespace blockfrag::fuzz {

// A small valid record of each format, so that scenes naming them reach the record paths.
inline constexpr std::string_view kAt2Record =
    "PEER NGA STRONG MOTION DATABASE RECORD\n"
    "blockfrag fuzz record\n"
    "ACCELERATION TIME SERIES IN UNITS OF G\n"
    "NPTS=   8, DT=   .0500 SEC\n"
    "  0.0000000E+00  1.0000000E-01  2.0000000E-01  1.0000000E-01\n"
    "  0.0000000E+00 -1.0000000E-01 -2.0000000E-01 -1.0000000E-01\n";
inline constexpr std::string_view kTwoColumnRecord =
    "# time_s acceleration_g\n"
    "0.00 0.0\n0.05, 0.2\n0.10\t-0.2\n0.15 0.0\n";

// A folder of this process's own, made once (under $TMPDIR, else /tmp) and holding the two records
// above as decaying_sine.AT2 and cosine_pulse.txt (the names tests/data's scenes use); removed at
// a normal exit.
inline const std::filesystem::path& folder() {
  static const std::filesystem::path path = [] {
    const char* tmp = std::getenv("TMPDIR");
    std::string name = std::string(tmp && *tmp ? tmp : "/tmp") + "/blockfrag-fuzz-XXXXXX";
    if (!mkdtemp(name.data())) {
      std::perror("blockfrag fuzz: mkdtemp");
      std::abort();
    }
    const std::filesystem::path made(name);
    std::ofstream(made / "decaying_sine.AT2", std::ios::binary) << kAt2Record;
    std::ofstream(made / "cosine_pulse.txt", std::ios::binary) << kTwoColumnRecord;
    std::atexit([] {
      std::error_code ignored;
      std::filesystem::remove_all(path, ignored);
    });
    return made;
  }();
  return path;
}

// Whether every "file" string in the document names a file inside folder(): relative, without
// "..". A config may name any file; the fuzzer must not make the readers open arbitrary ones.
inline bool files_stay_inside(const nlohmann::json& value) {
  if (value.is_object()) {
    for (const auto& [key, member] : value.items()) {
      if (key == "file" && member.is_string()) {
        const std::filesystem::path file(member.get<std::string>());
        if (file.has_root_path()) return false;
        for (const auto& part : file) {
          if (part == "..") return false;
        }
      }
      if (!files_stay_inside(member)) return false;
    }
  } else if (value.is_array()) {
    for (const auto& element : value) {
      if (!files_stay_inside(element)) return false;
    }
  }
  return true;
}

// Stops the run on a finding, saying what escaped: libFuzzer saves the input as crash-*.
[[noreturn]] inline void finding(std::string_view what, const std::exception* error = nullptr) {
  std::fprintf(stderr, "\n==blockfrag fuzz== FINDING: %.*s", static_cast<int>(what.size()),
               what.data());
  if (error) std::fprintf(stderr, ": %s: %s", typeid(*error).name(), error->what());
  std::fprintf(stderr, "\n");
  std::abort();
}

// Runs one input: an InvalidInput is an expected answer, any other exception a finding. With
// BLOCKFRAG_FUZZ_VERBOSE set, prints the InvalidInput's message (why an input is refused).
template <class Body>
int run(Body&& body) {
  static const bool verbose = std::getenv("BLOCKFRAG_FUZZ_VERBOSE") != nullptr;
  try {
    return body();
  } catch (const InvalidInput& error) {
    if (verbose) std::fprintf(stderr, "refused: %s\n", error.what());
    return 0;
  } catch (const std::exception& error) {
    finding("an exception other than InvalidInput escaped", &error);
  } catch (...) {
    finding("a non-std::exception escaped");
  }
}

}  // namespace blockfrag::fuzz
