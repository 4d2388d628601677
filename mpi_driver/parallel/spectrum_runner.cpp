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
#include "mpi_driver/parallel/minimum_refinement_state.hpp"

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

// Calls visit(frequency index, column) for every column of the finished map, in order.
void for_each_column(
    const SpectrumConfig& config, const RecordSpool& spool,
    const std::function<void(std::int64_t, const std::vector<SampleRecord>&)>& visit) {
  const std::size_t na = config.amplitude_ratio.size();
  std::vector<SampleRecord> column(na);
  for_each_record(spool, config.map_points(), [&](std::int64_t index, const SampleRecord& record) {
    const auto j = static_cast<std::size_t>(index) % na;
    column[j] = record;
    if (j + 1 == na) visit(index / static_cast<std::int64_t>(na), column);
  });
}

// The brackets of every column of the finished map, in order of frequency, then amplitude.
std::vector<SpectrumBracket> map_brackets(const SpectrumConfig& config, const RecordSpool& spool) {
  std::vector<SpectrumBracket> brackets;
  std::vector<SpectrumVerdict> verdicts;
  for_each_column(config, spool, [&](std::int64_t i, const std::vector<SampleRecord>& column) {
    verdicts.clear();
    for (const SampleRecord& record : column) verdicts.push_back(spectrum_verdict(record));
    const auto found =
        column_brackets(i, config.amplitude_ratio, verdicts, config.bisection_tolerance);
    brackets.insert(brackets.end(), found.begin(), found.end());
  });
  return brackets;
}

std::uint64_t round_hash(std::uint64_t config_hash, std::int64_t round) {
  return fnv1a64(hash_to_hex(config_hash) + " bisection round " + std::to_string(round));
}
std::uint64_t minimum_round_hash(std::uint64_t config_hash, std::int64_t round) {
  return fnv1a64(hash_to_hex(config_hash) + " minimum round " + std::to_string(round));
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

// At most: a probe for every map interval, and two segments for every midpoint the refinement may
// evaluate (kMaxSpectrumPoints over the whole spectrum).
std::int64_t max_segments_of(const SpectrumConfig& config) {
  return config.map_points() + 2 * kMaxSpectrumPoints;
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

// The minimum refinement at files.minimum, if there is one, checked as the bisection state is.
std::optional<MinimumRefinement> read_own_minimum(const SpectrumConfig& config,
                                                  const SpectrumFiles& files) {
  auto refinement =
      read_minimum_refinement(files.minimum, max_segments_of(config),
                              static_cast<std::int64_t>(config.frequency_ratio.size()));
  if (refinement && refinement->config_hash != config.hash) {
    throw StudyMismatchError(
        "refusing to resume: the minimum refinement " + files.minimum.string() +
        " belongs to a different spectrum spec (spec hash " + hash_to_hex(refinement->config_hash) +
        ", this spec " + hash_to_hex(config.hash) + "); remove it to start the refinement over");
  }
  return refinement;
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

// Rank 0, once every bracket is closed: the minimum refinement as it stood when the last run
// stopped, or its start from the map's columns and their bisected crossings.
MinimumRefinement start_minimum(const SpectrumConfig& config, const RunSettings& settings,
                                const SpectrumFiles& files,
                                const std::vector<SpectrumBracket>& brackets) {
  if (auto refinement = read_own_minimum(config, files)) return std::move(*refinement);
  const RecordSpool spool(settings.records, config.hash, config.map_points(),
                          RecordSpool::Mode::resume);
  std::vector<MinimumSegment> segments;
  std::vector<MinimumPoint> points;
  auto bracket = brackets.begin();
  for_each_column(config, spool, [&](std::int64_t i, const std::vector<SampleRecord>& column) {
    points.clear();
    for (const SampleRecord& record : column)
      points.push_back(minimum_point(record, config.alpha()));
    const auto first = bracket;
    while (bracket != brackets.end() && bracket->frequency_index == i) ++bracket;
    const auto found = column_segments(i, config.amplitude_ratio, points,
                                       std::span<const SpectrumBracket>(first, bracket),
                                       config.minimum_overturning);
    segments.insert(segments.end(), found.begin(), found.end());
  });
  MinimumRefinement refinement = start_minimum_refinement(
      config.hash, static_cast<std::int64_t>(config.frequency_ratio.size()), std::move(segments),
      config.minimum_overturning);
  write_minimum_refinement(files.minimum, refinement);
  return refinement;
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

// Rank 0, after a minimum round: the segments refined by their midpoints' points, then as
// finish_round.
void finish_minimum_round(const SpectrumConfig& config, const SpectrumFiles& files,
                          const SampleJob& job, MinimumRefinement& refinement) {
  const RecordSpool spool(files.round_records, job.hash, job.total, RecordSpool::Mode::resume);
  std::vector<MinimumPoint> points;
  points.reserve(static_cast<std::size_t>(job.total));
  for_each_record(spool, job.total, [&](std::int64_t, const SampleRecord& record) {
    points.push_back(minimum_point(record, config.alpha()));
  });
  refine_minimum(refinement, points, config.minimum_overturning);
  std::filesystem::remove(files.round_checkpoint);
  write_minimum_refinement(files.minimum, refinement);
}

// What a phase of rounds does on rank 0, for run_rounds.
struct RoundPhase {
  // The current round, and the (frequency ratio, amplitude ratio) pairs of its points.
  std::function<std::int64_t(std::vector<double>& points)> next;
  std::function<std::uint64_t(std::int64_t round)> hash;
  std::function<void(const SampleJob& job)> finish;
  const char* name;   // "bisection round"
  const char* one;    // "crossing"
  const char* many;   // "crossings"
  const char* doing;  // "to narrow"
};

struct RoundsRun {
  RunOutcome outcome = RunOutcome::completed;
  std::int64_t rounds = 0, midpoints = 0;
};

// Collective: the phase's rounds, each one job of the study runner in the round files, until
// rank 0 has no point left.
RoundsRun run_rounds(MPI_Comm comm, const SpectrumConfig& config, const RunSettings& settings,
                     const SpectrumFiles& files, const SceneEvaluator& evaluate,
                     const RoundPhase& phase) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  RunSettings round_settings = settings;
  round_settings.checkpoint = files.round_checkpoint;
  round_settings.records = files.round_records;
  round_settings.log = nullptr;
  RoundsRun run;
  std::vector<double> points;  // (frequency ratio, amplitude ratio) of each point
  for (;;) {
    std::int64_t header[2] = {0, 0};  // the round and its points
    if (rank == 0) {
      points.clear();
      header[0] = phase.next(points);
      header[1] = static_cast<std::int64_t>(points.size() / 2);
    }
    MPI_Bcast(header, 2, MPI_INT64_T, 0, comm);
    if (header[1] == 0) return run;
    points.resize(static_cast<std::size_t>(2 * header[1]));
    MPI_Bcast(points.data(), static_cast<int>(points.size()), MPI_DOUBLE, 0, comm);
    if (settings.log) {
      *settings.log << phase.name << ' ' << header[0] + 1 << ": " << header[1] << ' '
                    << (header[1] == 1 ? phase.one : phase.many) << ' ' << phase.doing << '\n';
    }
    const SampleJob job{.hash = phase.hash(header[0]),
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
    run.midpoints += round.computed;
    if (interrupted_on_rank0(comm, round.outcome)) {
      run.outcome = RunOutcome::interrupted;
      return run;
    }
    on_rank0(comm, [&] { phase.finish(job); });
    ++run.rounds;
  }
}

// Rank 0, before the map: the rounds' files, checked as the map's are, so that a file the spectrum
// cannot use is refused before hours of map and not after. A round's checkpoint belongs to the
// round the phase in progress is at: the minimum's once it has started, else the bisection's;
// with neither state, no round has started.
void check_round_files(const SpectrumConfig& config, const SpectrumFiles& files) {
  const auto state = read_own_bisection_state(config, files);
  const auto minimum = read_own_minimum(config, files);
  const auto round = read_checkpoint(files.round_checkpoint);
  const std::optional<std::uint64_t> current =
      minimum ? std::optional(minimum_round_hash(config.hash, minimum->round))
      : state ? std::optional(round_hash(config.hash, state->round))
              : std::nullopt;
  if (round && round->config_hash != current) {
    throw StudyMismatchError("refusing to resume: the round checkpoint " +
                             files.round_checkpoint.string() + " (spec hash " +
                             hash_to_hex(round->config_hash) +
                             ") is not of this spectrum's current round; remove it to start the "
                             "round over");
  }
  read_record_spool_hash(files.round_records);
}

// Collective: every map point, one job of the study runner in the map's files.
RunResult run_spectrum_map(MPI_Comm comm, const SpectrumConfig& config, const RunSettings& settings,
                           const SceneEvaluator& evaluate) {
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
  return run_samples(comm, map_job, settings);
}

// Collective: the bisection's rounds, each the midpoints of the crossings still open on rank 0.
RoundsRun run_bisection_rounds(MPI_Comm comm, const SpectrumConfig& config,
                               const RunSettings& settings, const SpectrumFiles& files,
                               const SceneEvaluator& evaluate, BisectionState& state) {
  const RoundPhase bisection{
      .next =
          [&](std::vector<double>& points) {
            for (const SpectrumBracket& bracket : state.brackets) {
              if (!bracket.is_open()) continue;
              points.push_back(
                  config.frequency_ratio[static_cast<std::size_t>(bracket.frequency_index)]);
              points.push_back(bracket.midpoint());
            }
            return state.round;
          },
      .hash = [&](std::int64_t round) { return round_hash(config.hash, round); },
      .finish = [&](const SampleJob& job) { finish_round(config, files, job, state); },
      .name = "bisection round",
      .one = "crossing",
      .many = "crossings",
      .doing = "to narrow"};
  return run_rounds(comm, config, settings, files, evaluate, bisection);
}

// Collective: the minimum's rounds, each the midpoints of the segments still open on rank 0.
RoundsRun run_minimum_rounds(MPI_Comm comm, const SpectrumConfig& config,
                             const RunSettings& settings, const SpectrumFiles& files,
                             const SceneEvaluator& evaluate, MinimumRefinement& minimum) {
  const RoundPhase refinement{
      .next =
          [&](std::vector<double>& points) {
            for (const MinimumSegment& segment : minimum.segments) {
              if (!segment.is_open()) continue;
              points.push_back(
                  config.frequency_ratio[static_cast<std::size_t>(segment.frequency_index)]);
              points.push_back(segment.midpoint());
            }
            return minimum.round;
          },
      .hash = [&](std::int64_t round) { return minimum_round_hash(config.hash, round); },
      .finish = [&](const SampleJob& job) { finish_minimum_round(config, files, job, minimum); },
      .name = "minimum refinement round",
      .one = "amplitude",
      .many = "amplitudes",
      .doing = "to probe"};
  return run_rounds(comm, config, settings, files, evaluate, refinement);
}

}  // namespace

SpectrumFiles SpectrumFiles::for_output(const std::filesystem::path& output) {
  const auto next_to = [&](const char* suffix) {
    auto path = output;
    path += suffix;
    return path;
  };
  return {bisection_state_path_for(output), minimum_refinement_path_for(output),
          next_to(".round-checkpoint"), next_to(".round-records")};
}

SpectrumRunResult run_spectrum(MPI_Comm comm, const SpectrumConfig& config,
                               const RunSettings& settings, const SpectrumFiles& files,
                               const SceneEvaluator& evaluate) {
  SpectrumRunResult result;
  on_rank0(comm, [&] { check_round_files(config, files); });
  result.map = run_spectrum_map(comm, config, settings, evaluate);
  if (interrupted_on_rank0(comm, result.map.outcome)) {
    result.outcome = RunOutcome::interrupted;
    return result;
  }

  BisectionState state;
  on_rank0(comm, [&] {
    seal_map(config, settings);
    state = start_bisection(config, settings, files);
  });
  const RoundsRun narrowed = run_bisection_rounds(comm, config, settings, files, evaluate, state);
  result.rounds = narrowed.rounds;
  result.midpoints = narrowed.midpoints;
  if (narrowed.outcome == RunOutcome::interrupted) {
    result.outcome = RunOutcome::interrupted;
    return result;
  }

  MinimumRefinement minimum;
  on_rank0(comm, [&] { minimum = start_minimum(config, settings, files, state.brackets); });
  const RoundsRun refined = run_minimum_rounds(comm, config, settings, files, evaluate, minimum);
  result.minimum_rounds = refined.rounds;
  result.minimum_midpoints = refined.midpoints;
  if (refined.outcome == RunOutcome::interrupted) {
    result.outcome = RunOutcome::interrupted;
    return result;
  }
  result.brackets = std::move(state.brackets);
  result.minimum = std::move(minimum);
  return result;
}

void remove_spectrum_files(const SpectrumConfig& config, const RunSettings& settings,
                           const SpectrumFiles& files) {
  const auto state = read_own_bisection_state(config, files);
  const auto minimum = read_own_minimum(config, files);
  const auto own_round = [&](std::uint64_t hash) {
    for (std::int64_t round = 0; state && round <= state->round; ++round) {
      if (hash == round_hash(config.hash, round)) return true;
    }
    for (std::int64_t round = 0; minimum && round <= minimum->round; ++round) {
      if (hash == minimum_round_hash(config.hash, round)) return true;
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
  if (minimum) std::filesystem::remove(files.minimum);
}

}  // namespace blockfrag
