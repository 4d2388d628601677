// The lock when runs of one output come and go at once: a run that ends removes its lock file, and
// one that opened the name just before must not then hold a lock on the removed file while a third
// run holds the new one.
#include <atomic>
#include <chrono>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "mpi_driver/parallel/study_lock.hpp"
#include "tests/support/temporary_folder.hpp"

namespace blockfrag {
namespace {

TEST(StudyLockRace, NeverTwoHoldersWhileRunsStartAndEnd) {
  testing::TemporaryFolder folder;
  const auto output = folder.path() / "study.h5";
  std::atomic<int> holding{0}, most_at_once{0}, taken{0};
  const auto run_many = [&] {
    for (int attempt = 0; attempt < 1000; ++attempt) {
      StudyLock lock(output);
      if (!lock.held()) continue;
      const int now = ++holding;
      int most = most_at_once.load();
      while (now > most && !most_at_once.compare_exchange_weak(most, now)) {
      }
      ++taken;
      std::this_thread::sleep_for(std::chrono::microseconds(20));
      --holding;
    }
  };
  std::vector<std::thread> runs;
  for (int k = 0; k < 4; ++k) runs.emplace_back(run_many);
  for (auto& run : runs) run.join();
  EXPECT_EQ(most_at_once.load(), 1);
  EXPECT_GT(taken.load(), 100);
}

}  // namespace
}  // namespace blockfrag
