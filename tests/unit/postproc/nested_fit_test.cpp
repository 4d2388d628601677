// The common-beta fit against a synthetic truth (three limit states of one beta, binomial counts
// drawn from them): it recovers each median and the beta within its standard errors, its 95 %
// Wald intervals cover the truth about 95 % of the time over repeated draws, its curves never
// cross, it is a maximum of the joint likelihood, and with one limit state it is that state's
// separate fit (lognormal_fit.hpp).
#include "postproc/fragility/nested_fit.hpp"

#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "postproc/fragility/lognormal_fit.hpp"
#include "postproc/fragility/normal_probability.hpp"
#include "tests/support/fragility_draws.hpp"

namespace blockfrag {
namespace {

const std::vector<double> kLevels{0.2, 0.4, 0.6, 0.8, 1.0, 1.2, 1.4, 1.6, 1.8, 2.0};
const std::vector<double> kMedians{0.5, 0.8, 1.3};
constexpr double kBeta = 0.4;

std::vector<NestedStateData> draw_states(std::mt19937_64& engine, std::int64_t trials) {
  std::vector<NestedStateData> states;
  for (const double median : kMedians) {
    NestedStateData state{kLevels, std::vector<std::int64_t>(kLevels.size(), trials), {}};
    for (const double x : kLevels) {
      const double p = testing::normal_cdf(std::log(x / median) / kBeta);
      state.exceedances.push_back(testing::binomial_draw(engine, trials, p));
    }
    states.push_back(state);
  }
  return states;
}

TEST(NestedFit, RecoversASyntheticTruthWithinItsStandardErrors) {
  std::mt19937_64 engine(20261206);
  const NestedFit fit = fit_nested_lognormal(draw_states(engine, 200));
  ASSERT_TRUE(fit.ok()) << fit.status;
  ASSERT_EQ(fit.median.size(), 3u);
  for (std::size_t k = 0; k < kMedians.size(); ++k) {
    ASSERT_TRUE(fit.median_se[k] > 0.0 && fit.median_se[k] < 0.05) << k;
    EXPECT_LT(std::abs(fit.median[k] - kMedians[k]), 2.5 * fit.median_se[k]) << k;
  }
  ASSERT_TRUE(fit.beta_se > 0.0 && fit.beta_se < 0.05);
  EXPECT_LT(std::abs(fit.beta - kBeta), 2.5 * fit.beta_se);
}

TEST(NestedFit, ItsIntervalsCoverTheTruthAbout95PercentOfTheTime) {
  std::mt19937_64 engine(7);
  constexpr int repeats = 100;
  int median_covered = 0, beta_covered = 0;
  for (int r = 0; r < repeats; ++r) {
    const NestedFit fit = fit_nested_lognormal(draw_states(engine, 60));
    ASSERT_TRUE(fit.ok()) << fit.status;
    median_covered += std::abs(fit.median[1] - kMedians[1]) <= 1.96 * fit.median_se[1];
    beta_covered += std::abs(fit.beta - kBeta) <= 1.96 * fit.beta_se;
  }
  // 95 % of 100 is 95, its binomial standard deviation 2.2: 89 is 3 of them below; all 100
  // (0.6 % likely) would say the intervals are too wide.
  EXPECT_GE(median_covered, 89);
  EXPECT_LE(median_covered, 99);
  EXPECT_GE(beta_covered, 89);
  EXPECT_LE(beta_covered, 99);
}

TEST(NestedFit, ItsCurvesNeverCrossAndItIsTheJointMaximum) {
  std::mt19937_64 engine(3);
  const auto states = draw_states(engine, 50);
  const NestedFit fit = fit_nested_lognormal(states);
  ASSERT_TRUE(fit.ok()) << fit.status;
  // Less severe (smaller median) above more severe at every intensity, far into both tails.
  for (double x = 1e-3; x < 1e3; x *= 1.05) {
    for (std::size_t k = 1; k < states.size(); ++k) {
      const double lower = normal_cdf(std::log(x / fit.median[k - 1]) / fit.beta);
      const double upper = normal_cdf(std::log(x / fit.median[k]) / fit.beta);
      ASSERT_GE(lower, upper) << x << ' ' << k;
    }
  }
  // Moving the beta or a median either way lowers the joint likelihood.
  const auto joint = [&](std::vector<double> medians, double beta) {
    double sum = 0.0;
    for (std::size_t k = 0; k < states.size(); ++k) {
      sum += lognormal_log_likelihood(states[k].im, states[k].trials, states[k].exceedances,
                                      medians[k], beta);
    }
    return sum;
  };
  EXPECT_NEAR(joint(fit.median, fit.beta), fit.log_likelihood, 1e-9 * std::abs(fit.log_likelihood));
  for (const double factor : {0.999, 1.001}) {
    EXPECT_LT(joint(fit.median, fit.beta * factor), fit.log_likelihood);
    auto moved = fit.median;
    moved[1] *= factor;
    EXPECT_LT(joint(moved, fit.beta), fit.log_likelihood);
  }
}

TEST(NestedFit, OneLimitStateIsItsSeparateFit) {
  const std::vector<double> im{0.2, 0.3, 0.4, 0.6, 0.7, 0.8, 0.9, 1.0};
  const std::vector<std::int64_t> trials(8, 40), exceedances{0, 0, 0, 4, 6, 13, 12, 16};
  const NestedFit nested = fit_nested_lognormal({{im, trials, exceedances}});
  const LognormalFit separate = fit_lognormal_fragility(im, trials, exceedances);
  ASSERT_TRUE(nested.ok());
  // Baker's (2015) data: theta 1.076116, beta 0.429237 (docs/references.md).
  EXPECT_NEAR(nested.median[0], separate.median, 1e-7);
  EXPECT_NEAR(nested.beta, separate.beta, 1e-7);
  EXPECT_NEAR(nested.log_likelihood, separate.log_likelihood, 1e-9);
  EXPECT_FALSE(fit_nested_lognormal({}).ok());
}

}  // namespace
}  // namespace blockfrag
