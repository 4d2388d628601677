// `mpirun -n N blockfrag spectrum SPEC.json [--output FILE.h5]`: an overturning spectrum over N
// ranks (N = 1 works without mpirun): the map over the grid, then the boundaries by bisection
// (mpi_driver/parallel/spectrum_runner.hpp), into FILE.h5 (mpi_driver/io/spectrum_output.hpp).
// Running the same command again after a kill resumes from the checkpoint (the map's, or the
// bisection's); after a completed run it reports the spectrum complete and does nothing.
//
// Exit codes as `run`'s: 0 done (or already complete); 1 an I/O error; 2 a bad config or a refused
// run (a file of another spectrum at the output, its checkpoint or bisection state, or another run
// in progress); 3 the output is written, but some points failed or some crossings stopped short of
// the tolerance; 4 interrupted by SIGTERM or SIGINT after writing a checkpoint.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>

#include "mpi_driver/io/atomic_file.hpp"
#include "mpi_driver/study/sample_evaluation.hpp"

namespace blockfrag {

struct SpectrumOptions {
  std::filesystem::path spectrum_path;
  std::optional<std::filesystem::path> output;
  std::int64_t max_chunk = 0;         // 0: adapted (RunSettings::max_chunk)
  AtomicWriteHooks checkpoint_hooks;  // none from the command line (run_command_line)
};

// Initialises and finalises MPI; runs the spectrum with `evaluate` (blockfrag::simulate by
// default) and returns the exit code. On rank 0, a bad config or a refused run throws ConfigError
// (after MPI is finalised); the other ranks return 2 quietly, so the message is printed once.
int run_spectrum_command(const SpectrumOptions& options, const SceneEvaluator& evaluate = {});

}  // namespace blockfrag
