// Statistical properties of the sampled inputs, with bounds derived from the sample size:
// moments within 5 standard errors of their closed forms, Kolmogorov-Smirnov distances below the
// 0.1% critical value, unbiased Latin hypercube permutations, uncorrelated streams, and Latin
// hypercube's smaller variance of the mean for monotone functions. All seeds are fixed, so a pass
// is reproducible; the bounds are what make a failure meaningful.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <map>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "sampling/designs.hpp"
#include "sampling/distributions.hpp"
#include "sampling/sampling_plan.hpp"

namespace blockfrag {
namespace {

constexpr std::uint32_t sample_size = 20000;
constexpr double standard_errors = 5.0;
// Asymptotic Kolmogorov critical value at significance 0.001: sqrt(-ln(0.0005) / 2).
constexpr double kolmogorov_001 = 1.9494746035204052;

// Closed forms computed with <cmath> (erf), independently of GSL.
double standard_normal_cdf(double z) { return 0.5 * std::erfc(-z / std::numbers::sqrt2); }
double standard_normal_pdf(double z) {
  return std::exp(-0.5 * z * z) / std::sqrt(2 * std::numbers::pi);
}

struct Law {
  std::string name;
  Distribution distribution;
  double mean;
  double variance;
  double fourth_central_moment;  // NaN when not used: the variance is then not checked
  std::function<double(double)> cdf;
};

// Central fourth moment from raw moments m1..m4.
double fourth_central(double m1, double m2, double m3, double m4) {
  return m4 - 4 * m3 * m1 + 6 * m2 * m1 * m1 - 3 * m1 * m1 * m1 * m1;
}

std::vector<Law> laws() {
  std::vector<Law> result;
  {
    const double a = 2.0, b = 5.0, w = b - a;
    result.push_back({"uniform", Uniform{a, b}, (a + b) / 2, w * w / 12, w * w * w * w / 80,
                      [=](double x) { return std::clamp((x - a) / w, 0.0, 1.0); }});
  }
  {
    const double mu = 1.0, sigma = 0.5;
    result.push_back({"normal", Normal{mu, sigma}, mu, sigma * sigma, 3 * std::pow(sigma, 4),
                      [=](double x) { return standard_normal_cdf((x - mu) / sigma); }});
  }
  {
    // ln x ~ N(ln median, beta): E[x^k] = median^k exp(k^2 beta^2 / 2).
    const double median = 2.0, beta = 0.5;
    auto raw = [=](int k) { return std::pow(median, k) * std::exp(k * k * beta * beta / 2); };
    const double m1 = raw(1), m2 = raw(2), m3 = raw(3), m4 = raw(4);
    result.push_back({"lognormal", LogNormal{median, beta}, m1, m2 - m1 * m1,
                      fourth_central(m1, m2, m3, m4),
                      [=](double x) { return standard_normal_cdf(std::log(x / median) / beta); }});
  }
  {
    // Normal truncated to [lo, hi]: the standard mean and variance formulas.
    const double mu = 0.6, sigma = 0.2, lo = 0.3, hi = 1.0;
    const double alpha = (lo - mu) / sigma, beta = (hi - mu) / sigma;
    const double z = standard_normal_cdf(beta) - standard_normal_cdf(alpha);
    const double phi_a = standard_normal_pdf(alpha), phi_b = standard_normal_pdf(beta);
    const double mean = mu + sigma * (phi_a - phi_b) / z;
    const double variance =
        sigma * sigma * (1 + (alpha * phi_a - beta * phi_b) / z - std::pow((phi_a - phi_b) / z, 2));
    result.push_back({"truncated normal", Normal{mu, sigma, lo, hi}, mean, variance, std::nan(""),
                      [=](double x) {
                        const double p =
                            (standard_normal_cdf((x - mu) / sigma) - standard_normal_cdf(alpha)) /
                            z;
                        return std::clamp(p, 0.0, 1.0);
                      }});
  }
  return result;
}

// One plan holding every law as an input, with `levels` levels of `n` samples.
SamplingPlan plan_of(const std::vector<Law>& laws, Design design, std::uint64_t seed,
                     std::uint32_t n, std::uint32_t levels = 1) {
  SamplingPlan plan;
  plan.seed = seed;
  plan.design = design;
  plan.samples_per_level = n;
  plan.levels = levels;
  for (const auto& law : laws) plan.inputs.push_back({law.name, law.distribution});
  return plan;
}

// columns[k] = input k's values over every sample of the plan.
std::vector<std::vector<double>> draw_all(const SamplingPlan& plan) {
  std::vector<std::vector<double>> columns(plan.inputs.size());
  Sampler sampler(plan);
  for (std::uint64_t index = 0; index < sample_count(plan); ++index) {
    const auto values = sampler.draw(index);
    for (std::size_t k = 0; k < values.size(); ++k) columns[k].push_back(values[k]);
  }
  return columns;
}

double mean_of(const std::vector<double>& x) {
  double sum = 0;
  for (const double v : x) sum += v;
  return sum / x.size();
}

double variance_of(const std::vector<double>& x) {
  const double m = mean_of(x);
  double sum = 0;
  for (const double v : x) sum += (v - m) * (v - m);
  return sum / (x.size() - 1);
}

double correlation(const std::vector<double>& x, const std::vector<double>& y) {
  const double mx = mean_of(x), my = mean_of(y);
  double sxy = 0, sxx = 0, syy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sxy += (x[i] - mx) * (y[i] - my);
    sxx += (x[i] - mx) * (x[i] - mx);
    syy += (y[i] - my) * (y[i] - my);
  }
  return sxy / std::sqrt(sxx * syy);
}

double kolmogorov_distance(std::vector<double> x, const std::function<double(double)>& cdf) {
  std::sort(x.begin(), x.end());
  const double n = static_cast<double>(x.size());
  double distance = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double f = cdf(x[i]);
    distance = std::max({distance, f - i / n, (i + 1) / n - f});
  }
  return distance;
}

class SamplingStatistics : public ::testing::TestWithParam<Design> {};

TEST_P(SamplingStatistics, MeansAndVariancesMatchClosedForms) {
  const auto all = laws();
  const auto columns = draw_all(plan_of(all, GetParam(), 7, sample_size));
  for (std::size_t k = 0; k < all.size(); ++k) {
    const Law& law = all[k];
    // Standard error of the sample mean sqrt(var / n), of the sample variance
    // sqrt((mu4 - var^2) / n). Latin hypercube is never worse for these, so the Monte Carlo
    // errors bound both designs.
    const double mean_error = std::sqrt(law.variance / sample_size);
    EXPECT_NEAR(mean_of(columns[k]), law.mean, standard_errors * mean_error) << law.name;
    if (!std::isnan(law.fourth_central_moment)) {
      const double variance_error =
          std::sqrt((law.fourth_central_moment - law.variance * law.variance) / sample_size);
      EXPECT_NEAR(variance_of(columns[k]), law.variance, standard_errors * variance_error)
          << law.name;
    }
  }
}

TEST_P(SamplingStatistics, KolmogorovSmirnovDistanceIsBelowTheCriticalValue) {
  const auto all = laws();
  const auto columns = draw_all(plan_of(all, GetParam(), 8, sample_size));
  for (std::size_t k = 0; k < all.size(); ++k) {
    EXPECT_LT(kolmogorov_distance(columns[k], all[k].cdf), kolmogorov_001 / std::sqrt(sample_size))
        << all[k].name;
  }
}

TEST_P(SamplingStatistics, InputsAndNeighbouringSamplesAreUncorrelated) {
  // A sample correlation of independent variables has standard error about 1/sqrt(n).
  const auto all = laws();
  const auto columns = draw_all(plan_of(all, GetParam(), 9, sample_size));
  const double bound = standard_errors / std::sqrt(sample_size);
  for (std::size_t k = 0; k < all.size(); ++k) {
    for (std::size_t other = 0; other < k; ++other) {
      EXPECT_LT(std::abs(correlation(columns[k], columns[other])), bound)
          << all[k].name << " / " << all[other].name;
    }
    const std::vector<double> head(columns[k].begin(), columns[k].end() - 1);
    const std::vector<double> tail(columns[k].begin() + 1, columns[k].end());
    EXPECT_LT(std::abs(correlation(head, tail)), bound) << all[k].name << " lag 1";
  }
}

TEST_P(SamplingStatistics, LevelsAreFilledAlike) {
  // Every level is a sample of the same law: each level's mean within 5 standard errors.
  const auto all = laws();
  const std::uint32_t n = 2000, levels = 8;
  const auto columns = draw_all(plan_of(all, GetParam(), 10, n, levels));
  for (std::size_t k = 0; k < all.size(); ++k) {
    for (std::uint32_t level = 0; level < levels; ++level) {
      const std::vector<double> part(columns[k].begin() + level * n,
                                     columns[k].begin() + (level + 1) * n);
      EXPECT_NEAR(mean_of(part), all[k].mean, standard_errors * std::sqrt(all[k].variance / n))
          << all[k].name << " level " << level;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Designs, SamplingStatistics,
                         ::testing::Values(Design::monte_carlo, Design::latin_hypercube),
                         [](const auto& design) {
                           return design.param == Design::monte_carlo
                                      ? std::string("MonteCarlo")
                                      : std::string("LatinHypercube");
                         });

TEST(LatinHypercubeStatistics, UniformMeanHasTheStratifiedStandardError) {
  // With u_j = (s_j + v_j) / n over a permutation s, mean(u) = (n - 1) / (2n) + sum(v) / n^2:
  // its standard error is 1 / (sqrt(12) n^1.5), against 1 / sqrt(12 n) for Monte Carlo.
  const std::uint32_t n = 1000;
  for (std::uint64_t seed = 0; seed < 20; ++seed) {
    const SamplingPlan plan = plan_of({laws()[0]}, Design::latin_hypercube, seed, n);
    const auto column = draw_all(plan)[0];
    const double width = 3.0;
    const double error = width / (std::sqrt(12.0) * std::pow(n, 1.5));
    EXPECT_NEAR(mean_of(column), 3.5, standard_errors * error) << seed;
  }
}

TEST(LatinHypercubeStatistics, PermutationsAreUniform) {
  // Every permutation of n elements equally likely: chi-square over the n! outcomes, against the
  // 0.1% critical values (df = 5: 20.515, df = 23: 49.728). The classic Fisher-Yates slip
  // (swapping with any position instead of one at or below k) fails this by a wide margin.
  const std::map<std::uint32_t, double> critical = {{3u, 20.515005652432878},
                                                    {4u, 49.728232466431495}};
  for (const auto& [n, limit] : critical) {
    const std::uint64_t levels = 60000;
    std::map<std::vector<std::uint32_t>, int> counts;
    for (std::uint64_t level = 0; level < levels; ++level) {
      ++counts[latin_hypercube_permutation(31, 77, level, n)];
    }
    const double outcomes = n == 3 ? 6.0 : 24.0;
    ASSERT_EQ(counts.size(), static_cast<std::size_t>(outcomes));
    const double expected = levels / outcomes;
    double chi_square = 0;
    for (const auto& [permutation, count] : counts) {
      chi_square += (count - expected) * (count - expected) / expected;
    }
    EXPECT_LT(chi_square, limit) << "n = " << n;
  }
}

TEST(LatinHypercubeStatistics, MeanOfAMonotoneFunctionVariesLessThanWithMonteCarlo) {
  // f = x1 + exp(x2), x1 ~ N(1, 0.5), x2 ~ U(2, 5): monotone in each input, so Latin hypercube
  // removes the main effects and its variance of the mean falls far below Monte Carlo's
  // var(f) / n (for smooth additive f, by a factor of order n^2). Over 200 seeds the estimated
  // Monte Carlo variance itself has relative standard error sqrt(2 / 199) = 0.1, hence its
  // +-50% band (5 of them).
  const std::vector<Law> all = {laws()[1], laws()[0]};
  const std::uint32_t n = 100;
  const int repeats = 200;
  auto variance_of_means = [&](Design design) {
    std::vector<double> means;
    for (int seed = 0; seed < repeats; ++seed) {
      const auto columns = draw_all(plan_of(all, design, 1000 + seed, n));
      std::vector<double> f(n);
      for (std::uint32_t i = 0; i < n; ++i) f[i] = columns[0][i] + std::exp(columns[1][i]);
      means.push_back(mean_of(f));
    }
    return variance_of(means);
  };
  const double a = 2.0, b = 5.0;
  const double exp_mean = (std::exp(b) - std::exp(a)) / (b - a);
  const double exp_square_mean = (std::exp(2 * b) - std::exp(2 * a)) / (2 * (b - a));
  const double f_variance = 0.25 + exp_square_mean - exp_mean * exp_mean;

  const double monte_carlo = variance_of_means(Design::monte_carlo);
  const double latin_hypercube = variance_of_means(Design::latin_hypercube);
  EXPECT_NEAR(monte_carlo / (f_variance / n), 1.0, 0.5);
  EXPECT_LT(latin_hypercube, 0.1 * monte_carlo);
}

}  // namespace
}  // namespace blockfrag
