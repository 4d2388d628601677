// Runs an adaptive study (mpi_driver/config/adaptive_design.hpp): batch after batch, each a prefix
// of one growing study run by run_samples against one checkpoint and record spool of max_samples
// samples. After each batch rank 0 fits the adaptive limit state over every sample so far and
// decides (mpi_driver/study/adaptive_levels.hpp); every rank learns the next levels. A resumed run
// replays the decisions from the records on disk, so it places the batches exactly as the first
// run did.
#pragma once

#include <mpi.h>

#include <cstdint>

#include "mpi_driver/config/study_config.hpp"
#include "mpi_driver/parallel/study_runner.hpp"
#include "mpi_driver/study/adaptive_levels.hpp"

namespace blockfrag {

struct AdaptiveRun {
  RunResult result;   // summed over the batches; restored: what the first batch found done
  StudyConfig grown;  // the config with every batch's levels: what the output describes
  AdaptiveHistory history;
};

// The samples an adaptive study's spool and checkpoint hold room for: its budget, whole levels.
std::int64_t adaptive_capacity(const StudyConfig& config);

// Collective over comm, like run_study_samples.
AdaptiveRun run_adaptive_study(MPI_Comm comm, const StudyConfig& config,
                               const RunSettings& settings, const SceneEvaluator& evaluate);

}  // namespace blockfrag
