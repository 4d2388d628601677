// ReadDeadline: a read that finishes in time goes on as if unguarded; one that does not ends the
// process with the caller's exit code and a message naming the file.
#include "mpi_driver/io/read_deadline.hpp"

#include <chrono>
#include <thread>

#include <gtest/gtest.h>

namespace blockfrag {
namespace {

using namespace std::chrono_literals;

TEST(ReadDeadline, AReadInTimeGoesOn) {
  int value = 0;
  {
    const ReadDeadline deadline("fast.h5", 5000ms, 2);
    value = 42;
  }
  EXPECT_EQ(value, 42);
}

TEST(ReadDeadlineDeathTest, AReadThatNeverEndsExitsWithTheCode) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(
      {
        const ReadDeadline deadline("stuck.h5", 200ms, 2);
        std::this_thread::sleep_for(10s);
      },
      ::testing::ExitedWithCode(2), "stuck.h5: still not read after 0.2 s: a damaged file");
}

}  // namespace
}  // namespace blockfrag
