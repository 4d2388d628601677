// The lock when runs of one output come and go at once: a run that ends removes its lock file, and
// one that opened the name just before must not then hold a lock on the removed file while a third
// run holds the new one. Each run keeps trying until the runs together have held the lock often
// enough to have raced: how many tries that takes depends on the scheduler, not on the lock.
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
  constexpr int enough_holds = 400;
  std::atomic<int> holding{0}, most_at_once{0}, taken{0};
  const auto run_many = [&] {
    for (int attempt = 0; attempt < 200000 && taken.load() < enough_holds; ++attempt) {
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
  EXPECT_GE(taken.load(), enough_holds);
}

}  // namespace
}  // namespace blockfrag
