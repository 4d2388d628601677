// `mpirun -n N blockfrag run STUDY.json [--output FILE.h5] [--samples-per-level N]`: a batch study
// over N ranks (N = 1 works without mpirun). The two options replace the config's values. Running
// the same command again after a kill resumes from the checkpoint FILE.h5.checkpoint; after a
// completed run it reports the study complete and does nothing.
//
// Exit codes (main's, plus one): 0 done (or already complete); 1 an I/O error; 2 a bad config or
// a refused run (the checkpoint or output belongs to another config, or another run of the study
// is in progress); 4 interrupted by SIGTERM or SIGINT after writing a checkpoint: run the same
// command to resume. (Under mpirun, a signal sent to mpirun itself makes mpirun report its own
// non-zero code; the ranks still checkpoint and exit 4.)
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>

#include "mpi_driver/cli/exit_codes.hpp"
#include "mpi_driver/io/atomic_file.hpp"
#include "mpi_driver/parallel/study_runner.hpp"

namespace blockfrag {

struct RunOptions {
  std::filesystem::path study_path;
  std::optional<std::filesystem::path> output;
  std::optional<long> samples_per_level;
  std::int64_t max_chunk = 0;         // 0: adapted (RunSettings::max_chunk)
  AtomicWriteHooks checkpoint_hooks;  // none from the command line (run_command_line)
};

// Initialises and finalises MPI; runs the study with `evaluate` (blockfrag::simulate by default)
// and returns the exit code. On rank 0, a bad config or a refused resume throws ConfigError (after
// MPI is finalised); the other ranks return 2 quietly, so the message is printed once.
int run_study_command(const RunOptions& options, const SceneEvaluator& evaluate = {});

}  // namespace blockfrag
