// The lognormal fit recovers a known curve from binomial data drawn from it, within standard errors
// from the observed Fisher information (a numerical Hessian of a likelihood written here), and the
// 95 % Wald intervals of the median and of beta cover the true values at their nominal rate over
// many data sets.
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "postproc/fragility/lognormal_fit.hpp"

namespace blockfrag {
namespace {

constexpr double true_median = 0.8;
constexpr double true_beta = 0.4;
constexpr std::int64_t trials_per_level = 200;
constexpr int repetitions = 200;

struct Data {
  std::vector<double> im;
  std::vector<std::int64_t> trials;
  std::vector<std::int64_t> exceedances;
};

double normal_cdf(double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); }

// Ten levels from p = 0.02 to 0.97 of the true curve.
std::vector<double> levels() {
  std::vector<double> im;
  for (int k = 1; k <= 10; ++k) im.push_back(0.2 + 0.15 * k);
  return im;
}

// A binomial draw as a sum of Bernoulli trials. Uniforms straight from mt19937's 32-bit output
// (std::*_distribution algorithms differ between standard libraries; this is the same everywhere).
std::int64_t binomial_draw(std::mt19937& engine, std::int64_t n, double p) {
  std::int64_t successes = 0;
  for (std::int64_t i = 0; i < n; ++i)
    if ((static_cast<double>(engine()) + 0.5) / 4294967296.0 < p) ++successes;
  return successes;
}

Data draw(std::mt19937& engine) {
  Data d{levels(), {}, {}};
  for (const double x : d.im) {
    d.trials.push_back(trials_per_level);
    d.exceedances.push_back(
        binomial_draw(engine, trials_per_level, normal_cdf(std::log(x / true_median) / true_beta)));
  }
  return d;
}

double log_likelihood(const Data& d, double median, double beta) {
  double sum = 0.0;
  for (std::size_t j = 0; j < d.im.size(); ++j) {
    const double n = static_cast<double>(d.trials[j]), z = static_cast<double>(d.exceedances[j]);
    const double p = normal_cdf(std::log(d.im[j] / median) / beta);
    sum += z * std::log(p) + (n - z) * std::log(1.0 - p);
  }
  return sum;
}

struct StandardErrors {
  double median, beta;
};

// Inverse of the observed information -H, H the Hessian of ln L in (median, beta) by central
// differences with steps proportional to the estimates.
StandardErrors standard_errors(const Data& d, double median, double beta) {
  const double hm = 1e-4 * median, hb = 1e-4 * beta;
  auto f = [&](double dm, double db) { return log_likelihood(d, median + dm, beta + db); };
  const double f0 = f(0, 0);
  const double h_mm = (f(hm, 0) - 2 * f0 + f(-hm, 0)) / (hm * hm);
  const double h_bb = (f(0, hb) - 2 * f0 + f(0, -hb)) / (hb * hb);
  const double h_mb = (f(hm, hb) - f(hm, -hb) - f(-hm, hb) + f(-hm, -hb)) / (4 * hm * hb);
  const double det = h_mm * h_bb - h_mb * h_mb;
  return {std::sqrt(-h_bb / det), std::sqrt(-h_mm / det)};
}

// The central 99.9 % range of Binomial(n, p), from the pmf.
std::pair<int, int> binomial_range(int n, double p) {
  std::vector<double> cdf;
  double sum = 0.0;
  for (int k = 0; k <= n; ++k) {
    sum += std::exp(std::lgamma(n + 1.0) - std::lgamma(k + 1.0) - std::lgamma(n - k + 1.0) +
                    k * std::log(p) + (n - k) * std::log1p(-p));
    cdf.push_back(sum);
  }
  int low = 0, high = n;
  while (cdf[static_cast<std::size_t>(low)] < 0.0005) ++low;
  while (high > 0 && cdf[static_cast<std::size_t>(high - 1)] > 0.9995) --high;
  return {low, high};
}

TEST(LognormalFitRecovery, EstimatesLieWithinTheirStandardErrorsAndWaldCoverageIsNominal) {
  std::mt19937 engine(20150101);
  int median_covered = 0, beta_covered = 0;
  double mean_z_median = 0.0;
  for (int r = 0; r < repetitions; ++r) {
    const Data d = draw(engine);
    const auto fit = fit_lognormal_fragility(d.im, d.trials, d.exceedances);
    ASSERT_EQ(fit.status, FitStatus::ok) << "repetition " << r;
    const auto se = standard_errors(d, fit.median, fit.beta);
    // 400 checks at 4.5 standard errors: a normal deviate that far out has probability 7e-6 each.
    EXPECT_LT(std::abs(fit.median - true_median), 4.5 * se.median) << "repetition " << r;
    EXPECT_LT(std::abs(fit.beta - true_beta), 4.5 * se.beta) << "repetition " << r;
    // The information is that of 2000 trials: standard errors of a few percent, not zero or huge.
    EXPECT_GT(se.median, 0.005);
    EXPECT_LT(se.median, 0.05);
    const double z = (fit.median - true_median) / se.median;
    if (std::abs(z) <= 1.959963984540054) ++median_covered;
    if (std::abs(fit.beta - true_beta) <= 1.959963984540054 * se.beta) ++beta_covered;
    mean_z_median += z / repetitions;
  }
  const auto [low, high] = binomial_range(repetitions, 0.95);
  EXPECT_GE(median_covered, low);
  EXPECT_LE(median_covered, high);
  EXPECT_GE(beta_covered, low);
  EXPECT_LE(beta_covered, high);
  // The mean of 200 near-standard normal deviates: within 4 / sqrt(200) of zero.
  EXPECT_LT(std::abs(mean_z_median), 4.0 / std::sqrt(static_cast<double>(repetitions)));
}

}  // namespace
}  // namespace blockfrag
