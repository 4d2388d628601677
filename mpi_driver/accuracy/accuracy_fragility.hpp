// What the solver setting does to a fragility curve (issue 5, item 3): a batch study is run in
// process, sample by sample through the batch runner's evaluate_sample, once per solver setting,
// and each limit state's curve is compared with the reference setting's, next to the curve's own
// sampling error (the half-width of its Wilson 95 % intervals). And how fast Monte Carlo and Latin
// hypercube designs converge: the fitted median's error against a large Latin hypercube run.
#pragma once

#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "mpi_driver/accuracy/accuracy_settings.hpp"
#include "mpi_driver/config/study_config.hpp"
#include "mpi_driver/study/limit_states.hpp"

namespace blockfrag {

struct FragilityDifference {
  SolverSetting setting;
  std::string limit_state;
  std::int64_t verdicts_changed = 0;  // samples whose exceedance differs from the reference's
  std::int64_t failures = 0;  // samples that failed (a budget, or over 5 s) with this setting
  double max_probability_difference = 0;    // max over levels of |p - p_reference|
  double max_sampling_half_width = 0;       // max over levels of the reference's Wilson half-width
  double median = 0, reference_median = 0;  // of the lognormal fits (NaN when a fit does not exist)
  double beta = 0, reference_beta = 0;
  double median_seconds = 0;  // per sample, from one pass (not repeated: a rough cost)
};

// The study's curves with each setting against those with `reference`; one row per setting and
// limit state, in that order.
std::vector<FragilityDifference> compare_fragility(const StudyConfig& config,
                                                   const std::vector<SolverSetting>& settings,
                                                   const SolverSetting& reference);

struct DesignConvergence {
  std::string design;  // "monte_carlo" or "latin_hypercube"
  std::int64_t samples_per_level = 0;
  std::string limit_state;
  double rms_relative_median_error = 0;  // over replicates (seeds) whose fit exists
  double rms_beta_error = 0;
  int fitted_replicates = 0;
};

// For each design and size, `replicates` seeds of the study (with the production default); errors
// of the lognormal fit of the first limit state against one Latin hypercube run of
// reference_samples_per_level samples per level.
std::vector<DesignConvergence> design_convergence(const nlohmann::json& study_document,
                                                  const std::vector<std::int64_t>& sizes,
                                                  int replicates,
                                                  std::int64_t reference_samples_per_level);

void write_fragility_table(std::ostream& out, const std::vector<FragilityDifference>& rows);
void write_design_convergence_table(std::ostream& out, const std::vector<DesignConvergence>& rows);

}  // namespace blockfrag
