#include "mpi_driver/cli/run_command.hpp"

#include <unistd.h>

#include <cstdlib>
#include <exception>
#include <iostream>
#include <memory>
#include <optional>

#include <CLI/CLI.hpp>

#include "engine/simulate.hpp"
#include "mpi_driver/config/config_reader.hpp"
#include "mpi_driver/config/study_hash.hpp"
#include "mpi_driver/io/atomic_file.hpp"
#include "mpi_driver/io/record_spool.hpp"
#include "mpi_driver/io/study_output.hpp"
#include "mpi_driver/parallel/adaptive_study.hpp"
#include "mpi_driver/parallel/checkpoint.hpp"
#include "mpi_driver/parallel/progress.hpp"
#include "mpi_driver/parallel/signals.hpp"
#include "mpi_driver/parallel/study_lock.hpp"
#include "mpi_driver/study/failure_report.hpp"
#include "mpi_driver/study/fragility_summary.hpp"

namespace blockfrag {
namespace {

// MPI_Init in the constructor, MPI_Finalize in the destructor, so every return and every exception
// leaves MPI finalised.
class MpiSession {
 public:
  MpiSession() {
    int initialized = 0;
    MPI_Initialized(&initialized);
    if (!initialized) {
      MPI_Init(nullptr, nullptr);
      owner_ = true;
    }
  }
  ~MpiSession() {
    if (owner_) MPI_Finalize();
  }
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

 private:
  bool owner_ = false;
};

double checkpoint_pause_from_environment() {
  const char* text = std::getenv("BLOCKFRAG_TEST_CHECKPOINT_PAUSE_S");
  return text ? std::strtod(text, nullptr) : 0.0;
}

enum class Verdict : int { run = 0, already_complete = 1, refused = 2 };

// Rank 0 looks at the output before any work: a folder it can write in, no link at its name
// (unless the link leads to this study's finished output), and no file there that belongs to
// anything but this study. A finished output of this study means there is nothing to do. Whatever
// checkpoint lies beside it, another study's output is never replaced.
Verdict judge_existing_output(const StudyConfig& config, std::string& message) {
  const std::string output = config.output.string();
  if (const auto problem = folder_write_problem(config.output)) {
    message = output + ": " + *problem;
    return Verdict::refused;
  }
  std::error_code error;
  const auto status = std::filesystem::symlink_status(config.output, error);
  if (!std::filesystem::exists(status)) return Verdict::run;
  const bool link = std::filesystem::is_symlink(status);
  if (!link && !std::filesystem::is_regular_file(status)) {
    message = output +
              ": refusing to replace something that is not a regular file; choose another --output";
    return Verdict::refused;
  }
  const std::string hash = output_config_hash(config.output);
  if (hash == hash_to_hex(config.hash)) {
    message = "study already complete: " + output + " (config hash " + hash + ")";
    return Verdict::already_complete;
  }
  if (link) {
    message = output + ": is a symbolic link" +
              (hash.empty() ? std::string(" that does not lead to a blockfrag study output")
                            : " to another study's output (config hash " + hash + ")") +
              "; blockfrag replaces only its own files: remove the link or choose another --output";
    return Verdict::refused;
  }
  message =
      output + ": refusing to replace an existing file that is not this study's output" +
      (hash.empty() ? std::string(" (not a blockfrag study output)")
                    : " (config hash " + hash + ", this config " + hash_to_hex(config.hash) + ")") +
      "; remove it or choose another --output";
  return Verdict::refused;
}

// The exit code for an error of this kind (mpi_driver/cli/exit_codes.hpp).
int exit_code_for(const std::exception& error) {
  if (dynamic_cast<const InvalidInput*>(&error)) return exit_code_bad_input;
  if (dynamic_cast<const ContractViolation*>(&error)) return exit_code_internal_error;
  return exit_code_file_failure;
}

// Any error inside the distributed run leaves other ranks waiting on messages: abort them all,
// with the exit code of the error's kind.
[[noreturn]] void abort_run(MPI_Comm comm, int rank, const std::exception& error) {
  const bool bug = dynamic_cast<const ContractViolation*>(&error) != nullptr;
  std::cerr << "blockfrag: rank " << rank << ": "
            << (bug ? "internal error (a bug, please report it with the input): " : "")
            << error.what() << '\n'
            << std::flush;
  MPI_Abort(comm, exit_code_for(error));
  std::abort();
}

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
            << " samples computed in this run, " << result.chunks << " chunks handed out, "
            << result.checkpoints << " checkpoints taking " << result.checkpoint_seconds << " s)\n";
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
  } catch (const InvalidInput&) {
    if (rank == 0) throw;
    return exit_code_bad_input;
  }

  RunSettings settings;
  settings.checkpoint = checkpoint_path_for(config.output);
  settings.records = record_spool_path_for(config.output);
  settings.checkpoint_interval_s = config.checkpoint_interval_s;
  settings.max_chunk = options.max_chunk;
  settings.checkpoint_hooks.pause_before_rename_s = checkpoint_pause_from_environment();
  settings.log = rank == 0 ? &std::cerr : nullptr;
  settings.log_is_terminal = rank == 0 && ::isatty(STDERR_FILENO);

  std::string message;
  int verdict = static_cast<int>(Verdict::run);
  std::optional<StudyLock> lock;
  if (rank == 0) {
    verdict = static_cast<int>(judge_existing_output(config, message));
    if (verdict == static_cast<int>(Verdict::run)) {
      lock.emplace(config.output);
      if (lock->busy()) {
        message = config.output.string() + ": another run of this study is in progress (it holds " +
                  lock->path().string() + "); wait for it to end, or stop it first";
        verdict = static_cast<int>(Verdict::refused);
      } else if (!lock->held()) {
        message = config.output.string() + ": the lock file " + lock->path().string() + " " +
                  lock->problem();
        verdict = static_cast<int>(Verdict::refused);
      } else {
        // Holding the lock, no other writer of these files runs: a killed one's leftovers can go.
        remove_stale_temporaries(config.output);
        remove_stale_temporaries(settings.checkpoint);
      }
    }
  }
  MPI_Bcast(&verdict, 1, MPI_INT, 0, comm);
  if (verdict == static_cast<int>(Verdict::already_complete)) {
    if (rank == 0) std::cerr << message << '\n';
    return 0;
  }
  if (verdict == static_cast<int>(Verdict::refused)) {
    if (rank == 0) throw ConfigError({message});
    return exit_code_bad_input;
  }

  const SceneEvaluator engine =
      evaluate ? evaluate : SceneEvaluator([](const Scene& scene) { return simulate(scene); });
  if (rank == 0) {
    std::cerr << "study " << options.study_path.string() << ": " << config.total_samples()
              << " samples (" << config.intensity.level_count() << " levels x "
              << config.samples_per_level << ") on " << ranks << (ranks == 1 ? " rank" : " ranks")
              << ", config hash " << hash_to_hex(config.hash) << '\n';
  }
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
    if (rank == 0) throw ConfigError({error.what()});
    return exit_code_bad_input;
  } catch (const std::exception& error) {
    abort_run(comm, rank, error);
  }

  int outcome = static_cast<int>(result.outcome);
  MPI_Bcast(&outcome, 1, MPI_INT, 0, comm);
  if (outcome == static_cast<int>(RunOutcome::interrupted)) {
    if (rank == 0) {
      std::cerr << "interrupted: checkpoint written to " << settings.checkpoint.string()
                << "; resume with the same command\n";
    }
    return exit_code_interrupted;
  }
  // Rank 0 finishes alone; whatever happens there, every rank learns its exit code (a rank left
  // waiting on the broadcast would hang the job), then rank 0 reports an error the usual way.
  int exit_code = exit_code_success;
  std::exception_ptr failure;
  if (rank == 0) {
    try {
      exit_code = finish_study(adaptive ? adaptive->grown : config, settings, result, engine,
                               adaptive ? &*adaptive : nullptr);
    } catch (const std::exception& error) {
      failure = std::current_exception();
      exit_code = exit_code_for(error);
    }
  }
  MPI_Bcast(&exit_code, 1, MPI_INT, 0, comm);
  if (failure) std::rethrow_exception(failure);
  return exit_code;
}

void add_run_command(CLI::App& app, std::function<int()>& command) {
  auto options = std::make_shared<RunOptions>();
  CLI::App* run = app.add_subcommand("run", "Run a batch study (under mpirun for several ranks)");
  run->add_option("study", options->study_path, "Study config (JSON)")
      ->required()
      ->check(CLI::ExistingFile);
  run->add_option("--output", options->output,
                  "Output HDF5 file (replaces the config's \"output\")");
  run->add_option("--samples-per-level", options->samples_per_level,
                  "Samples per intensity level (replaces the config's \"samples_per_level\")")
      ->check(CLI::PositiveNumber);
  run->add_option("--max-chunk", options->max_chunk,
                  "Largest number of samples a worker gets per request (default: adapted to the "
                  "measured speed; results never depend on it)")
      ->check(CLI::Range(1, 1 << 20));
  run->callback(
      [options, &command] { command = [options] { return run_study_command(*options); }; });
}

}  // namespace blockfrag
