#include "postproc/risk/risk_integral.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include "engine/errors.hpp"
#include "postproc/fragility/normal_probability.hpp"

namespace blockfrag {
namespace {

// Each piece between two break points is integrated in ln x by 4-point Gauss-Legendre on
// sub-intervals at most this wide: the integrand (a smooth fragility times a power law) is then
// integrated to about 1e-12 of itself.
constexpr double kMaxLogStep = 0.05;
constexpr std::array<double, 4> kNodes = {-0.8611363115940526, -0.3399810435848563,
                                          0.3399810435848563, 0.8611363115940526};
constexpr std::array<double, 4> kWeights = {0.3478548451374538, 0.6521451548625461,
                                            0.6521451548625461, 0.3478548451374538};

// integral over [a, b] (a < b, inside hazard segment `segment`) of P(x) (-d lambda / d ln x) d ln
// x.
double integrate_piece(const HazardCurve& hazard, std::size_t segment,
                       const ExceedanceProbability& probability, double a, double b) {
  const double la = std::log(a), lb = std::log(b);
  const auto steps = static_cast<int>(std::ceil((lb - la) / kMaxLogStep));
  const double h = (lb - la) / steps;
  double sum = 0.0;
  for (int s = 0; s < steps; ++s) {
    const double middle = la + (s + 0.5) * h;
    for (std::size_t q = 0; q < kNodes.size(); ++q) {
      const double x = std::exp(middle + 0.5 * h * kNodes[q]);
      sum += kWeights[q] * probability(x) * hazard_density(hazard, segment, x);
    }
  }
  return 0.5 * h * sum;
}

}  // namespace

double RiskIntegral::share_beyond_levels() const {
  return lambda > 0.0 ? (lambda_below_levels + lambda_above_levels) / lambda : 0.0;
}

RiskIntegral integrate_risk(const HazardCurve& hazard, const ExceedanceProbability& probability,
                            const std::vector<double>& levels) {
  check_hazard_curve(hazard);
  if (levels.empty() || !std::is_sorted(levels.begin(), levels.end())) {
    throw ContractViolation("integrate_risk: the study's levels must be given, increasing");
  }
  const double lowest = levels.front(), highest = levels.back();
  RiskIntegral result;
  result.bin_lambda.assign(hazard.im.size() - 1, 0.0);
  for (std::size_t i = 0; i + 1 < hazard.im.size(); ++i) {
    const double x0 = hazard.im[i], x1 = hazard.im[i + 1];
    std::vector<double> breaks{x0, x1};
    for (const double level : levels) {
      if (level > x0 && level < x1) breaks.push_back(level);
    }
    std::sort(breaks.begin(), breaks.end());
    for (std::size_t p = 0; p + 1 < breaks.size(); ++p) {
      const double part = integrate_piece(hazard, i, probability, breaks[p], breaks[p + 1]);
      result.bin_lambda[i] += part;
      if (breaks[p + 1] <= lowest) result.lambda_below_levels += part;
      if (breaks[p] >= highest) result.lambda_above_levels += part;
    }
  }
  const double last = hazard.im.back();
  result.lambda_beyond_hazard = hazard.annual_rate.back() * probability(last);
  if (last >= highest) result.lambda_above_levels += result.lambda_beyond_hazard;
  if (last <= lowest) result.lambda_below_levels += result.lambda_beyond_hazard;
  result.lambda = result.lambda_beyond_hazard;
  for (const double part : result.bin_lambda) result.lambda += part;
  return result;
}

ExceedanceProbability lognormal_exceedance(double median, double beta) {
  if (!(median > 0.0 && beta > 0.0)) {
    throw ContractViolation("lognormal_exceedance: median and beta must be > 0");
  }
  return [median, beta](double x) { return normal_cdf(std::log(x / median) / beta); };
}

ExceedanceProbability points_exceedance(std::vector<double> levels,
                                        std::vector<double> probability) {
  if (levels.empty() || levels.size() != probability.size() ||
      !std::is_sorted(levels.begin(), levels.end())) {
    throw ContractViolation("points_exceedance: levels, increasing, each with its probability");
  }
  return [levels = std::move(levels), probability = std::move(probability)](double x) {
    if (x <= levels.front()) return probability.front();
    if (x >= levels.back()) return probability.back();
    const auto above = std::upper_bound(levels.begin(), levels.end(), x);
    const auto j = static_cast<std::size_t>(above - levels.begin());
    const double t = std::log(x / levels[j - 1]) / std::log(levels[j] / levels[j - 1]);
    return probability[j - 1] + t * (probability[j] - probability[j - 1]);
  };
}

double probability_in_years(double lambda, double years) { return -std::expm1(-lambda * years); }

}  // namespace blockfrag
