// read_in_child: the child's text comes back; its refusal comes back as InvalidInput and any other
// exception as Error; a child that crashes (a signal, or AddressSanitizer's exit code 1 in a
// sanitized build) or does not finish in time is a damaged file, named; and nothing the child does
// reaches the parent's memory.
#include "mpi_driver/io/read_in_child.hpp"

#include <chrono>
#include <csignal>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "engine/errors.hpp"

namespace blockfrag {
namespace {

using namespace std::chrono_literals;

constexpr std::size_t memory = std::size_t{1} << 30;

// Expects `call` to throw InvalidInput whose message holds the fragment.
template <typename Call>
void expect_refused(Call call, const std::string& fragment) {
  try {
    call();
    ADD_FAILURE() << "no InvalidInput";
  } catch (const InvalidInput& error) {
    EXPECT_NE(std::string(error.what()).find(fragment), std::string::npos) << error.what();
  }
}

TEST(ReadInChild, GivesBackTheChildsTextAndNothingElse) {
  int touched = 0;
  const std::string text = read_in_child("f.h5", 5000ms, memory, [&] {
    touched = 1;
    std::string answer(100003, 'x');
    answer.replace(100000, 3, "end");
    return answer;
  });
  EXPECT_EQ(text.size(), 100003u);
  EXPECT_EQ(text.substr(100000), "end");
  EXPECT_EQ(touched, 0);  // the child's memory is its own
}

TEST(ReadInChild, RefusalsAndFailuresComeBack) {
  expect_refused(
      [] {
        read_in_child("f.h5", 5000ms, memory,
                      []() -> std::string { throw InvalidInput("f.h5: bad"); });
      },
      "f.h5: bad");
  try {
    read_in_child("f.h5", 5000ms, memory,
                  []() -> std::string { throw std::runtime_error("no memory"); });
    ADD_FAILURE() << "no Error";
  } catch (const InvalidInput&) {
    ADD_FAILURE() << "a failure became a refusal";
  } catch (const Error& error) {
    EXPECT_STREQ(error.what(), "no memory");
  }
}

TEST(ReadInChild, ACrashOrAHangIsADamagedFile) {
  expect_refused(
      [] {
        read_in_child("crash.h5", 5000ms, memory, []() -> std::string {
          std::raise(SIGSEGV);
          return "";
        });
      },
      "crash.h5: reading it crashed HDF5 (");
  const auto start = std::chrono::steady_clock::now();
  expect_refused(
      [] {
        read_in_child("loop.h5", 300ms, memory, []() -> std::string {
          std::this_thread::sleep_for(30s);
          return "";
        });
      },
      "loop.h5: still not read after 0.3 s: a damaged file");
  EXPECT_LT(std::chrono::steady_clock::now() - start, 5s);
}

TEST(ReadInChild, MoreMemoryThanItsLimitIsADamagedFile) {
  if (!child_memory_limited) GTEST_SKIP() << "a sanitized build does not limit the child's memory";
  expect_refused(
      [] {
        read_in_child("big.h5", 5000ms, std::size_t{1} << 30, [] {
          std::vector<char> huge(std::size_t{2} << 30, 'x');
          return std::string(1, huge.back());
        });
      },
      "big.h5: reading it takes more than 1073741824 bytes of memory: a damaged file");
}

}  // namespace
}  // namespace blockfrag
