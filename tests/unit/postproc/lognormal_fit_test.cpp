// The lognormal fragility fit against Baker's (2015) check data (docs/references.md), against a
// likelihood written here from the definition (std::erfc, not the library's tail-safe forms), and
// through each degenerate case, where the likelihood itself is probed to show the maximum is
// missing.
#include "postproc/fragility/lognormal_fit.hpp"

#include <cmath>
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "tests/support/fragility_draws.hpp"

namespace blockfrag {
namespace {

using testing::fit;
using testing::FragilityCounts;
using testing::kBakerStripes;
using testing::normal_cdf;

// docs/references.md prints six decimals: half a unit in the last one.
constexpr double kPrintedSixDecimals = 0.5e-6;

// ln L from the definition; with_coefficients adds ln C(n, z).
double independent_log_likelihood(const FragilityCounts& d, double median, double beta,
                                  bool with_coefficients = true) {
  double sum = 0.0;
  for (std::size_t j = 0; j < d.im.size(); ++j) {
    const double n = static_cast<double>(d.trials[j]), z = static_cast<double>(d.exceedances[j]);
    const double p = normal_cdf(std::log(d.im[j] / median) / beta);
    if (with_coefficients)
      sum += std::lgamma(n + 1.0) - std::lgamma(z + 1.0) - std::lgamma(n - z + 1.0);
    if (z > 0) sum += z * std::log(p);
    if (n > z) sum += (n - z) * std::log(1.0 - p);
  }
  return sum;
}

// Central differences in (ln median, ln beta).
std::pair<double, double> numerical_gradient(const FragilityCounts& d, double median, double beta,
                                             double h = 1e-5) {
  auto at = [&](double dm, double db) {
    return independent_log_likelihood(d, median * std::exp(dm), beta * std::exp(db));
  };
  return {(at(h, 0) - at(-h, 0)) / (2 * h), (at(0, h) - at(0, -h)) / (2 * h)};
}

TEST(LognormalFit, MatchesBakersCheckValues) {
  const auto result = fit(kBakerStripes);
  ASSERT_EQ(result.status, FitStatus::ok);
  EXPECT_TRUE(result.converged);
  EXPECT_NEAR(result.median, 1.076116, kPrintedSixDecimals);
  EXPECT_NEAR(result.beta, 0.429237, kPrintedSixDecimals);
  EXPECT_NEAR(-result.log_likelihood, 10.797705, kPrintedSixDecimals);
  EXPECT_NEAR(-independent_log_likelihood(kBakerStripes, result.median, result.beta, false),
              107.899826, kPrintedSixDecimals);
  EXPECT_EQ(result.median_low, result.median);
  EXPECT_EQ(result.median_high, result.median);
}

TEST(LognormalFit, GradientOfAnIndependentLikelihoodVanishesAtTheEstimate) {
  const auto result = fit(kBakerStripes);
  const auto [g_median, g_beta] = numerical_gradient(kBakerStripes, result.median, result.beta);
  // Central differences with h = 1e-5 on ln L ~ 10 are good to about 1e-9.
  EXPECT_NEAR(g_median, 0.0, 1e-7);
  EXPECT_NEAR(g_beta, 0.0, 1e-7);
  // ... and the same differences are far from zero a little away: the check can fail.
  const auto [g_off, _] = numerical_gradient(kBakerStripes, result.median * 1.01, result.beta);
  EXPECT_GT(std::abs(g_off), 1e-2);
  EXPECT_LE(result.gradient_norm, 1e-10 * 320);
  // A maximum, not a saddle: every nearby point is lower.
  for (const double dm : {-1e-3, 0.0, 1e-3}) {
    for (const double db : {-1e-3, 0.0, 1e-3}) {
      if (dm == 0.0 && db == 0.0) continue;
      EXPECT_LT(independent_log_likelihood(kBakerStripes, result.median * std::exp(dm),
                                           result.beta * std::exp(db)),
                result.log_likelihood);
    }
  }
}

TEST(LognormalFit, LikelihoodMatchesAnIndependentEvaluation) {
  for (const double median : {0.3, 1.076116, 4.0})
    for (const double beta : {0.05, 0.4, 2.0}) {
      const double expected = independent_log_likelihood(kBakerStripes, median, beta);
      EXPECT_NEAR(lognormal_log_likelihood(kBakerStripes.im, kBakerStripes.trials,
                                           kBakerStripes.exceedances, median, beta),
                  expected, 1e-11 * std::abs(expected))
          << median << " " << beta;
    }
}

// In the far tails Phi underflows and the definition gives -inf; the library's ln L must stay
// finite and close to its asymptote ln Phi(-t) ~ -t^2/2 - ln(t sqrt(2 pi)).
TEST(LognormalFit, LikelihoodStaysFiniteInTheFarTails) {
  const std::vector<double> im{1.0};
  const std::vector<std::int64_t> n{1}, z{1};
  const double t = 50.0;  // ln(1 / median) / beta = -50 with median = e
  const double value = lognormal_log_likelihood(im, n, z, std::exp(1.0), 1.0 / t);
  EXPECT_NEAR(value, -0.5 * t * t - std::log(t * std::sqrt(2.0 * M_PI)), 1e-3);
}

// The curve is a function of x / median: changing the unit of the intensity scales the median only.
TEST(LognormalFit, ScalesWithTheUnitOfTheIntensity) {
  FragilityCounts scaled = kBakerStripes;
  for (double& x : scaled.im) x *= 9.81;
  const auto base = fit(kBakerStripes), other = fit(scaled);
  ASSERT_EQ(other.status, FitStatus::ok);
  EXPECT_NEAR(other.median / base.median, 9.81, 1e-9);
  EXPECT_NEAR(other.beta, base.beta, 1e-9);
  EXPECT_NEAR(other.log_likelihood, base.log_likelihood, 1e-9);
}

// Levels without trials carry no information; a level split into two entries at the same im
// carries the same information about the curve (the binomial coefficients change, not the fit).
TEST(LognormalFit, IgnoresEmptyLevelsAndPoolsRepeatedOnes) {
  FragilityCounts padded = kBakerStripes;
  padded.im.push_back(5.0);
  padded.trials.push_back(0);
  padded.exceedances.push_back(0);
  const auto base = fit(kBakerStripes), with_empty = fit(padded);
  EXPECT_NEAR(with_empty.median, base.median, 1e-12);
  EXPECT_NEAR(with_empty.beta, base.beta, 1e-12);
  EXPECT_NEAR(with_empty.log_likelihood, base.log_likelihood, 1e-12);

  FragilityCounts split = kBakerStripes;
  split.trials[5] = 25;
  split.exceedances[5] = 9;
  split.im.push_back(0.8);
  split.trials.push_back(15);
  split.exceedances.push_back(4);
  const auto pooled = fit(split);
  EXPECT_NEAR(pooled.median, base.median, 1e-9);
  EXPECT_NEAR(pooled.beta, base.beta, 1e-9);
}

// FragilityCounts close to separation still have a maximum (one level overlaps): it must be found,
// sharp.
TEST(LognormalFit, FindsSteepCurvesOfNearlySeparatedData) {
  const FragilityCounts steep{kBakerStripes.im, kBakerStripes.trials, {0, 0, 0, 1, 39, 40, 40, 40}};
  const auto result = fit(steep);
  ASSERT_EQ(result.status, FitStatus::ok);
  EXPECT_GT(result.median, 0.6);
  EXPECT_LT(result.median, 0.7);
  EXPECT_LT(result.beta, 0.1);
  const auto [g_median, g_beta] = numerical_gradient(steep, result.median, result.beta, 1e-6);
  EXPECT_NEAR(g_median, 0.0, 1e-5);
  EXPECT_NEAR(g_beta, 0.0, 1e-5);
}

TEST(LognormalFit, ConvergesWithMillionsOfTrials) {
  FragilityCounts big = kBakerStripes;
  for (auto& n : big.trials) n *= 250000;
  for (auto& z : big.exceedances) z *= 250000;
  const auto result = fit(big);
  ASSERT_EQ(result.status, FitStatus::ok);
  // The same proportions: the same maximum.
  EXPECT_NEAR(result.median, 1.076116, kPrintedSixDecimals);
  EXPECT_NEAR(result.beta, 0.429237, kPrintedSixDecimals);
}

TEST(LognormalFit, ReportsNoExceedances) {
  const auto result =
      fit({kBakerStripes.im, kBakerStripes.trials, std::vector<std::int64_t>(8, 0)});
  EXPECT_EQ(result.status, FitStatus::no_exceedances);
  EXPECT_FALSE(result.converged);
  EXPECT_TRUE(std::isnan(result.median));
  EXPECT_TRUE(std::isnan(result.beta));
  EXPECT_EQ(result.median_low, 1.0);
  EXPECT_TRUE(std::isinf(result.median_high));
  EXPECT_EQ(result.log_likelihood, 0.0);  // every p_j -> 0 reproduces the data exactly
}

TEST(LognormalFit, ReportsAllExceedances) {
  const auto result = fit({kBakerStripes.im, kBakerStripes.trials, kBakerStripes.trials});
  EXPECT_EQ(result.status, FitStatus::all_exceedances);
  EXPECT_TRUE(std::isnan(result.median));
  EXPECT_EQ(result.median_low, 0.0);
  EXPECT_EQ(result.median_high, 0.2);
}

TEST(LognormalFit, ReportsASingleLevel) {
  const FragilityCounts single{{0.5, 0.5}, {40, 20}, {10, 5}};
  const auto below = fit(single);
  EXPECT_EQ(below.status, FitStatus::single_level);
  EXPECT_TRUE(std::isnan(below.median));
  EXPECT_EQ(below.median_low, 0.5);  // p = 1/4 < 1/2: the median lies above the level
  EXPECT_TRUE(std::isinf(below.median_high));
  // Any curve through p = 1/4 at 0.5 attains the supremum: one such curve, by hand.
  const double beta = 0.3, median = 0.5 * std::exp(-beta * -0.6744897501960817);  // Phi^-1(1/4)
  EXPECT_NEAR(below.log_likelihood, independent_log_likelihood(single, median, beta), 1e-9);

  const auto half = fit({{0.5}, {40}, {20}});
  EXPECT_EQ(half.median_low, 0.5);
  EXPECT_EQ(half.median_high, 0.5);
}

// Zeros up to 0.6 and all exceedances from 0.7: ln L keeps rising as beta -> 0 with the median in
// between, towards 0; no finite estimate is the answer.
TEST(LognormalFit, ReportsSeparatedData) {
  const FragilityCounts separated{
      kBakerStripes.im, kBakerStripes.trials, {0, 0, 0, 0, 40, 40, 40, 40}};
  const auto result = fit(separated);
  EXPECT_EQ(result.status, FitStatus::separated);
  EXPECT_TRUE(std::isnan(result.median));
  EXPECT_TRUE(std::isnan(result.beta));
  EXPECT_EQ(result.median_low, 0.6);
  EXPECT_EQ(result.median_high, 0.7);
  EXPECT_EQ(result.log_likelihood, 0.0);
  double previous = -INFINITY;
  for (const double beta : {0.2, 0.1, 0.05, 0.02, 0.01}) {
    const double value = independent_log_likelihood(separated, std::sqrt(0.6 * 0.7), beta);
    EXPECT_GT(value, previous);
    EXPECT_LT(value, 0.0);
    previous = value;
  }
  EXPECT_GT(previous, -1e-6);
}

// One mixed level at the boundary (13 of 40 at 0.7): the curve tends to a step at 0.7 through
// p = 13/40 there; the supremum is that level's binomial log-likelihood at its own proportion.
TEST(LognormalFit, ReportsQuasiSeparatedDataWithTheBoundaryLevel) {
  const FragilityCounts data{kBakerStripes.im, kBakerStripes.trials, {0, 0, 0, 0, 13, 40, 40, 40}};
  const auto result = fit(data);
  EXPECT_EQ(result.status, FitStatus::separated);
  EXPECT_EQ(result.median_low, 0.7);
  EXPECT_EQ(result.median_high, 0.7);
  const double p = 13.0 / 40.0;
  const double expected = std::lgamma(41.0) - std::lgamma(14.0) - std::lgamma(28.0) +
                          13 * std::log(p) + 27 * std::log(1 - p);
  EXPECT_NEAR(result.log_likelihood, expected, 1e-10);
  const double beta = 1e-3,
               median = 0.7 * std::exp(beta * 0.4537621901698793);  // Phi(-0.45376...) = 13/40
  EXPECT_NEAR(independent_log_likelihood(data, median, beta), expected, 1e-6);
}

// Proportions falling with the intensity, either separated the wrong way (first case) or merely
// decreasing (second): the best increasing curve is flat at the overall proportion.
TEST(LognormalFit, ReportsDataWithoutAnIncreasingTrend) {
  for (const auto& z : {std::vector<std::int64_t>{40, 40, 40, 20, 0, 0, 0, 0},
                        std::vector<std::int64_t>{40, 40, 30, 20, 10, 0, 0, 0}}) {
    const FragilityCounts data{kBakerStripes.im, kBakerStripes.trials, z};
    const auto result = fit(data);
    EXPECT_EQ(result.status, FitStatus::no_trend);
    EXPECT_TRUE(std::isnan(result.median));
    double z_total = 0.0;
    for (const auto k : z) z_total += static_cast<double>(k);
    const double p = z_total / 320.0;
    double flat = 0.0;
    for (std::size_t j = 0; j < 8; ++j) {
      const double n = 40.0, k = static_cast<double>(z[j]);
      flat += std::lgamma(n + 1) - std::lgamma(k + 1) - std::lgamma(n - k + 1) + k * std::log(p) +
              (n - k) * std::log(1 - p);
    }
    EXPECT_NEAR(result.log_likelihood, flat, 1e-10);
    EXPECT_LT(independent_log_likelihood(data, 1.0, 0.4), flat);
    // Ever flatter curves through p = 140/320 at im = 1 approach the supremum, with a gap that
    // falls as 1 / beta (the first-order term): beta 4 times larger, gap 4 times smaller.
    ASSERT_EQ(z_total, 140.0);
    auto gap = [&](double beta) {
      const double median = std::exp(-beta * -0.15731068461017067);  // Phi^-1(0.4375)
      return flat - independent_log_likelihood(data, median, beta);
    };
    EXPECT_GT(gap(4000.0), 0.0);
    EXPECT_LT(gap(4000.0), 0.05);
    EXPECT_NEAR(gap(1000.0) / gap(4000.0), 4.0, 0.05);
  }
}

// The same proportion at every level: the maximum is exactly flat (beta = infinity, the median
// overflows), not an "ok" fit with a huge beta.
TEST(LognormalFit, ReportsEqualProportionsAsNoTrend) {
  const FragilityCounts data{{537.79, 3703.2}, {20, 10}, {4, 2}};
  const auto result = fit(data);
  EXPECT_EQ(result.status, FitStatus::no_trend);
  EXPECT_TRUE(std::isnan(result.median));
  EXPECT_TRUE(std::isnan(result.beta));
}

// The iteration limit ends the fit with a status, never with a half-converged estimate.
TEST(LognormalFit, ReportsTheIterationLimit) {
  const auto result = fit_lognormal_fragility(kBakerStripes.im, kBakerStripes.trials,
                                              kBakerStripes.exceedances, {1e-10, 1});
  EXPECT_EQ(result.status, FitStatus::not_converged);
  EXPECT_FALSE(result.converged);
  EXPECT_EQ(result.iterations, 1);
  EXPECT_TRUE(std::isnan(result.median));
  EXPECT_TRUE(std::isnan(result.beta));
}

TEST(LognormalFit, ReportsNoData) {
  const auto result = fit({{0.5, 1.0}, {0, 0}, {0, 0}});
  EXPECT_EQ(result.status, FitStatus::no_data);
  EXPECT_TRUE(std::isnan(result.median));
}

TEST(LognormalFit, RejectsInvalidData) {
  EXPECT_THROW(fit({{0.5, 1.0}, {10}, {1, 2}}), FitError);
  EXPECT_THROW(fit({{0.0, 1.0}, {10, 10}, {1, 2}}), FitError);
  EXPECT_THROW(fit({{-0.5, 1.0}, {10, 10}, {1, 2}}), FitError);
  EXPECT_THROW(fit({{NAN, 1.0}, {10, 10}, {1, 2}}), FitError);
  EXPECT_THROW(fit({{INFINITY, 1.0}, {10, 10}, {1, 2}}), FitError);
  EXPECT_THROW(fit({{0.5, 1.0}, {-1, 10}, {0, 2}}), FitError);
  EXPECT_THROW(fit({{0.5, 1.0}, {10, 10}, {11, 2}}), FitError);
  EXPECT_THROW(fit({{0.5, 1.0}, {10, 10}, {-1, 2}}), FitError);
  EXPECT_THROW(fit_lognormal_fragility(kBakerStripes.im, kBakerStripes.trials,
                                       kBakerStripes.exceedances, {0.0, 100}),
               FitError);
  EXPECT_THROW(lognormal_log_likelihood(kBakerStripes.im, kBakerStripes.trials,
                                        kBakerStripes.exceedances, 1.0, 0.0),
               FitError);
}

TEST(LognormalFit, NamesEveryStatus) {
  EXPECT_STREQ(fit_status_name(FitStatus::ok), "ok");
  EXPECT_STREQ(fit_status_name(FitStatus::separated), "separated");
  EXPECT_STREQ(fit_status_name(FitStatus::no_trend), "no_trend");
}

}  // namespace
}  // namespace blockfrag
