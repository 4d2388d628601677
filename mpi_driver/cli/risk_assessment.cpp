#include "mpi_driver/cli/risk_assessment.hpp"

#include <algorithm>
#include <cmath>

#include "engine/errors.hpp"
#include "mpi_driver/study/limit_states.hpp"
#include "postproc/fragility/bootstrap.hpp"
#include "postproc/fragility/sample_quantile.hpp"

namespace blockfrag {
namespace {

// The stored intervals are the bootstrap's quantiles of the same refits: drawn again from the
// same counts and seed, they agree to the last bits of the fits' convergence.
constexpr double kReproducedTolerance = 1e-9;

void set_interval(RiskEstimate& estimate) {
  std::vector<double> finite;
  for (const double lambda : estimate.resample_lambda) {
    if (std::isfinite(lambda)) finite.push_back(lambda);
  }
  if (finite.empty()) {
    if (estimate.interval_note.empty()) estimate.interval_note = "no resample has a fit";
    return;
  }
  estimate.lambda_low = sample_quantile(finite, 0.025);
  estimate.lambda_high = sample_quantile(finite, 0.975);
}

bool reproduces(const std::vector<double>& stored, double low, double high) {
  const auto close = [](double a, double b) {
    return std::abs(a - b) <= kReproducedTolerance * std::max(std::abs(a), std::abs(b));
  };
  return stored.size() == 2 && close(stored[0], low) && close(stored[1], high);
}

// The fit's and the points' lambda of every resample the study drew.
// `order`: the indices of the levels with trials, by increasing intensity (risk.levels').
void bootstrap_estimates(const WeightedStudy& weighted, std::size_t k, const HazardCurve& hazard,
                         const std::vector<std::size_t>& order, LimitStateRisk& risk) {
  const FragilityFit& fit = weighted.study.fits.states[k];
  const StateCounts& counts = weighted.study.counts[k];
  const auto note = [&](const std::string& why) {
    if (risk.fit) risk.fit->interval_note = why;
    if (risk.points) risk.points->interval_note = why;
  };
  if (weighted.study.cloud) {
    return note("a cloud's bootstrap resamples its samples, which risk does not read");
  }
  if (!fit.fitted() || counts.bootstrap_resamples == 0) {
    return note("the study ran no bootstrap for this limit state");
  }
  const UniformDraw uniforms = bootstrap_uniforms(weighted.study.seed, fit.name);
  const auto refits = bootstrap_stripe_fits(fit.im, counts.trials, counts.exceedances,
                                            counts.bootstrap_resamples, uniforms);
  std::vector<double> medians;
  for (const auto& refit : refits) {
    if (refit.status == FitStatus::ok) medians.push_back(refit.median);
  }
  if (!reproduces(fit.median_ci, sample_quantile(medians, 0.025),
                  sample_quantile(medians, 0.975))) {
    return note(
        "the study's stored bootstrap interval of the median is not reproduced from its "
        "counts and seed");
  }
  for (std::size_t b = 0; b < refits.size(); ++b) {
    const auto& refit = refits[b];
    risk.fit->resample_lambda.push_back(
        refit.status == FitStatus::ok
            ? integrate_risk(hazard, lognormal_exceedance(refit.median, refit.beta), risk.levels)
                  .lambda
            : RiskEstimate::nan);
    if (!risk.points) continue;
    const auto drawn = resampled_exceedances(counts.trials, counts.exceedances, b, uniforms);
    std::vector<double> probability;
    for (const std::size_t j : order) {
      probability.push_back(static_cast<double>(drawn[j]) / static_cast<double>(counts.trials[j]));
    }
    risk.points->resample_lambda.push_back(
        integrate_risk(hazard, points_exceedance(risk.levels, probability), risk.levels).lambda);
  }
  set_interval(*risk.fit);
  if (risk.points) set_interval(*risk.points);
}

LimitStateRisk assess_state(const WeightedStudy& weighted, std::size_t k,
                            const HazardCurve& hazard) {
  const FragilityFit& fit = weighted.study.fits.states[k];
  const StateCounts& counts = weighted.study.counts[k];
  LimitStateRisk risk;
  risk.name = fit.name;
  risk.median = fit.median;
  risk.beta = fit.beta;
  risk.fit_status = fit.fit_status;
  // Levels in increasing order with trials (an adaptive study's come in the order they ran).
  std::vector<std::size_t> order;
  for (std::size_t j = 0; j < fit.im.size(); ++j) {
    if (counts.trials[j] > 0) order.push_back(j);
  }
  std::sort(order.begin(), order.end(), [&](auto a, auto b) { return fit.im[a] < fit.im[b]; });
  for (const std::size_t j : order) {
    risk.levels.push_back(fit.im[j]);
    risk.probability.push_back(static_cast<double>(counts.exceedances[j]) /
                               static_cast<double>(counts.trials[j]));
  }
  if (risk.levels.empty()) return risk;
  if (fit.fitted()) {
    risk.fit.emplace();
    risk.fit->integral =
        integrate_risk(hazard, lognormal_exceedance(fit.median, fit.beta), risk.levels);
  }
  risk.points.emplace();
  risk.points->integral =
      integrate_risk(hazard, points_exceedance(risk.levels, risk.probability), risk.levels);
  bootstrap_estimates(weighted, k, hazard, order, risk);
  return risk;
}

// sum of weight * estimate over the studies; nullopt when one of them has none.
std::optional<RiskEstimate> combined_estimate(const std::vector<StudyRisk>& studies, std::size_t k,
                                              std::optional<RiskEstimate> LimitStateRisk::*method) {
  RiskEstimate sum;
  std::size_t resamples = SIZE_MAX;
  for (const auto& study : studies) {
    const auto& estimate = study.states[k].*method;
    if (!estimate) return std::nullopt;
    const double w = study.weight;
    const RiskIntegral& part = estimate->integral;
    RiskIntegral& total = sum.integral;
    total.lambda += w * part.lambda;
    total.lambda_below_levels += w * part.lambda_below_levels;
    total.lambda_above_levels += w * part.lambda_above_levels;
    total.lambda_beyond_hazard += w * part.lambda_beyond_hazard;
    total.bin_lambda.resize(part.bin_lambda.size(), 0.0);
    for (std::size_t i = 0; i < part.bin_lambda.size(); ++i) {
      total.bin_lambda[i] += w * part.bin_lambda[i];
    }
    resamples = std::min(resamples, estimate->resample_lambda.size());
    if (estimate->resample_lambda.empty()) sum.interval_note = estimate->interval_note;
  }
  sum.resample_lambda.assign(resamples, 0.0);
  for (const auto& study : studies) {
    const auto& estimate = study.states[k].*method;
    for (std::size_t b = 0; b < resamples; ++b) {
      sum.resample_lambda[b] += study.weight * estimate->resample_lambda[b];
    }
  }
  if (resamples > 0) set_interval(sum);
  return sum;
}

}  // namespace

StudyRisk assess_study(const WeightedStudy& weighted, const HazardCurve& hazard) {
  StudyRisk result;
  result.file = weighted.file;
  result.weight = weighted.weight;
  result.config_hash = weighted.study.fits.config_hash;
  result.im_label = weighted.study.fits.im_label;
  result.im_units = weighted.study.fits.im_units;
  result.cloud = weighted.study.cloud;
  for (std::size_t k = 0; k < weighted.study.fits.states.size(); ++k) {
    result.states.push_back(assess_state(weighted, k, hazard));
  }
  return result;
}

std::vector<LimitStateRisk> combine_studies(const std::vector<StudyRisk>& studies) {
  if (studies.empty()) throw ContractViolation("combine_studies: no study");
  std::vector<LimitStateRisk> combined;
  for (std::size_t k = 0; k < studies.front().states.size(); ++k) {
    LimitStateRisk state;
    state.name = studies.front().states[k].name;
    state.median = state.beta = RiskEstimate::nan;
    if (studies.size() == 1) state = studies.front().states[k];
    state.fit = combined_estimate(studies, k, &LimitStateRisk::fit);
    state.points = combined_estimate(studies, k, &LimitStateRisk::points);
    combined.push_back(std::move(state));
  }
  return combined;
}

}  // namespace blockfrag
