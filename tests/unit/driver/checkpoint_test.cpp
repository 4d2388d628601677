// Checkpoints: the file round-trips every record bit for bit, damage of any kind is refused, the
// atomic write leaves no partial file behind; one run at a time holds the study lock; the work
// queue hands out every pending index exactly once, also after give-backs. (The run loop itself,
// which needs MPI, is tested in tests/mpi/driver/study_runner_test.cpp.)
#include "mpi_driver/parallel/checkpoint.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include <gtest/gtest.h>
#include <sys/stat.h>

#include "mpi_driver/config/input_file.hpp"
#include "mpi_driver/io/atomic_file.hpp"
#include "mpi_driver/parallel/study_lock.hpp"
#include "mpi_driver/parallel/work_distribution.hpp"

namespace blockfrag {
namespace {

class TemporaryFolder {
 public:
  TemporaryFolder() {
    char pattern[] = "/tmp/blockfrag_checkpoint_test_XXXXXX";
    path_ = ::mkdtemp(pattern);
  }
  ~TemporaryFolder() { std::filesystem::remove_all(path_); }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

SampleRecord some_record(std::int64_t index) {
  SampleRecord record;
  record.index = index;
  record.status = index % 5 == 0 ? 1 : 0;
  record.overturned = index % 3 == 0;
  record.impacts = index * 7;
  record.steps = index * 1000 + 1;
  record.rhs_evaluations = index * 6000 + 2;
  record.max_abs_theta = 0.1 * static_cast<double>(index) + 1e-17;
  record.final_theta = -std::ldexp(1.0, -1070);  // a subnormal: bits must survive
  record.final_slide = -0.3 * static_cast<double>(index);
  record.max_abs_slide = 1.0 / 3.0;
  if (index % 2 == 0) record.overturn_time = 1.25 + static_cast<double>(index);
  return record;
}

bool same_bits(const SampleRecord& a, const SampleRecord& b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

CheckpointState some_state() {
  CheckpointState state;
  state.config_hash = 0x0123456789abcdefULL;
  state.total_samples = 50;
  for (const std::int64_t i : {7, 0, 49, 13, 22}) state.done.push_back(some_record(i));
  return state;
}

TEST(Checkpoint, RoundTripsEveryRecordBitForBit) {
  const CheckpointState state = some_state();
  const CheckpointState back = decode_checkpoint(encode_checkpoint(state), "test");
  EXPECT_EQ(back.config_hash, state.config_hash);
  EXPECT_EQ(back.total_samples, 50);
  ASSERT_EQ(back.done.size(), state.done.size());
  for (std::size_t k = 0; k < state.done.size(); ++k)
    EXPECT_TRUE(same_bits(back.done[k], state.done[k])) << k;
}

TEST(Checkpoint, EmptyStateRoundTrips) {
  CheckpointState state;
  state.total_samples = 10;
  EXPECT_TRUE(decode_checkpoint(encode_checkpoint(state), "test").done.empty());
}

TEST(Checkpoint, EveryDamageIsRefused) {
  const std::string bytes = encode_checkpoint(some_state());
  for (std::size_t position = 0; position < bytes.size(); position += 13) {
    std::string damaged = bytes;
    damaged[position] = static_cast<char>(damaged[position] ^ 0x20);
    EXPECT_THROW(decode_checkpoint(damaged, "test"), CheckpointError) << "byte " << position;
  }
  for (const std::size_t length :
       {std::size_t{0}, std::size_t{5}, bytes.size() / 2, bytes.size() - 1}) {
    EXPECT_THROW(decode_checkpoint(bytes.substr(0, length), "test"), CheckpointError)
        << "length " << length;
  }
}

TEST(Checkpoint, DuplicateOrOutOfRangeIndicesAreRefused) {
  CheckpointState duplicate = some_state();
  duplicate.done.push_back(some_record(13));
  EXPECT_THROW(decode_checkpoint(encode_checkpoint(duplicate), "test"), CheckpointError);
  CheckpointState outside = some_state();
  outside.done.push_back(some_record(50));
  EXPECT_THROW(decode_checkpoint(encode_checkpoint(outside), "test"), CheckpointError);
}

std::size_t files_in(const std::filesystem::path& folder) {
  std::size_t count = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(folder)) ++count;
  return count;
}

TEST(Checkpoint, FileWriteIsAtomicAndLeavesNoTemporary) {
  TemporaryFolder folder;
  const auto path = folder.path() / "study.h5.checkpoint";
  EXPECT_FALSE(read_checkpoint(path, 40).has_value());
  // A leftover temporary from a writer killed before its rename is neither read nor in the way,
  // and the study's start (holding the lock) clears it.
  std::ofstream(folder.path() / "study.h5.checkpoint.tmp.a1B2c3") << "half a checkpoint";
  EXPECT_FALSE(read_checkpoint(path, 40).has_value());
  write_checkpoint(path, some_state());
  EXPECT_EQ(files_in(folder.path()), 2u);  // the checkpoint and the leftover
  EXPECT_EQ(remove_stale_temporaries(path), 1);
  EXPECT_EQ(files_in(folder.path()), 1u);
  const auto back = read_checkpoint(path, 40);
  ASSERT_TRUE(back.has_value());
  EXPECT_EQ(back->done.size(), 5u);
  EXPECT_EQ(checkpoint_path_for("out/study.h5"), "out/study.h5.checkpoint");
}

// The checkpoint is the program's own file: a link, a FIFO, or a file larger than any checkpoint of
// the study could be is refused, never read.
TEST(Checkpoint, ReadsOnlyARegularFileOfAPlausibleSize) {
  TemporaryFolder folder;
  const auto path = folder.path() / "study.h5.checkpoint";
  write_checkpoint(folder.path() / "other", some_state());
  std::filesystem::create_symlink(folder.path() / "other", path);
  EXPECT_THROW(read_checkpoint(path, 40), CheckpointError);
  std::filesystem::remove(path);
  ASSERT_EQ(::mkfifo(path.c_str(), 0600), 0);
  EXPECT_THROW(read_checkpoint(path, 40), CheckpointError);
  std::filesystem::remove(path);
  write_checkpoint(path, some_state());  // 5 records: too many for a study of 2 samples
  EXPECT_THROW(read_checkpoint(path, 2), CheckpointError);
  EXPECT_NO_THROW(read_checkpoint(path, 40));
}

// Nothing planted in the output's folder can redirect a write: the temporary file has a fresh
// name and is created exclusively, and the rename replaces a link at the target, not its target.
TEST(AtomicFile, APlantedLinkIsNeverFollowed) {
  TemporaryFolder folder;
  const auto victim = folder.path() / "victim.txt";
  std::ofstream(victim) << "precious";
  const auto target = folder.path() / "out.h5";
  // The names a writer of the old scheme would have used, and the target itself, all links.
  for (const char* name : {"out.h5.tmp", "out.h5.checkpoint.tmp"}) {
    std::filesystem::create_symlink(victim, folder.path() / name);
  }
  std::filesystem::create_symlink(victim, target);
  write_file_atomically(target, "new content");
  EXPECT_EQ(read_input_file(victim, {100}), "precious");
  EXPECT_FALSE(std::filesystem::is_symlink(target));
  EXPECT_EQ(read_input_file(target, {100}), "new content");
  // A link to a file is never a leftover temporary: it is left alone.
  EXPECT_EQ(remove_stale_temporaries(folder.path() / "out.h5.tmp"), 0);
}

TEST(AtomicFile, AFailedWriteLeavesNothingBehind) {
  TemporaryFolder folder;
  const auto target = folder.path() / "out.h5";
  EXPECT_THROW(replace_file_atomically(target,
                                       [](const std::filesystem::path& temporary) {
                                         ::close(create_exclusively(temporary));
                                         throw FileError("disk full");
                                       }),
               FileError);
  EXPECT_EQ(files_in(folder.path()), 0u);
}

TEST(AtomicFile, FolderProblemsAreFoundBeforeAnyWork) {
  TemporaryFolder folder;
  EXPECT_FALSE(folder_write_problem(folder.path() / "out.h5").has_value());
  EXPECT_EQ(files_in(folder.path()), 0u);  // the probe is gone
  EXPECT_NE(folder_write_problem(folder.path() / "missing" / "out.h5")
                .value_or("")
                .find("does not exist"),
            std::string::npos);
  EXPECT_NE(folder_write_problem("/proc/out.h5").value_or("").find("cannot create a file"),
            std::string::npos);
}

TEST(StudyLock, OneHolderAtATimeAndFreeAgainAfterwards) {
  TemporaryFolder folder;
  const auto output = folder.path() / "study.h5";
  {
    StudyLock first(output);
    ASSERT_TRUE(first.held());
    StudyLock second(output);
    EXPECT_FALSE(second.held());
    EXPECT_TRUE(second.busy());
  }
  StudyLock again(output);
  EXPECT_TRUE(again.held());
}

// Two spellings of one output (through a linked folder, or with "..") take one lock.
TEST(StudyLock, IsTakenOnTheCanonicalFolder) {
  TemporaryFolder folder;
  std::filesystem::create_directory(folder.path() / "real");
  std::filesystem::create_directory_symlink(folder.path() / "real", folder.path() / "alias");
  StudyLock first(folder.path() / "real" / "study.h5");
  ASSERT_TRUE(first.held());
  EXPECT_TRUE(StudyLock(folder.path() / "alias" / "study.h5").busy());
  EXPECT_TRUE(StudyLock(folder.path() / "alias" / ".." / "real" / "study.h5").busy());
}

TEST(StudyLock, ALinkAtTheLocksNameIsRefusedAndNotFollowed) {
  TemporaryFolder folder;
  const auto victim = folder.path() / "victim";
  std::filesystem::create_symlink(victim, folder.path() / "study.h5.lock");
  StudyLock lock(folder.path() / "study.h5");
  EXPECT_FALSE(lock.held());
  EXPECT_FALSE(lock.busy());
  EXPECT_NE(lock.problem().find("symbolic link"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(victim));
}

// --- The work queue
// ---------------------------------------------------------------------------------

TEST(WorkQueue, HandsOutEveryPendingIndexExactlyOnce) {
  std::vector<bool> done(1000, false);
  for (std::size_t i = 0; i < done.size(); i += 7) done[i] = true;
  for (std::size_t i = 300; i < 400; ++i) done[i] = true;
  WorkQueue queue(done);
  std::multiset<std::int64_t> handed;
  int chunks = 0;
  bool gave_back = false;
  while (true) {
    IndexRange chunk = queue.next_chunk(3, 40);
    if (chunk.empty()) break;
    EXPECT_LE(chunk.count, 40);
    ++chunks;
    if (!gave_back && chunks == 5) {
      // An interrupted worker computed only the first two of its chunk.
      queue.give_back({chunk.first + 2, chunk.count - 2});
      chunk.count = 2;
      gave_back = true;
    }
    for (std::int64_t i = chunk.first; i < chunk.first + chunk.count; ++i) handed.insert(i);
  }
  EXPECT_EQ(queue.remaining(), 0);
  for (std::int64_t i = 0; i < 1000; ++i) {
    EXPECT_EQ(handed.count(i), done[static_cast<std::size_t>(i)] ? 0u : 1u) << i;
  }
  // Guided: chunks shrink to single samples at the end, so the last ones balance the ranks.
  EXPECT_GT(chunks, 1000 / 40);
}

}  // namespace
}  // namespace blockfrag
