#include "mpi_driver/parallel/spectrum_runner.hpp"

#include <algorithm>
#include <exception>
#include <functional>
#include <optional>
#include <ostream>

#include "mpi_driver/config/study_hash.hpp"
#include "mpi_driver/io/record_spool.hpp"
#include "mpi_driver/parallel/bisection_state.hpp"
#include "mpi_driver/parallel/checkpoint.hpp"

namespace blockfrag {
namespace {

// Records read from a spool at a time: 64k of them, a few MB.
constexpr std::int64_t kBlock = 1 << 16;
// What a spectrum's hash identifies, in the messages that refuse another spectrum's files.
constexpr const char* kSpectrumSpec = "spectrum spec";
constexpr const char* kSpec = "spec";

// Runs `work` on rank 0 alone; every rank learns whether it failed, and then every rank throws:
// rank 0 its own error (a refused file as StudyMismatchError), the others one of the same kind.
void on_rank0(MPI_Comm comm, const std::function<void()>& work) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  int failure = 0;  // 1: a file that belongs to another spectrum or is damaged; 2: anything else
  std::exception_ptr error;
  std::string refusal;
  if (rank == 0) {
    try {
      work();
    } catch (const InvalidInput& refused) {
      refusal = refused.what();
      failure = 1;
    } catch (const std::exception&) {
      error = std::current_exception();
      failure = 2;
    }
  }
  MPI_Bcast(&failure, 1, MPI_INT, 0, comm);
  if (failure == 1)
    throw StudyMismatchError(rank == 0 ? refusal : "refusing to resume (see rank 0)");
  if (error) std::rethrow_exception(error);
  if (failure == 2) throw FileFailure("the spectrum stopped (see rank 0)");
}

// Calls visit(index, record) for every record of the spool, a block at a time.
void for_each_record(const RecordSpool& spool, std::int64_t total,
                     const std::function<void(std::int64_t, const SampleRecord&)>& visit) {
  std::vector<SampleRecord> records;
  for (std::int64_t first = 0; first < total; first += kBlock) {
    records.resize(static_cast<std::size_t>(std::min(kBlock, total - first)));
    spool.read(first, records);
    for (std::size_t k = 0; k < records.size(); ++k) {
      const std::int64_t index = first + static_cast<std::int64_t>(k);
      if (records[k].index != index) {
        throw ContractViolation("the record spool " + spool.path().string() + " lacks sample " +
                                std::to_string(index));
      }
      visit(index, records[k]);
    }
  }
}

// The brackets of every column of the finished map, in order of frequency, then amplitude.
std::vector<SpectrumBracket> map_brackets(const SpectrumConfig& config, const RecordSpool& spool) {
  const std::size_t na = config.amplitude_ratio.size();
  std::vector<SpectrumBracket> brackets;
  std::vector<SpectrumVerdict> column(na);
  for_each_record(spool, config.map_points(), [&](std::int64_t index, const SampleRecord& record) {
    const auto j = static_cast<std::size_t>(index) % na;
    column[j] = spectrum_verdict(record);
    if (j + 1 < na) return;
    const auto found = column_brackets(index / static_cast<std::int64_t>(na),
                                       config.amplitude_ratio, column, config.bisection_tolerance);
    brackets.insert(brackets.end(), found.begin(), found.end());
  });
  return brackets;
}

std::uint64_t round_hash(std::uint64_t config_hash, std::int64_t round) {
  return fnv1a64(hash_to_hex(config_hash) + " bisection round " + std::to_string(round));
}

// Rank 0, once the map is complete: every point is on disk and the checkpoint says so, so a run
// killed during the bisection never computes the map again.
void seal_map(const SpectrumConfig& config, const RunSettings& settings) {
  RecordSpool spool(settings.records, config.hash, config.map_points(), RecordSpool::Mode::resume);
  spool.sync();
  write_checkpoint(settings.checkpoint,
                   {config.hash, config.map_points(), {{0, config.map_points()}}},
                   settings.checkpoint_hooks);
}

std::int64_t max_brackets_of(const SpectrumConfig& config) {
  return static_cast<std::int64_t>(config.frequency_ratio.size()) *
         static_cast<std::int64_t>(config.amplitude_ratio.size() - 1);
}

// The bisection state at files.bisection, if there is one, checked against this spectrum: a
// damaged file (CheckpointError) or another spectrum's (StudyMismatchError) is refused.
std::optional<BisectionState> read_own_bisection_state(const SpectrumConfig& config,
                                                       const SpectrumFiles& files) {
  auto state = read_bisection_state(files.bisection, max_brackets_of(config),
                                    static_cast<std::int64_t>(config.frequency_ratio.size()));
  if (state && state->config_hash != config.hash) {
    throw StudyMismatchError("refusing to resume: the bisection state " + files.bisection.string() +
                             " belongs to a different spectrum spec (spec hash " +
                             hash_to_hex(state->config_hash) + ", this spec " +
                             hash_to_hex(config.hash) + "); remove it to start the bisection over");
  }
  return state;
}

// Rank 0: the bisection as it stood when the last run stopped, or its start from the map.
BisectionState start_bisection(const SpectrumConfig& config, const RunSettings& settings,
                               const SpectrumFiles& files) {
  if (auto state = read_own_bisection_state(config, files)) return std::move(*state);
  const RecordSpool spool(settings.records, config.hash, config.map_points(),
                          RecordSpool::Mode::resume);
  BisectionState state{config.hash, 0, map_brackets(config, spool)};
  write_bisection_state(files.bisection, state);
  return state;
}

// Rank 0, after a round: each open bracket narrowed by its midpoint's verdict, the round's
// checkpoint removed (so that no checkpoint of a finished round outlives it), the next round's
// state written.
void finish_round(const SpectrumConfig& config, const SpectrumFiles& files, const SampleJob& job,
                  BisectionState& state) {
  const RecordSpool spool(files.round_records, job.hash, job.total, RecordSpool::Mode::resume);
  std::vector<SpectrumBracket*> open;
  for (SpectrumBracket& bracket : state.brackets) {
    if (bracket.is_open()) open.push_back(&bracket);
  }
  if (static_cast<std::int64_t>(open.size()) != job.total)
    throw ContractViolation("a round's midpoints are not its open brackets");
  for_each_record(spool, job.total, [&](std::int64_t k, const SampleRecord& record) {
    narrow(*open[static_cast<std::size_t>(k)], spectrum_verdict(record), config.bisection_tolerance,
           config.max_iterations);
  });
  std::filesystem::remove(files.round_checkpoint);
  ++state.round;
  write_bisection_state(files.bisection, state);
}

// Rank 0, before the map: the bisection's files, checked as the map's are, so that a file the
// spectrum cannot use is refused before hours of map and not after. A round's checkpoint belongs
// to the round the bisection state is at; with no state, no round has started.
void check_bisection_files(const SpectrumConfig& config, const SpectrumFiles& files) {
  const auto state = read_own_bisection_state(config, files);
  const auto round = read_checkpoint(files.round_checkpoint);
  if (round && (!state || round->config_hash != round_hash(config.hash, state->round))) {
    throw StudyMismatchError("refusing to resume: the round checkpoint " +
                             files.round_checkpoint.string() + " (spec hash " +
                             hash_to_hex(round->config_hash) +
                             ") is not of this spectrum's current bisection round; remove it to "
                             "start the round over");
  }
  read_record_spool_hash(files.round_records);
}

}  // namespace

SpectrumFiles SpectrumFiles::for_output(const std::filesystem::path& output) {
  const auto next_to = [&](const char* suffix) {
    auto path = output;
    path += suffix;
    return path;
  };
  return {bisection_state_path_for(output), next_to(".round-checkpoint"),
          next_to(".round-records")};
}

SpectrumRunResult run_spectrum(MPI_Comm comm, const SpectrumConfig& config,
                               const RunSettings& settings, const SpectrumFiles& files,
                               const SceneEvaluator& evaluate) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  SpectrumRunResult result;
  on_rank0(comm, [&] { check_bisection_files(config, files); });
  const auto na = static_cast<std::int64_t>(config.amplitude_ratio.size());
  const SampleJob map_job{
      .hash = config.hash,
      .total = config.map_points(),
      .evaluate =
          [&](std::int64_t index) {
            return evaluate_spectrum_point(
                config, config.frequency_ratio[static_cast<std::size_t>(index / na)],
                config.amplitude_ratio[static_cast<std::size_t>(index % na)], index, evaluate);
          },
      .config_name = kSpectrumSpec,
      .config_word = kSpec};
  result.map = run_samples(comm, map_job, settings);
  if (interrupted_on_rank0(comm, result.map.outcome)) {
    result.outcome = RunOutcome::interrupted;
    return result;
  }

  BisectionState state;
  on_rank0(comm, [&] {
    seal_map(config, settings);
    state = start_bisection(config, settings, files);
  });
  RunSettings round_settings = settings;
  round_settings.checkpoint = files.round_checkpoint;
  round_settings.records = files.round_records;
  round_settings.log = nullptr;
  std::vector<double> points;  // (frequency ratio, amplitude ratio) of each open bracket's midpoint
  for (;;) {
    std::int64_t header[2] = {0, 0};  // the round and its midpoints
    if (rank == 0) {
      points.clear();
      for (const SpectrumBracket& bracket : state.brackets) {
        if (!bracket.is_open()) continue;
        points.push_back(config.frequency_ratio[static_cast<std::size_t>(bracket.frequency_index)]);
        points.push_back(bracket.midpoint());
      }
      header[0] = state.round;
      header[1] = static_cast<std::int64_t>(points.size() / 2);
    }
    MPI_Bcast(header, 2, MPI_INT64_T, 0, comm);
    if (header[1] == 0) break;
    points.resize(static_cast<std::size_t>(2 * header[1]));
    MPI_Bcast(points.data(), static_cast<int>(points.size()), MPI_DOUBLE, 0, comm);
    if (settings.log) {
      *settings.log << "bisection round " << header[0] + 1 << ": " << header[1]
                    << (header[1] == 1 ? " crossing" : " crossings") << " to narrow\n";
    }
    const SampleJob job{.hash = round_hash(config.hash, header[0]),
                        .total = header[1],
                        .evaluate =
                            [&](std::int64_t k) {
                              const auto at = static_cast<std::size_t>(2 * k);
                              return evaluate_spectrum_point(config, points[at], points[at + 1], k,
                                                             evaluate);
                            },
                        .config_name = kSpectrumSpec,
                        .config_word = kSpec};
    const RunResult round = run_samples(comm, job, round_settings);
    result.midpoints += round.computed;
    if (interrupted_on_rank0(comm, round.outcome)) {
      result.outcome = RunOutcome::interrupted;
      return result;
    }
    on_rank0(comm, [&] { finish_round(config, files, job, state); });
    ++result.rounds;
  }
  result.brackets = std::move(state.brackets);
  return result;
}

void remove_spectrum_files(const SpectrumConfig& config, const RunSettings& settings,
                           const SpectrumFiles& files) {
  const auto state = read_own_bisection_state(config, files);
  const auto own_round = [&](std::uint64_t hash) {
    for (std::int64_t round = 0; state && round <= state->round; ++round) {
      if (hash == round_hash(config.hash, round)) return true;
    }
    return false;
  };
  // A file that cannot be read as this spectrum's is someone else's, and stays.
  const auto remove_when_own = [](const std::filesystem::path& path, const auto& read_hash,
                                  const auto& own) {
    try {
      if (const auto hash = read_hash(path); hash && own(*hash)) std::filesystem::remove(path);
    } catch (const InvalidInput&) {
    }
  };
  const auto checkpoint_hash = [](const std::filesystem::path& path) {
    const auto checkpoint = read_checkpoint(path);
    return checkpoint ? std::optional<std::uint64_t>(checkpoint->config_hash) : std::nullopt;
  };
  const auto own_map = [&](std::uint64_t hash) { return hash == config.hash; };
  remove_when_own(settings.checkpoint, checkpoint_hash, own_map);
  remove_when_own(settings.records, read_record_spool_hash, own_map);
  remove_when_own(files.round_checkpoint, checkpoint_hash, own_round);
  remove_when_own(files.round_records, read_record_spool_hash, own_round);
  if (state) std::filesystem::remove(files.bisection);
}

}  // namespace blockfrag
