#include "mpi_driver/parallel/adaptive_study.hpp"

#include <algorithm>
#include <iomanip>
#include <limits>
#include <ostream>

#include "engine/scene/block_geometry.hpp"
#include "mpi_driver/io/record_spool.hpp"
#include "mpi_driver/study/adaptive_levels.hpp"
#include "mpi_driver/study/limit_states.hpp"
#include "mpi_driver/study/study_sample.hpp"

namespace blockfrag {
namespace {

const LimitState& adaptive_limit_state(const StudyConfig& config) {
  for (const auto& state : config.limit_states) {
    if (state.name == config.adaptive->limit_state) return state;
  }
  throw ContractViolation("the adaptive limit state is not one of the study's");
}

// Rank 0: the adaptive limit state's counts per level, read from the spool a batch at a time (a
// level, once run, never changes), and its fit (without a bootstrap) over every level so far.
class AdaptiveCounts {
 public:
  FragilityCurve add_levels_and_fit(const StudyConfig& grown, const RecordSpool& spool) {
    const LimitState& state = adaptive_limit_state(grown);
    const bool needs_alpha = state.kind == LimitStateKind::max_rotation;
    StudySampler sampler(grown);
    std::vector<SampleRecord> records(static_cast<std::size_t>(grown.samples_per_level));
    for (std::size_t level = trials_.size(); level < grown.intensity.levels.size(); ++level) {
      spool.read(static_cast<std::int64_t>(level) * grown.samples_per_level, records);
      std::int64_t trials = 0, exceedances = 0;
      for (const SampleRecord& record : records) {
        if (record.status != static_cast<std::int64_t>(SampleStatus::ok)) continue;
        const double alpha = needs_alpha ? block_alpha(sampler.draw(record.index).scene) : 0.0;
        ++trials;
        if (exceeds(state, record, alpha)) ++exceedances;
      }
      trials_.push_back(trials);
      exceedances_.push_back(exceedances);
    }
    return fragility_from_counts(grown.intensity.levels, trials_, exceedances_);
  }

 private:
  std::vector<std::int64_t> trials_, exceedances_;
};

// The run's totals over its batches; restored is what the first batch found done, since each later
// batch also finds the batches before it.
void add_batch_totals(const RunResult& batch, bool first, RunResult& sum) {
  if (first) sum.restored = batch.restored;
  sum.computed += batch.computed;
  sum.chunks += batch.chunks;
  sum.chunk_samples += batch.chunk_samples;
  sum.checkpoints += batch.checkpoints;
  sum.checkpoint_seconds += batch.checkpoint_seconds;
}

void log_adaptive_batch(std::ostream& log, std::int64_t batch, const StudyConfig& grown,
                        const FragilityCurve& curve, const BatchDecision& next) {
  log << "batch " << batch << ": " << grown.total_samples() << " samples, median "
      << std::setprecision(4) << curve.median << ", 95 % interval " << std::setprecision(3)
      << 100.0 * next.relative_width << " % of it wide"
      << (next.stop ? "; " + next.reason : std::string()) << '\n';
}

}  // namespace

std::int64_t adaptive_capacity(const StudyConfig& config) {
  const std::int64_t level = config.samples_per_level;
  return config.adaptive->max_samples / level * level;
}

AdaptiveRun run_adaptive_study(MPI_Comm comm, const StudyConfig& config,
                               const RunSettings& settings, const SceneEvaluator& evaluate) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  AdaptiveRun run;
  run.grown = config;
  run.history.level_batch.assign(config.intensity.levels.size(), 0);
  const std::int64_t capacity = adaptive_capacity(config);
  const std::int64_t batch_samples = 2 * static_cast<std::int64_t>(config.samples_per_level);
  const LevelBounds bounds = adaptive_level_bounds(config);
  AdaptiveCounts counts;
  RunResult sum;
  RunSettings batch_settings = settings;
  for (std::int64_t batch = 0;; ++batch) {
    batch_settings.announce_resume = batch == 0;
    StudySampler sampler(run.grown);
    const SampleJob job{
        config.hash, capacity,
        [&](std::int64_t index) { return evaluate_sample(sampler, index, evaluate); },
        run.grown.total_samples()};
    run.result = run_samples(comm, job, batch_settings);
    add_batch_totals(run.result, batch == 0, sum);
    int interrupted = run.result.outcome == RunOutcome::interrupted ? 1 : 0;
    MPI_Bcast(&interrupted, 1, MPI_INT, 0, comm);
    if (interrupted) break;

    // Rank 0 decides; the decision travels as [stop, level, level].
    double decision[3] = {1.0, 0.0, 0.0};
    if (rank == 0) {
      const RecordSpool spool(settings.records, config.hash, capacity, RecordSpool::Mode::resume);
      const FragilityCurve curve = counts.add_levels_and_fit(run.grown, spool);
      const BatchDecision next =
          decide_next_batch(*config.adaptive, curve, run.grown.intensity.levels,
                            run.grown.total_samples(), batch_samples, bounds);
      run.history.samples.push_back(run.grown.total_samples());
      run.history.median.push_back(curve.median);
      run.history.beta.push_back(curve.beta);
      run.history.relative_width.push_back(next.relative_width);
      if (settings.log) log_adaptive_batch(*settings.log, batch, run.grown, curve, next);
      if (next.stop) {
        run.history.stop_reason = next.reason;
      } else {
        decision[0] = 0.0;
        decision[1] = next.next_levels[0];
        decision[2] = next.next_levels[1];
      }
    }
    MPI_Bcast(decision, 3, MPI_DOUBLE, 0, comm);
    if (decision[0] != 0.0) break;
    for (const double level : {decision[1], decision[2]}) {
      run.grown.intensity.levels.push_back(level);
      run.history.level_batch.push_back(batch + 1);
    }
  }
  sum.outcome = run.result.outcome;
  run.result = sum;
  return run;
}

}  // namespace blockfrag
