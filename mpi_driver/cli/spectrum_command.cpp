#include "mpi_driver/cli/spectrum_command.hpp"

#include <unistd.h>

#include <iostream>

#include "engine/simulate.hpp"
#include "mpi_driver/cli/distributed_run.hpp"
#include "mpi_driver/cli/exit_codes.hpp"
#include "mpi_driver/config/config_reader.hpp"
#include "mpi_driver/config/study_hash.hpp"
#include "mpi_driver/io/spectrum_output.hpp"
#include "mpi_driver/parallel/checkpoint.hpp"
#include "mpi_driver/parallel/signals.hpp"
#include "mpi_driver/parallel/spectrum_runner.hpp"

namespace blockfrag {
namespace {

// Rank 0, once the map and the bisections are done: the output, then the run's own files go.
int finish_spectrum(const SpectrumConfig& config, const RunSettings& settings,
                    const SpectrumFiles& files, const SpectrumRunResult& result) {
  SpectrumTally tally;
  {
    const RecordSpool spool(settings.records, config.hash, config.map_points(),
                            RecordSpool::Mode::resume);
    tally = write_spectrum_output(config.output, config, spool, result.brackets, result.minimum);
  }
  remove_spectrum_files(config, settings, files);
  std::cerr << "wrote " << config.output.string() << " (" << result.map.computed
            << " map points and " << result.midpoints << " bisection midpoints and "
            << result.minimum_midpoints << " minimum refinement midpoints computed in this run, "
            << result.rounds << " bisection rounds, " << result.minimum_rounds
            << " minimum refinement rounds, " << result.map.chunks << " map chunks handed out)\n"
            << "  map: " << tally.points << " points, " << tally.overturned << " overturned, "
            << tally.failed << " failed\n"
            << "  boundary: " << tally.onsets << " onsets of overturning and " << tally.island_edges
            << " ends of an overturning band (safe island edges); " << tally.converged << " of "
            << tally.onsets + tally.island_edges << " bisected to the tolerance "
            << config.bisection_tolerance << '\n'
            << "  minimum overturning amplitude: found to the tolerance "
            << config.minimum_overturning.tolerance << " at " << tally.minima_found << " of "
            << config.frequency_ratio.size() << " frequencies, below the map's lowest onset at "
            << tally.minima_lowered << ", below the grid at " << tally.minima_below_grid
            << ", uncertain at " << tally.minima_uncertain << '\n';
  if (tally.failed > 0 || tally.converged < tally.onsets + tally.island_edges ||
      tally.minima_uncertain > 0) {
    std::cerr << "some points gave no verdict or some crossings or minima were not bisected to "
                 "the tolerance (/map/verdict 5 or 6, /boundary/state 2 or 3, "
                 "/minimum_overturning/state 4 or 5): exit code "
              << exit_code_simulation_failed << '\n';
    return exit_code_simulation_failed;
  }
  return exit_code_success;
}

// The spectrum's files sit next to its output; rank 0 alone logs.
RunSettings spectrum_run_settings(const SpectrumOptions& options, const SpectrumConfig& config,
                                  int rank) {
  RunSettings settings;
  settings.checkpoint = checkpoint_path_for(config.output);
  settings.records = record_spool_path_for(config.output);
  settings.checkpoint_interval_s = config.checkpoint_interval_s;
  settings.checkpoint_hooks = options.checkpoint_hooks;
  settings.log = rank == 0 ? &std::cerr : nullptr;
  settings.log_is_terminal = rank == 0 && ::isatty(STDERR_FILENO);
  settings.max_chunk = options.max_chunk;
  return settings;
}

// Rank 0, before the run: the spectrum's grid, block and identity, for the log.
void print_spectrum_plan(const SpectrumOptions& options, const SpectrumConfig& config, int ranks) {
  std::cerr << "spectrum " << options.spectrum_path.string() << ": "
            << spectrum_pulse_name(config.pulse) << ", " << config.map_points() << " map points ("
            << config.frequency_ratio.size() << " frequency ratios x "
            << config.amplitude_ratio.size() << " amplitude ratios), alpha = " << config.alpha()
            << " rad, p = " << config.p() << " rad/s, on " << ranks
            << (ranks == 1 ? " rank" : " ranks") << ", config hash " << hash_to_hex(config.hash)
            << '\n';
}

}  // namespace

int run_spectrum_command(const SpectrumOptions& options, const SceneEvaluator& evaluate) {
  install_interrupt_handlers();
  MpiSession session;
  const MPI_Comm comm = MPI_COMM_WORLD;
  int rank = 0, ranks = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &ranks);

  SpectrumConfig config;
  try {
    config = read_spectrum_config(options.spectrum_path, options.output);
  } catch (const InvalidInput& error) {
    return refuse_bad_input(comm, rank, error);
  }

  const RunSettings settings = spectrum_run_settings(options, config, rank);
  const SpectrumFiles files = SpectrumFiles::for_output(config.output);

  const OutputClaim claim =
      claim_output(comm, config.output, config.hash, "spectrum",
                   {settings.checkpoint, files.bisection, files.minimum, files.round_checkpoint});
  if (claim.verdict == OutputVerdict::already_complete) {
    if (rank == 0) std::cerr << claim.message << '\n';
    return exit_code_success;
  }
  if (claim.verdict == OutputVerdict::refused) {
    return refuse_bad_input(comm, rank, ConfigError({claim.message}));
  }

  const SceneEvaluator engine =
      evaluate ? evaluate : SceneEvaluator([](const Scene& scene) { return simulate(scene); });
  if (rank == 0) print_spectrum_plan(options, config, ranks);
  SpectrumRunResult result;
  try {
    result = run_spectrum(comm, config, settings, files, engine);
  } catch (const StudyMismatchError& error) {
    return refuse_bad_input(comm, rank, ConfigError({error.what()}));
  } catch (const std::exception& error) {
    abort_run(comm, rank, error);
  }
  if (result.outcome == RunOutcome::interrupted) {
    if (rank == 0) {
      std::cerr << "interrupted: checkpoint written next to " << config.output.string()
                << "; resume with the same command\n";
    }
    return exit_code_interrupted;
  }
  return finish_on_rank0(comm, [&] { return finish_spectrum(config, settings, files, result); });
}

}  // namespace blockfrag
