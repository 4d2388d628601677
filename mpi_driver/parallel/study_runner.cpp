#include "mpi_driver/parallel/study_runner.hpp"

#include <chrono>
#include <cstring>
#include <deque>
#include <memory>
#include <optional>
#include <span>
#include <thread>

#include "mpi_driver/config/study_hash.hpp"
#include "mpi_driver/io/record_spool.hpp"
#include "mpi_driver/parallel/checkpoint.hpp"
#include "mpi_driver/parallel/chunk_sizing.hpp"
#include "mpi_driver/parallel/progress.hpp"
#include "mpi_driver/parallel/signals.hpp"
#include "mpi_driver/parallel/work_distribution.hpp"

namespace blockfrag {
namespace {

using Clock = std::chrono::steady_clock;

// Worker -> rank 0: a header and the records computed for its chunk (a prefix of it).
// Rank 0 -> worker: a chunk (count 0: no more work), a stop request, or the final goodbye.
enum Tag : int { tag_report = 1, tag_chunk = 2, tag_stop = 3, tag_goodbye = 4 };

constexpr std::int64_t wants_more = 1;  // also a request for the next chunk
constexpr std::int64_t interrupted =
    2;                                // the worker got a signal or a stop: it computes nothing more
constexpr std::int64_t finished = 4;  // the worker's last report: no request is outstanding

struct ReportHeader {
  std::int64_t chunk_first = 0;
  std::int64_t chunk_count = 0;
  std::int64_t computed = 0;
  std::int64_t flags = 0;
};

// Two chunks in hand or on the way: the next one is already there when the current one ends.
constexpr int prefetch_depth = 2;

// Chunks last about this long at the cost per sample rank 0 measured last (chunk_sizing.hpp), so
// each worker asks rank 0 about 5 times a second: 1,000 ranks send 5,000 requests/s, a fraction of
// what rank 0 serves (docs/performance.md). The guided rule still shrinks the last chunks, so the
// ranks finish together.
constexpr double kChunkSeconds = 0.2;
// Chunks start at this size, before any sample is timed, and stay within these bounds. The
// largest keeps the cheapest samples (a block that never moves: 1.4 to 3 us) to 20 to 45 requests
// a second a rank, so rank 0 serves 1,000 to 2,000 such ranks (docs/performance.md); it is a
// 1.7 MB message.
constexpr std::int64_t kSmallestChunkLimit = 64;
constexpr std::int64_t kLargestChunk = 16384;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

void send_report(MPI_Comm comm, const ReportHeader& header,
                 const std::vector<SampleRecord>& records) {
  std::vector<char> buffer(sizeof header + records.size() * sizeof(SampleRecord));
  std::memcpy(buffer.data(), &header, sizeof header);
  if (!records.empty())
    std::memcpy(buffer.data() + sizeof header, records.data(),
                records.size() * sizeof(SampleRecord));
  MPI_Send(buffer.data(), static_cast<int>(buffer.size()), MPI_BYTE, 0, tag_report, comm);
}

void send_chunk(MPI_Comm comm, int worker, IndexRange chunk) {
  const std::int64_t message[2] = {chunk.first, chunk.count};
  MPI_Send(message, 2, MPI_INT64_T, worker, tag_chunk, comm);
}

void run_worker(MPI_Comm comm, const SampleJob& job) {
  int outstanding = 0;
  bool no_more_work = false;
  bool stopped = false;
  std::deque<IndexRange> chunks;
  for (int k = 0; k < prefetch_depth; ++k) {
    send_report(comm, {0, 0, 0, wants_more}, {});
    ++outstanding;
  }
  const auto check_stop = [&] {
    int arrived = 0;
    MPI_Iprobe(0, tag_stop, comm, &arrived, MPI_STATUS_IGNORE);
    if (arrived) {
      MPI_Recv(nullptr, 0, MPI_BYTE, 0, tag_stop, comm, MPI_STATUS_IGNORE);
      stopped = true;
    }
    if (interrupt_requested()) stopped = true;
  };
  while (!chunks.empty() || outstanding > 0) {
    if (chunks.empty()) {
      std::int64_t message[2];
      MPI_Recv(message, 2, MPI_INT64_T, 0, tag_chunk, comm, MPI_STATUS_IGNORE);
      --outstanding;
      if (message[1] == 0) {
        no_more_work = true;
      } else {
        chunks.push_back({message[0], message[1]});
      }
      continue;
    }
    const IndexRange chunk = chunks.front();
    chunks.pop_front();
    std::vector<SampleRecord> records;
    for (std::int64_t i = chunk.first; i < chunk.first + chunk.count; ++i) {
      check_stop();
      if (stopped) break;
      records.push_back(job.evaluate(i));
    }
    const bool more = !no_more_work && !stopped;
    const std::int64_t flags = (more ? wants_more : 0) | (stopped ? interrupted : 0);
    send_report(comm, {chunk.first, chunk.count, static_cast<std::int64_t>(records.size()), flags},
                records);
    if (more) ++outstanding;
  }
  send_report(comm, {0, 0, 0, finished | (stopped ? interrupted : 0)}, {});
  // A stop may still be on its way; the goodbye comes after it, so nothing is left unreceived.
  for (;;) {
    MPI_Status status;
    MPI_Recv(nullptr, 0, MPI_BYTE, 0, MPI_ANY_TAG, comm, &status);
    if (status.MPI_TAG == tag_goodbye) break;
  }
}

// Rank 0's state: what is done, what is left, who is still working.
class Coordinator {
 public:
  Coordinator(MPI_Comm comm, const SampleJob& job, const RunSettings& settings,
              const CheckpointState& restored, RecordSpool& spool)
      : comm_(comm), job_(job), settings_(settings), spool_(spool) {
    MPI_Comm_size(comm_, &ranks_);
    for (const auto& range : restored.done) done_.add(range);
    result_.restored = done_.count_below(job.end());
    queue_.emplace(done_.missing(job.end()));
    active_workers_ = ranks_ - 1;
    finished_.assign(static_cast<std::size_t>(ranks_), false);
  }

  RunResult run() {
    ProgressReporter progress(settings_.log ? *settings_.log : null_stream(),
                              settings_.log_is_terminal, job_.end(), done_.count_below(job_.end()),
                              settings_.log_interval_s);
    if (settings_.log && settings_.announce_resume && result_.restored > 0) {
      *settings_.log << "resumed from " << settings_.checkpoint.string() << ": " << result_.restored
                     << " of " << job_.end() << " samples already done\n";
    }
    auto last_checkpoint = Clock::now();
    for (;;) {
      serve_reports();
      if (interrupt_requested()) interrupt();
      if (!interrupted_) {
        const IndexRange own = queue_->next_chunk(ranks_, 1);
        if (!own.empty()) {
          const auto started = Clock::now();
          const SampleRecord record = job_.evaluate(own.first);
          if (ranks_ > 1) sizer_.record(seconds_since(started));
          store({&record, 1});
          ++result_.computed;
        }
      }
      const bool all_done = done_.count_below(job_.end()) == job_.end();
      if ((all_done || interrupted_) && active_workers_ == 0) break;
      if (interrupted_ || queue_->remaining() == 0)
        std::this_thread::sleep_for(std::chrono::microseconds(200));
      if (!all_done && seconds_since(last_checkpoint) >= settings_.checkpoint_interval_s) {
        write_checkpoint_now();
        last_checkpoint = Clock::now();
      }
      if (settings_.log) progress.update(done_.count_below(job_.end()));
    }
    if (settings_.log) progress.finish(done_.count_below(job_.end()));
    if (interrupted_) {
      write_checkpoint_now();
      result_.outcome = RunOutcome::interrupted;
    } else {
      // A finished job too: a growing study's next batch starts here, and an output that cannot be
      // written (a full disk) is written by the rerun from the records, computing nothing again.
      write_checkpoint_now();
    }
    return std::move(result_);
  }

 private:
  static std::ostream& null_stream() {
    static std::ostream stream(nullptr);
    return stream;
  }

  // Consecutive records, each handed out once: written where they belong, and marked done.
  void store(std::span<const SampleRecord> records) {
    if (records.empty()) return;
    spool_.write(records);
    done_.add({records.front().index, static_cast<std::int64_t>(records.size())});
  }

  // The largest chunk to hand out: fixed by the settings, or kChunkSeconds of work at the cost
  // per sample rank 0 measured last. Which samples a chunk holds never changes their records,
  // only when they are computed.
  std::int64_t chunk_limit() const {
    return settings_.max_chunk > 0 ? settings_.max_chunk : sizer_.limit();
  }

  void interrupt() {
    if (interrupted_) return;
    interrupted_ = true;
    for (int worker = 1; worker < ranks_; ++worker) {
      if (!finished_[static_cast<std::size_t>(worker)]) {
        MPI_Send(nullptr, 0, MPI_BYTE, worker, tag_stop, comm_);
      }
    }
  }

  void serve_reports() {
    for (;;) {
      int arrived = 0;
      MPI_Status status;
      MPI_Iprobe(MPI_ANY_SOURCE, tag_report, comm_, &arrived, &status);
      if (!arrived) return;
      int bytes = 0;
      MPI_Get_count(&status, MPI_BYTE, &bytes);
      std::vector<char> buffer(static_cast<std::size_t>(bytes));
      MPI_Recv(buffer.data(), bytes, MPI_BYTE, status.MPI_SOURCE, tag_report, comm_,
               MPI_STATUS_IGNORE);
      handle_report(status.MPI_SOURCE, buffer);
    }
  }

  void handle_report(int worker, const std::vector<char>& buffer) {
    ReportHeader header;
    std::memcpy(&header, buffer.data(), sizeof header);
    std::vector<SampleRecord> records(static_cast<std::size_t>(header.computed));
    if (header.computed > 0) {
      std::memcpy(records.data(), buffer.data() + sizeof header,
                  records.size() * sizeof(SampleRecord));
    }
    store(records);
    result_.computed += header.computed;
    queue_->give_back({header.chunk_first + header.computed, header.chunk_count - header.computed});
    if (header.flags & interrupted) interrupt();
    if (header.flags & wants_more) {
      const IndexRange chunk =
          interrupted_ ? IndexRange{} : queue_->next_chunk(ranks_, chunk_limit());
      if (!chunk.empty()) {
        ++result_.chunks;
        result_.chunk_samples += chunk.count;
      }
      send_chunk(comm_, worker, chunk);
    }
    if (header.flags & finished) {
      finished_[static_cast<std::size_t>(worker)] = true;
      --active_workers_;
      MPI_Send(nullptr, 0, MPI_BYTE, worker, tag_goodbye, comm_);
    }
  }

  void write_checkpoint_now() {
    const auto start = Clock::now();
    // The records first: a checkpoint must never call done a sample whose record is not on disk.
    spool_.sync();
    CheckpointState state;
    state.config_hash = job_.hash;
    state.total_samples = job_.total;
    state.done = done_.ranges();
    write_checkpoint(settings_.checkpoint, state, settings_.checkpoint_hooks);
    ++result_.checkpoints;
    result_.checkpoint_seconds += seconds_since(start);
  }

  MPI_Comm comm_;
  ChunkSizer sizer_{kChunkSeconds, kSmallestChunkLimit, kLargestChunk};
  const SampleJob& job_;
  const RunSettings& settings_;
  int ranks_ = 1;
  RecordSpool& spool_;
  RunResult result_;
  IndexSet done_;
  std::optional<WorkQueue> queue_;
  std::vector<bool> finished_;
  int active_workers_ = 0;
  bool interrupted_ = false;
};

// What a run starts from on rank 0: the checkpoint's progress and the record spool.
struct Restored {
  CheckpointState checkpoint;
  std::unique_ptr<RecordSpool> spool;
};

// Rank 0 reads the checkpoint, checks it against the config and opens the record spool; the
// verdict goes to every rank so all of them stop together when it is refused.
Restored restore(MPI_Comm comm, const SampleJob& job, const RunSettings& settings) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  Restored restored;
  std::string refusal;
  int refused = 0;  // 1: the checkpoint or spool is not this study's; 2: a file cannot be used
  if (rank == 0) {
    try {
      const std::optional<CheckpointState> checkpoint = read_checkpoint(settings.checkpoint);
      if (checkpoint && checkpoint->config_hash != job.hash) {
        const std::string word = job.config_word;
        throw StudyMismatchError("refusing to resume: the checkpoint " +
                                 settings.checkpoint.string() + " belongs to a different " +
                                 job.config_name + " (checkpoint " + word + " hash " +
                                 hash_to_hex(checkpoint->config_hash) + ", this " + word + " " +
                                 hash_to_hex(job.hash) + "); run the original " + word +
                                 " to finish it, or remove the checkpoint to start over");
      }
      if (checkpoint && checkpoint->total_samples != job.total) {
        throw StudyMismatchError("refusing to resume: the checkpoint " +
                                 settings.checkpoint.string() + " has " +
                                 std::to_string(checkpoint->total_samples) +
                                 " samples, this study " + std::to_string(job.total));
      }
      restored.spool = std::make_unique<RecordSpool>(
          settings.records, job.hash, job.total,
          checkpoint ? RecordSpool::Mode::resume : RecordSpool::Mode::fresh);
      if (checkpoint) restored.checkpoint = *checkpoint;
    } catch (const InvalidInput& error) {
      refusal = error.what();
      refused = 1;
    } catch (const FileFailure& error) {
      refusal = error.what();
      refused = 2;
    }
  }
  MPI_Bcast(&refused, 1, MPI_INT, 0, comm);
  if (refused == 2) throw FileFailure(rank == 0 ? refusal : "cannot start (see rank 0)");
  if (refused) throw StudyMismatchError(rank == 0 ? refusal : "refusing to resume (see rank 0)");
  return restored;
}

}  // namespace

bool interrupted_on_rank0(MPI_Comm comm, RunOutcome outcome) {
  int code = static_cast<int>(outcome);
  MPI_Bcast(&code, 1, MPI_INT, 0, comm);
  return code == static_cast<int>(RunOutcome::interrupted);
}

RunResult run_samples(MPI_Comm comm, const SampleJob& job, const RunSettings& settings) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  Restored restored = restore(comm, job, settings);
  if (rank != 0) {
    run_worker(comm, job);
    return {};
  }
  Coordinator coordinator(comm, job, settings, restored.checkpoint, *restored.spool);
  return coordinator.run();
}

RunResult run_study_samples(MPI_Comm comm, const StudyConfig& config, const RunSettings& settings,
                            const SceneEvaluator& evaluate) {
  StudySampler sampler(config);
  const SampleJob job{config.hash, config.total_samples(), [&](std::int64_t index) {
                        return evaluate_sample(sampler, index, evaluate);
                      }};
  return run_samples(comm, job, settings);
}

}  // namespace blockfrag
