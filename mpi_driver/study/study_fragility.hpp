// A limit state's fragility from a study's records: per intensity level the trials (samples whose
// simulation succeeded: failed and rejected ones are excluded), the exceedances, the empirical
// probability with its Wilson 95 % interval, and the lognormal maximum-likelihood fit over the
// binomial counts (postproc/).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "mpi_driver/config/study_config.hpp"
#include "mpi_driver/study/study_record.hpp"

namespace blockfrag {

// Whether one successful sample exceeds the limit state; alpha = atan(a / b) of its block.
// An overturned block exceeds every rotation limit (its rotation reached pi/2 and beyond).
bool exceeds(const LimitState& state, const SampleRecord& record, double alpha);

struct FragilityCurve {
  std::vector<double> im;
  std::vector<std::int64_t> trials;
  std::vector<std::int64_t> exceedances;
  std::vector<double> probability;  // exceedances / trials; NaN without trials
  std::vector<double> ci_low;
  std::vector<double> ci_high;
  double median;          // of the lognormal fit; NaN when the fit does not exist
  double beta;
  double log_likelihood;  // binomial log-likelihood at the fit, coefficients included; NaN likewise
  std::string fit_status;  // postproc's FitStatus name: "ok", "no_exceedances", "separated", ...
  double median_low;       // where the data place the median when the fit does not exist
  double median_high;
};

// records[i] and alphas[i] belong to sample i (all samples of the study).
FragilityCurve fragility_curve(const StudyConfig& config, const LimitState& state,
                               const std::vector<SampleRecord>& records, const std::vector<double>& alphas);

}  // namespace blockfrag
