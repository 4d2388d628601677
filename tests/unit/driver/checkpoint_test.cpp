// Checkpoints: the file round-trips its ranges, damage of any kind is refused, the atomic write
// leaves no partial file behind; the record spool keeps every record's bits where it belongs and
// never overwrites a file that is not its own; index sets against a plain vector of flags; one run
// at a time holds the study lock; the work queue hands out every pending index exactly once, also
// after give-backs. (The run loop itself,
// which needs MPI, is tested in tests/mpi/driver/study_runner_test.cpp.)
#include "mpi_driver/parallel/checkpoint.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <set>
#include <string>

#include <gtest/gtest.h>
#include <sys/stat.h>

#include "mpi_driver/config/input_file.hpp"
#include "mpi_driver/io/atomic_file.hpp"
#include "mpi_driver/io/record_spool.hpp"
#include "mpi_driver/parallel/study_lock.hpp"
#include "mpi_driver/parallel/work_distribution.hpp"
#include "tests/support/temporary_folder.hpp"

namespace blockfrag {
namespace {

using testing::TemporaryFolder;

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
  state.done = {{0, 3}, {7, 1}, {13, 10}, {49, 1}};
  return state;
}

bool same_ranges(const std::vector<IndexRange>& a, const std::vector<IndexRange>& b) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](IndexRange x, IndexRange y) {
    return x.first == y.first && x.count == y.count;
  });
}

TEST(Checkpoint, RoundTripsEveryRange) {
  const CheckpointState state = some_state();
  const CheckpointState back = decode_checkpoint(encode_checkpoint(state), "test");
  EXPECT_EQ(back.config_hash, state.config_hash);
  EXPECT_EQ(back.total_samples, 50);
  EXPECT_TRUE(same_ranges(back.done, state.done));
}

TEST(Checkpoint, EmptyStateRoundTrips) {
  CheckpointState state;
  state.total_samples = 10;
  EXPECT_TRUE(decode_checkpoint(encode_checkpoint(state), "test").done.empty());
}

TEST(Checkpoint, EveryDamageIsRefused) {
  const std::string bytes = encode_checkpoint(some_state());
  for (std::size_t position = 0; position < bytes.size(); position += 3) {
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

TEST(Checkpoint, RangesOutOfOrderOverlappingEmptyOrOutsideTheStudyAreRefused) {
  for (const auto& done : std::vector<std::vector<IndexRange>>{{{13, 10}, {0, 3}},
                                                               {{0, 3}, {2, 5}},
                                                               {{0, 3}, {7, 0}},
                                                               {{-1, 2}},
                                                               {{45, 6}},
                                                               {{1, INT64_MAX}}}) {
    CheckpointState state = some_state();
    state.done = done;
    EXPECT_THROW(decode_checkpoint(encode_checkpoint(state), "test"), CheckpointError)
        << done.front().first << " " << done.front().count;
  }
}

TEST(Checkpoint, AnOlderCheckpointWithTheRecordsInsideIsRefusedSayingSo) {
  std::string older = "BFCKPT01";
  older.append(40, '\0');
  try {
    decode_checkpoint(older, "study.h5.checkpoint");
    FAIL() << "accepted";
  } catch (const CheckpointError& error) {
    EXPECT_NE(std::string(error.what()).find("older blockfrag"), std::string::npos) << error.what();
  }
}

std::size_t files_in(const std::filesystem::path& folder) {
  std::size_t count = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(folder)) ++count;
  return count;
}

TEST(Checkpoint, FileWriteIsAtomicAndLeavesNoTemporary) {
  TemporaryFolder folder;
  const auto path = folder.path() / "study.h5.checkpoint";
  EXPECT_FALSE(read_checkpoint(path).has_value());
  // A leftover temporary from a writer killed before its rename is neither read nor in the way,
  // and the study's start (holding the lock) clears it.
  std::ofstream(folder.path() / "study.h5.checkpoint.tmp.a1B2c3") << "half a checkpoint";
  EXPECT_FALSE(read_checkpoint(path).has_value());
  write_checkpoint(path, some_state());
  EXPECT_EQ(files_in(folder.path()), 2u);  // the checkpoint and the leftover
  EXPECT_EQ(remove_stale_temporaries(path), 1);
  EXPECT_EQ(files_in(folder.path()), 1u);
  const auto back = read_checkpoint(path);
  ASSERT_TRUE(back.has_value());
  EXPECT_TRUE(same_ranges(back->done, some_state().done));
  EXPECT_EQ(checkpoint_path_for("out/study.h5"), "out/study.h5.checkpoint");
}

// The checkpoint is the program's own file: a link, a FIFO, or a file larger than any checkpoint of
// the study could be is refused, never read.
TEST(Checkpoint, ReadsOnlyARegularFileOfAPlausibleSize) {
  TemporaryFolder folder;
  const auto path = folder.path() / "study.h5.checkpoint";
  write_checkpoint(folder.path() / "other", some_state());
  std::filesystem::create_symlink(folder.path() / "other", path);
  EXPECT_THROW(read_checkpoint(path), CheckpointError);
  std::filesystem::remove(path);
  ASSERT_EQ(::mkfifo(path.c_str(), 0600), 0);
  EXPECT_THROW(read_checkpoint(path), CheckpointError);
  std::filesystem::remove(path);
  // Larger than a checkpoint of kMaxCheckpointRanges ranges: refused before it is read.
  std::filesystem::resize_file(folder.path() / "other", 16 * (kMaxCheckpointRanges + 4));
  std::filesystem::rename(folder.path() / "other", path);
  EXPECT_THROW(read_checkpoint(path), CheckpointError);
  write_checkpoint(path, some_state());
  EXPECT_NO_THROW(read_checkpoint(path));
}

// Nothing planted in the output's folder can redirect a write: the temporary file has a fresh
// name and is created exclusively, and a link at the target is neither followed nor replaced.
TEST(AtomicFile, APlantedLinkIsNeverFollowed) {
  TemporaryFolder folder;
  const auto victim = folder.path() / "victim.txt";
  std::ofstream(victim) << "precious";
  const auto target = folder.path() / "out.h5";
  // The names a writer of the old scheme would have used, and the target itself, all links.
  for (const char* name : {"out.h5.tmp", "out.h5.checkpoint.tmp"}) {
    std::filesystem::create_symlink(victim, folder.path() / name);
  }
  write_file_atomically(target, "new content");
  EXPECT_EQ(read_input_file(target, {100}), "new content");
  std::filesystem::remove(target);
  std::filesystem::create_symlink(victim, target);
  EXPECT_THROW(write_file_atomically(target, "newer content"), FileError);
  EXPECT_EQ(read_input_file(victim, {100}), "precious");
  EXPECT_TRUE(std::filesystem::is_symlink(target));
  EXPECT_EQ(files_in(folder.path()), 4u);  // no temporary left: victim, two links, target
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

TEST(IndexSet, AgreesWithAVectorOfFlagsWhateverTheOrderOfTheRanges) {
  std::mt19937_64 engine(7);
  for (int trial = 0; trial < 50; ++trial) {
    const std::int64_t total = 200;
    std::vector<bool> flags(total, false);
    IndexSet set;
    for (int k = 0; k < 30; ++k) {
      const auto first = static_cast<std::int64_t>(engine() % total);
      const auto count = static_cast<std::int64_t>(engine() % 12);
      set.add({first, std::min(count, total - first)});
      for (std::int64_t i = first; i < std::min(first + count, total); ++i)
        flags[static_cast<std::size_t>(i)] = true;
    }
    const auto count = std::count(flags.begin(), flags.end(), true);
    EXPECT_EQ(set.count(), count);
    std::vector<bool> from_ranges(total, false), from_missing(total, true);
    std::int64_t previous_end = -1;
    for (const IndexRange range : set.ranges()) {
      EXPECT_GT(range.first, previous_end) << "ranges must be disjoint and not adjacent";
      previous_end = range.end();
      for (std::int64_t i = range.first; i < range.end(); ++i)
        from_ranges[static_cast<std::size_t>(i)] = true;
    }
    for (const IndexRange range : set.missing(total)) {
      for (std::int64_t i = range.first; i < range.end(); ++i)
        from_missing[static_cast<std::size_t>(i)] = false;
    }
    EXPECT_EQ(from_ranges, flags);
    EXPECT_EQ(from_missing, flags);
    for (std::int64_t i = 0; i < total; ++i)
      EXPECT_EQ(set.contains(i), flags[static_cast<std::size_t>(i)]) << i;
  }
}

TEST(RecordSpool, KeepsEachRecordsBitsAtItsIndexAndResumesOnlyItsOwnStudy) {
  TemporaryFolder folder;
  const auto path = record_spool_path_for(folder.path() / "study.h5");
  EXPECT_EQ(path, folder.path() / "study.h5.records");
  {
    RecordSpool spool(path, 42, 1000, RecordSpool::Mode::fresh);
    std::vector<SampleRecord> records;
    for (std::int64_t i = 990; i < 1000; ++i) records.push_back(some_record(i));
    spool.write(records);
    const SampleRecord one = some_record(3);
    spool.write({&one, 1});
    spool.sync();
    // Not consecutive, or outside the study: a bug in the caller.
    std::vector<SampleRecord> gap = {some_record(5), some_record(7)};
    EXPECT_THROW(spool.write(gap), ContractViolation);
    const SampleRecord outside = some_record(1000);
    EXPECT_THROW(spool.write({&outside, 1}), ContractViolation);
  }
  RecordSpool resumed(path, 42, 1000, RecordSpool::Mode::resume);
  std::vector<SampleRecord> back(12);
  resumed.read(988, back);
  EXPECT_EQ(back[0].index, 0);  // never written: zeros
  for (std::int64_t i = 990; i < 1000; ++i)
    EXPECT_TRUE(same_bits(back[static_cast<std::size_t>(i - 988)], some_record(i))) << i;
  std::vector<SampleRecord> three(1);
  resumed.read(3, three);
  EXPECT_TRUE(same_bits(three[0], some_record(3)));

  EXPECT_THROW(RecordSpool(path, 43, 1000, RecordSpool::Mode::resume), RecordSpoolError);
  EXPECT_THROW(RecordSpool(path, 42, 999, RecordSpool::Mode::resume), RecordSpoolError);
  EXPECT_THROW(RecordSpool(folder.path() / "missing.records", 42, 1000, RecordSpool::Mode::resume),
               RecordSpoolError);
  // A fresh start reuses its own file, emptied.
  RecordSpool fresh(path, 42, 1000, RecordSpool::Mode::fresh);
  fresh.read(990, three);
  EXPECT_EQ(three[0].index, 0);
}

TEST(RecordSpool, NeverWritesIntoAFileThatIsNotItsOwn) {
  TemporaryFolder folder;
  const auto path = folder.path() / "study.h5.records";
  std::ofstream(path) << "someone's notes";
  EXPECT_THROW(RecordSpool(path, 1, 10, RecordSpool::Mode::fresh), RecordSpoolError);
  std::ifstream in(path);
  std::string content;
  std::getline(in, content);
  EXPECT_EQ(content, "someone's notes");
  std::filesystem::remove(path);
  std::ofstream(folder.path() / "target") << "x";
  std::filesystem::create_symlink(folder.path() / "target", path);
  EXPECT_THROW(RecordSpool(path, 1, 10, RecordSpool::Mode::fresh), RecordSpoolError);
  EXPECT_EQ(std::filesystem::file_size(folder.path() / "target"), 1u);
  std::filesystem::remove(path);
  std::filesystem::create_directory(path);
  EXPECT_THROW(RecordSpool(path, 1, 10, RecordSpool::Mode::fresh), std::exception);
}

TEST(WorkQueue, HandsOutEveryPendingIndexExactlyOnce) {
  std::vector<bool> done(1000, false);
  IndexSet done_set;
  for (std::size_t i = 0; i < done.size(); i += 7) {
    done[i] = true;
    done_set.add({static_cast<std::int64_t>(i), 1});
  }
  for (std::size_t i = 300; i < 400; ++i) done[i] = true;
  done_set.add({300, 100});
  WorkQueue queue(done_set.missing(1000));
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
