#include "mpi_driver/cli/run_command.hpp"

#include <unistd.h>

#include <iostream>

#include "engine/simulate.hpp"
#include "mpi_driver/cli/distributed_run.hpp"
#include "mpi_driver/config/config_reader.hpp"
#include "mpi_driver/config/study_hash.hpp"
#include "mpi_driver/io/record_spool.hpp"
#include "mpi_driver/io/study_output.hpp"
#include "mpi_driver/parallel/adaptive_study.hpp"
#include "mpi_driver/parallel/checkpoint.hpp"
#include "mpi_driver/parallel/signals.hpp"
#include "mpi_driver/study/failure_report.hpp"
#include "mpi_driver/study/fragility_summary.hpp"

namespace blockfrag {
namespace {

// Rank 0, once every sample is done: the output, the failures' summary, the exit code. For an
// adaptive study, `config` is the grown one and `adaptive` its batches.
int finish_study(const StudyConfig& config, const RunSettings& settings, const RunResult& result,
                 const SceneEvaluator& engine, const AdaptiveRun* adaptive) {
  StudyTallies tallies;
  {
    const std::int64_t capacity = adaptive ? adaptive_capacity(config) : config.total_samples();
    const RecordSpool spool(settings.records, config.hash, capacity, RecordSpool::Mode::resume);
    tallies =
        write_study_output(config.output, config, spool, adaptive ? &adaptive->history : nullptr);
  }
  std::filesystem::remove(settings.checkpoint);
  std::filesystem::remove(settings.records);
  std::cerr << "wrote " << config.output.string() << " (" << result.computed
            << " samples computed in this run, " << result.chunks << " chunks handed out ("
            << result.chunk_samples << " samples), " << result.checkpoints << " checkpoints taking "
            << result.checkpoint_seconds << " s)\n";
  print_fragility_summary(std::cerr, config, tallies.fragility);
  const FailureReport failures = tallies.failures.report(config, engine);
  if (failures.total() > 0) {
    std::cerr << failures.failed << " failed and " << failures.rejected << " rejected of "
              << config.total_samples()
              << " samples (excluded from the fragility trials); the first:\n";
    for (const auto& reason : failures.first_reasons) std::cerr << "  " << reason << '\n';
  }
  if (too_many_failures(config, failures)) {
    std::cerr << "more than allowed_failed_fraction = " << config.allowed_failed_fraction
              << " of the samples gave no verdict: exit code " << exit_code_simulation_failed
              << '\n';
    return exit_code_simulation_failed;
  }
  return exit_code_success;
}

// The study's files sit next to its output; rank 0 alone logs.
RunSettings study_run_settings(const RunOptions& options, const StudyConfig& config, int rank) {
  RunSettings settings;
  settings.checkpoint = checkpoint_path_for(config.output);
  settings.records = record_spool_path_for(config.output);
  settings.checkpoint_interval_s = config.checkpoint_interval_s;
  settings.max_chunk = options.max_chunk;
  settings.checkpoint_hooks = options.checkpoint_hooks;
  settings.log = rank == 0 ? &std::cerr : nullptr;
  settings.log_is_terminal = rank == 0 && ::isatty(STDERR_FILENO);
  return settings;
}

// Rank 0, before the run: the study's size and identity, for the log.
void print_study_plan(const RunOptions& options, const StudyConfig& config, int ranks) {
  const IntensityMeasure& measure = config.intensity;
  std::cerr << "study " << options.study_path.string() << ": " << config.total_samples()
            << " samples (";
  if (measure.surface()) {
    std::cerr << measure.levels.size() << " x " << measure.periods.size() << " cells x ";
  } else {
    std::cerr << measure.level_count() << " levels x ";
  }
  std::cerr << config.samples_per_level << ") on " << ranks << (ranks == 1 ? " rank" : " ranks")
            << ", config hash " << hash_to_hex(config.hash) << '\n';
}

}  // namespace

int run_study_command(const RunOptions& options, const SceneEvaluator& evaluate) {
  // First of all, so that a signal during start-up is a clean interruption too.
  install_interrupt_handlers();
  MpiSession session;
  const MPI_Comm comm = MPI_COMM_WORLD;
  int rank = 0, ranks = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &ranks);

  StudyConfig config;
  try {
    config = read_study_config(options.study_path, {options.output, options.samples_per_level});
  } catch (const InvalidInput& error) {
    return refuse_bad_input(comm, rank, error);
  }

  const RunSettings settings = study_run_settings(options, config, rank);

  const OutputClaim claim =
      claim_output(comm, config.output, config.hash, "study", {settings.checkpoint});
  if (claim.verdict == OutputVerdict::already_complete) {
    if (rank == 0) std::cerr << claim.message << '\n';
    return 0;
  }
  if (claim.verdict == OutputVerdict::refused) {
    return refuse_bad_input(comm, rank, ConfigError({claim.message}));
  }

  const SceneEvaluator engine =
      evaluate ? evaluate : SceneEvaluator([](const Scene& scene) { return simulate(scene); });
  if (rank == 0) print_study_plan(options, config, ranks);
  RunResult result;
  std::optional<AdaptiveRun> adaptive;
  try {
    if (config.adaptive) {
      adaptive = run_adaptive_study(comm, config, settings, engine);
      result = adaptive->result;
    } else {
      result = run_study_samples(comm, config, settings, engine);
    }
  } catch (const StudyMismatchError& error) {
    return refuse_bad_input(comm, rank, ConfigError({error.what()}));
  } catch (const std::exception& error) {
    abort_run(comm, rank, error);
  }

  if (interrupted_on_rank0(comm, result.outcome)) {
    if (rank == 0) {
      std::cerr << "interrupted: checkpoint written to " << settings.checkpoint.string()
                << "; resume with the same command\n";
    }
    return exit_code_interrupted;
  }
  return finish_on_rank0(comm, [&] {
    return finish_study(adaptive ? adaptive->grown : config, settings, result, engine,
                        adaptive ? &*adaptive : nullptr);
  });
}

}  // namespace blockfrag
