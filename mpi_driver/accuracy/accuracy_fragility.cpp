#include "mpi_driver/accuracy/accuracy_fragility.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "engine/scene/block_geometry.hpp"
#include "engine/simulate.hpp"
#include "mpi_driver/accuracy/accuracy_metrics.hpp"
#include "mpi_driver/accuracy/table_cell.hpp"
#include "mpi_driver/study/sample_evaluation.hpp"
#include "mpi_driver/study/study_sample.hpp"
#include "postproc/fragility/sample_quantile.hpp"

namespace blockfrag {

namespace {

struct StudyResults {
  std::vector<SampleRecord> records;
  std::vector<double> alphas;
  double median_seconds = 0;
};

StudyResults run_in_process(const StudyConfig& config, const SceneEvaluator& evaluate) {
  StudyResults results;
  StudySampler sampler(config);
  StudySampler geometry(config);
  std::vector<double> seconds;
  for (std::int64_t i = 0; i < config.total_samples(); ++i) {
    const auto start = std::chrono::steady_clock::now();
    results.records.push_back(evaluate_sample(sampler, i, evaluate));
    seconds.push_back(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    const Scene scene = geometry.draw(i).scene;
    results.alphas.push_back(block_alpha(scene));
  }
  results.median_seconds = sample_quantile(seconds, 0.5);
  return results;
}

// A sample that needs more steps than this fails (and is excluded from the trials) instead of
// holding up the comparison: a rough study must not wait on one pathological sample.
constexpr long kSampleStepBudget = 5'000'000;

SceneEvaluator evaluator_for(const SolverSetting& setting) {
  return [setting](const Scene& scene) {
    Scene with = scene;
    with.solver = with_setting(with.solver, setting);
    with.solver.max_steps = std::min(with.solver.max_steps, kSampleStepBudget);
    return simulate(with);
  };
}

bool exceeds_at(const LimitState& state, const StudyResults& results, std::size_t i) {
  const SampleRecord& record = results.records[i];
  return record.status == static_cast<std::int64_t>(SampleStatus::ok) &&
         exceeds(state, record, results.alphas[i]);
}

double root_mean_square(const std::vector<double>& values) {
  double sum = 0;
  for (double v : values) sum += v * v;
  return values.empty() ? NAN : std::sqrt(sum / static_cast<double>(values.size()));
}

}  // namespace

std::vector<FragilityDifference> compare_fragility(const StudyConfig& config,
                                                   const std::vector<SolverSetting>& settings,
                                                   const SolverSetting& reference) {
  const StudyResults reference_results = run_in_process(config, evaluator_for(reference));
  std::vector<FragilityDifference> rows;
  for (const SolverSetting& setting : settings) {
    const StudyResults results = run_in_process(config, evaluator_for(setting));
    for (const LimitState& state : config.limit_states) {
      const FragilityCurve ref =
          fragility_curve(config, state, reference_results.records, reference_results.alphas);
      const FragilityCurve curve = fragility_curve(config, state, results.records, results.alphas);
      FragilityDifference row{setting, state.name};
      for (const SampleRecord& record : results.records) {
        row.failures += record.status != static_cast<std::int64_t>(SampleStatus::ok) ? 1 : 0;
      }
      for (std::size_t i = 0; i < results.records.size(); ++i) {
        row.verdicts_changed +=
            exceeds_at(state, results, i) != exceeds_at(state, reference_results, i) ? 1 : 0;
      }
      for (std::size_t level = 0; level < ref.probability.size(); ++level) {
        if (ref.trials[level] == 0 || curve.trials[level] == 0) continue;
        row.max_probability_difference =
            std::max(row.max_probability_difference,
                     std::abs(curve.probability[level] - ref.probability[level]));
        const double half_width = (ref.ci_high[level] - ref.ci_low[level]) / 2;
        row.max_sampling_half_width = std::max(row.max_sampling_half_width, half_width);
      }
      row.median = curve.median;
      row.reference_median = ref.median;
      row.beta = curve.beta;
      row.reference_beta = ref.beta;
      row.median_seconds = results.median_seconds;
      rows.push_back(row);
    }
  }
  return rows;
}

std::vector<DesignConvergence> design_convergence(const nlohmann::json& study_document,
                                                  const std::vector<std::int64_t>& sizes,
                                                  int replicates,
                                                  std::int64_t reference_samples_per_level) {
  const auto configured = [&](const char* design, std::int64_t size, std::uint64_t seed) {
    nlohmann::json document = study_document;
    document["design"] = design;
    document["samples_per_level"] = size;
    document["seed"] = seed;
    return parse_study_config(document, "design convergence");
  };
  const SceneEvaluator evaluate = evaluator_for(default_setting());
  const StudyConfig reference_config =
      configured("latin_hypercube", reference_samples_per_level, 1);
  const LimitState& state = reference_config.limit_states.front();
  const StudyResults reference_results = run_in_process(reference_config, evaluate);
  const FragilityCurve reference =
      fragility_curve(reference_config, state, reference_results.records, reference_results.alphas);

  std::vector<DesignConvergence> rows;
  for (const char* design : {"monte_carlo", "latin_hypercube"}) {
    for (std::int64_t size : sizes) {
      std::vector<double> median_errors, beta_errors;
      for (int replicate = 0; replicate < replicates; ++replicate) {
        // Seeds far from the reference's, so no replicate reuses its streams.
        const StudyConfig config =
            configured(design, size, 1000 + static_cast<std::uint64_t>(replicate));
        const StudyResults results = run_in_process(config, evaluate);
        const FragilityCurve curve =
            fragility_curve(config, config.limit_states.front(), results.records, results.alphas);
        if (!std::isfinite(curve.median) || !std::isfinite(reference.median)) continue;
        median_errors.push_back(curve.median / reference.median - 1);
        beta_errors.push_back(curve.beta - reference.beta);
      }
      rows.push_back({design, size, state.name, root_mean_square(median_errors),
                      root_mean_square(beta_errors), static_cast<int>(median_errors.size())});
    }
  }
  return rows;
}

void write_fragility_table(std::ostream& out, const std::vector<FragilityDifference>& rows) {
  out << "| setting | limit state | failed samples | samples with another verdict | max \\|P - "
         "P_ref\\| over levels "
         "| max Wilson 95 % half-width (sampling error) | fitted median (ref) | fitted beta (ref) "
         "| median time/sample (ms) |\n"
      << "|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& row : rows) {
    out << "| " << setting_label(row.setting) << " | " << row.limit_state << " | " << row.failures
        << " | " << row.verdicts_changed << " | "
        << table_cell(row.max_probability_difference, "%.3g") << " | "
        << table_cell(row.max_sampling_half_width, "%.3g") << " | "
        << table_cell(row.median, "%.5g") << " (" << table_cell(row.reference_median, "%.5g")
        << ") | " << table_cell(row.beta, "%.4g") << " (" << table_cell(row.reference_beta, "%.4g")
        << ") | " << table_cell(1e3 * row.median_seconds, "%.3g") << " |\n";
  }
}

void write_design_convergence_table(std::ostream& out, const std::vector<DesignConvergence>& rows) {
  out << "| design | samples per level | limit state | RMS relative error of the fitted median "
         "| RMS error of beta | replicates with a fit |\n"
      << "|---|---|---|---|---|---|\n";
  for (const auto& row : rows) {
    out << "| " << row.design << " | " << row.samples_per_level << " | " << row.limit_state << " | "
        << table_cell(row.rms_relative_median_error, "%.3g") << " | "
        << table_cell(row.rms_beta_error, "%.3g") << " | " << row.fitted_replicates << " |\n";
  }
}

}  // namespace blockfrag
