#include "mpi_driver/accuracy/accuracy_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numeric>

#include "postproc/fragility/sample_quantile.hpp"

namespace blockfrag {

namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();

double time_error(const std::optional<double>& reference, const std::optional<double>& candidate) {
  if (reference.has_value() != candidate.has_value()) return infinity;
  return reference ? std::abs(*reference - *candidate) : 0.0;
}

template <class T>
std::vector<double> as_doubles(const std::vector<T>& values) {
  return {values.begin(), values.end()};
}

// The values of one output over the scenes.
std::vector<double> column(const std::vector<OutputErrors>& errors, double OutputErrors::*output) {
  std::vector<double> values;
  values.reserve(errors.size());
  for (const auto& e : errors) values.push_back(e.*output);
  return values;
}

}  // namespace

OutputErrors output_errors(const Summary& reference, const Summary& candidate) {
  OutputErrors errors;
  if (candidate.status != Status::ok) {
    errors = {infinity, infinity, infinity, infinity, true, true};
    return errors;
  }
  errors.max_abs_theta = std::abs(candidate.max_abs_theta - reference.max_abs_theta);
  errors.final_theta = std::abs(candidate.final_theta - reference.final_theta);
  errors.final_slide = std::abs(candidate.final_slide - reference.final_slide);
  errors.first_impact_time = time_error(reference.first_impact_time, candidate.first_impact_time);
  errors.wrong_verdict = candidate.overturned != reference.overturned;
  return errors;
}

SettingStatistics setting_statistics(const std::vector<OutputErrors>& errors,
                                     const std::vector<double>& seconds,
                                     const std::vector<long>& rhs_evaluations,
                                     const std::vector<long>& steps) {
  SettingStatistics stats;
  for (double OutputErrors::*output :
       {&OutputErrors::max_abs_theta, &OutputErrors::final_theta, &OutputErrors::final_slide,
        &OutputErrors::first_impact_time}) {
    const auto values = column(errors, output);
    stats.max_error.*output =
        values.empty() ? 0.0 : *std::max_element(values.begin(), values.end());
    stats.median_error.*output = sample_quantile(values, 0.5);
  }
  for (const auto& e : errors) {
    stats.wrong_verdicts += e.wrong_verdict ? 1 : 0;
    stats.failures += e.failed ? 1 : 0;
    stats.scenes_over_target += e.max_abs_theta > max_abs_theta_target ? 1 : 0;
  }
  stats.max_error.wrong_verdict = stats.wrong_verdicts > 0;
  stats.max_error.failed = stats.failures > 0;
  stats.wrong_verdict_rate = errors.empty() ? 0.0
                                            : static_cast<double>(stats.wrong_verdicts) /
                                                  static_cast<double>(errors.size());
  stats.median_seconds = sample_quantile(seconds, 0.5);
  stats.p95_seconds = sample_quantile(seconds, 0.95);
  stats.median_rhs_evaluations = sample_quantile(as_doubles(rhs_evaluations), 0.5);
  stats.mean_rhs_evaluations = rhs_evaluations.empty()
                                   ? 0.0
                                   : static_cast<double>(std::accumulate(
                                         rhs_evaluations.begin(), rhs_evaluations.end(), 0L)) /
                                         static_cast<double>(rhs_evaluations.size());
  stats.median_steps = sample_quantile(as_doubles(steps), 0.5);
  return stats;
}

}  // namespace blockfrag
