// Runs an overturning spectrum over the ranks of a communicator, with the study machinery's
// checkpoints, signals and dynamic distribution (study_runner.hpp's run_samples):
//
// 1. The map: one job over every grid point, index i = (frequency index) * na + (amplitude index).
//    Its records end in the map's record spool (OUTPUT.records), checkpointed in OUTPUT.checkpoint.
// 2. The boundaries: rank 0 finds every bracket in the map's columns (spectrum_bisection.hpp) and
//    then runs rounds: each round is one job of the midpoints of every open bracket, evaluated in
//    parallel (its own spool and checkpoint, OUTPUT.round-records and OUTPUT.round-checkpoint),
//    after which rank 0 narrows the brackets. The brackets at the start of each round are in
//    OUTPUT.bisection, written before the round runs; a killed run resumes the round it was in
//    (from its checkpoint) or the one before.
// 3. The minimum overturning amplitudes: rank 0 starts each frequency's refinement
//    (mpi_driver/study/minimum_overturning.hpp) from the map's column and its bisected onset, then
//    runs rounds the same way: each round the midpoints of every open segment, in the same round
//    files, after which rank 0 refines the segments; OUTPUT.minimum holds them at the start of
//    each round.
//
// A bracket's or a segment's midpoints depend only on the config: the boundaries and the minima
// are the same on any number of ranks, after any restart.
#pragma once

#include <mpi.h>

#include <cstdint>
#include <filesystem>
#include <vector>

#include "mpi_driver/config/spectrum_config.hpp"
#include "mpi_driver/parallel/study_runner.hpp"
#include "mpi_driver/study/minimum_overturning.hpp"
#include "mpi_driver/study/spectrum_bisection.hpp"

namespace blockfrag {

struct SpectrumFiles {
  std::filesystem::path bisection;         // the brackets at the start of a round
  std::filesystem::path minimum;           // the minimum's segments at the start of a round
  std::filesystem::path round_checkpoint;  // the running round's checkpoint (either phase's)
  std::filesystem::path round_records;     // and its records

  // OUTPUT.bisection, OUTPUT.minimum, OUTPUT.round-checkpoint and OUTPUT.round-records, next to
  // the output (endings no output's own files have: mpi_driver/config/output_name.hpp).
  static SpectrumFiles for_output(const std::filesystem::path& output);
};

struct SpectrumRunResult {
  RunOutcome outcome = RunOutcome::completed;
  RunResult map;                          // the map phase in this run
  std::int64_t rounds = 0;                // bisection rounds run in this run
  std::int64_t midpoints = 0;             // bisection midpoints evaluated in this run
  std::int64_t minimum_rounds = 0;        // minimum refinement rounds run in this run
  std::int64_t minimum_midpoints = 0;     // and their midpoints
  std::vector<SpectrumBracket> brackets;  // rank 0, when completed: every crossing, closed
  MinimumRefinement minimum;              // rank 0, when completed: every segment, closed
};

// Collective over comm: first rank 0 checks the rounds' files (a damaged or foreign one is refused
// before the map starts), then the map (settings: its checkpoint, records, interval, log), then the
// bisection rounds, then the minimum's. When completed, settings.records holds every map point's
// record and rank 0's result the final brackets and segments. Throws StudyMismatchError (on every
// rank) when a checkpoint or the bisection state belongs to another spectrum or is damaged,
// FileFailure when a file cannot be written.
SpectrumRunResult run_spectrum(MPI_Comm comm, const SpectrumConfig& config,
                               const RunSettings& settings, const SpectrumFiles& files,
                               const SceneEvaluator& evaluate);

// Rank 0, once the output is written: removes the spectrum's files, each only when its hash says it
// is this spectrum's (the map's, or one of its bisection rounds'); anything else is left alone.
void remove_spectrum_files(const SpectrumConfig& config, const RunSettings& settings,
                           const SpectrumFiles& files);

}  // namespace blockfrag
