// Runs a study's samples over the ranks of a communicator, checkpointing and resuming.
//
// Rank 0 keeps the queue of sample indices still to do and hands out contiguous chunks on demand
// (workers ask for the next chunk before they need it, so they never wait on a busy rank 0); it
// also computes samples itself, one at a time, and answers requests between two of them. Every
// record goes to rank 0, which writes it into the record spool (mpi_driver/io/record_spool.hpp) at
// once and keeps only which samples are done, so its memory does not grow with the study; it
// writes the checkpoint every checkpoint_interval_s and when interrupted (SIGTERM, SIGINT on any
// rank). A sample's record depends only on (config, index): the number of ranks, the chunks and
// the restarts change when it is computed, never its value.
#pragma once

#include <mpi.h>

#include <cstdint>
#include <filesystem>
#include <functional>
#include <ostream>
#include <vector>

#include "engine/errors.hpp"
#include "engine/scene/scene.hpp"
#include "engine/summary.hpp"
#include "mpi_driver/config/study_config.hpp"
#include "mpi_driver/io/atomic_file.hpp"
#include "mpi_driver/study/sample_evaluation.hpp"
#include "mpi_driver/study/study_record.hpp"
#include "mpi_driver/study/study_sample.hpp"

namespace blockfrag {

// The checkpoint on disk belongs to another study (or another sample count).
class StudyMismatchError : public InvalidInput {
 public:
  using InvalidInput::InvalidInput;
};

struct RunSettings {
  std::filesystem::path checkpoint;
  std::filesystem::path records;  // the record spool
  double checkpoint_interval_s = 60.0;
  AtomicWriteHooks checkpoint_hooks;
  std::ostream* log = nullptr;  // rank 0's progress lines; nullptr: silent
  bool log_is_terminal = false;
  double log_interval_s = 30.0;
  // The largest chunk handed to a worker; 0: adapted to the measured speed (study_runner.cpp).
  std::int64_t max_chunk = 0;
  // Say "resumed from" when the checkpoint holds samples: false for a growing study's later
  // batches, which always continue the one before.
  bool announce_resume = true;
};

enum class RunOutcome { completed, interrupted };

struct RunResult {
  RunOutcome outcome = RunOutcome::completed;
  std::int64_t restored = 0;        // records read from the checkpoint
  std::int64_t computed = 0;        // records computed in this run (all ranks; rank 0's count)
  std::int64_t chunks = 0;          // chunks handed to workers in this run
  std::int64_t chunk_samples = 0;   // the samples those chunks held
  std::int64_t checkpoints = 0;     // checkpoints written in this run
  double checkpoint_seconds = 0.0;  // time rank 0 spent writing them
};

// Collective: rank 0's outcome to every rank (run_samples returns a default one on the others);
// true when the run was interrupted.
bool interrupted_on_rank0(MPI_Comm comm, RunOutcome outcome);

// Any set of samples the runner can run: `total` samples, each a pure function of its index, tied
// to its checkpoint and record spool by `hash`. Each rank has its own (evaluate may keep state,
// such as a sampler's cached permutations).
struct SampleJob {
  std::uint64_t hash = 0;
  std::int64_t total = 0;
  std::function<SampleRecord(std::int64_t index)> evaluate;
  // This run computes samples [0, run_until) only (0: all): a study that grows in batches runs
  // one prefix after another against one checkpoint and spool of `total` samples.
  std::int64_t run_until = 0;
  // What the hash identifies, for the messages that refuse another's checkpoint ("a different
  // study config") and name what to rerun ("the original config").
  const char* config_name = "study config";
  const char* config_word = "config";

  std::int64_t end() const { return run_until > 0 ? run_until : total; }
};

// Collective over comm: runs the job's samples as described above, resuming from the checkpoint.
// Throws as run_study_samples does.
RunResult run_samples(MPI_Comm comm, const SampleJob& job, const RunSettings& settings);

// A study's samples: its sample i evaluated by `evaluate` (mpi_driver/study/sample_evaluation.hpp).
// Collective over comm. Throws StudyMismatchError (on every rank) when the checkpoint belongs to
// another study or is damaged, or the record spool is not the checkpoint's (the message on rank 0
// says which). When the outcome is completed, settings.records holds every sample's record.
RunResult run_study_samples(MPI_Comm comm, const StudyConfig& config, const RunSettings& settings,
                            const SceneEvaluator& evaluate);

}  // namespace blockfrag
