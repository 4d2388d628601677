// Binomial confidence intervals against the check values of docs/references.md, closed forms at
// the ends, the equations that define each interval (solved here independently of the code) and
// exact coverage.
#include "postproc/fragility/binomial_interval.hpp"

#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

namespace blockfrag {
namespace {

// Two-sided standard normal quantiles, to 16 digits (Abramowitz & Stegun 26.2 tables).
constexpr double z_90 = 1.6448536269514722;
constexpr double z_95 = 1.9599639845400542;
constexpr double z_99 = 2.5758293035489004;

// docs/references.md prints four digits: half a unit in the last one.
constexpr double kPrintedFourDigits = 0.5e-4;

// P(X = k) for X ~ Binomial(n, p), from log-gamma in long double.
long double binomial_pmf(std::int64_t k, std::int64_t n, long double p) {
  if (p <= 0.0L) return k == 0 ? 1.0L : 0.0L;
  if (p >= 1.0L) return k == n ? 1.0L : 0.0L;
  const long double log_pmf =
      std::lgamma(static_cast<long double>(n) + 1) - std::lgamma(static_cast<long double>(k) + 1) -
      std::lgamma(static_cast<long double>(n - k) + 1) + k * std::log(p) + (n - k) * std::log1p(-p);
  return std::exp(log_pmf);
}

long double binomial_at_least(std::int64_t x, std::int64_t n, long double p) {
  long double sum = 0.0L;
  for (std::int64_t k = x; k <= n; ++k) sum += binomial_pmf(k, n, p);
  return sum;
}

long double binomial_at_most(std::int64_t x, std::int64_t n, long double p) {
  long double sum = 0.0L;
  for (std::int64_t k = 0; k <= x; ++k) sum += binomial_pmf(k, n, p);
  return sum;
}

TEST(WilsonInterval, MatchesReferenceValues) {
  const auto a = wilson_interval(7, 20);
  EXPECT_NEAR(a.low, 0.1812, kPrintedFourDigits);
  EXPECT_NEAR(a.high, 0.5671, kPrintedFourDigits);
  const auto b = wilson_interval(16, 40);
  EXPECT_NEAR(b.low, 0.2635, kPrintedFourDigits);
  EXPECT_NEAR(b.high, 0.5540, kPrintedFourDigits);
  const auto c = wilson_interval(0, 40);
  EXPECT_EQ(c.low, 0.0);
  EXPECT_NEAR(c.high, 0.0876, kPrintedFourDigits);
}

// The Wilson bounds are the two roots in p of (x/n - p)^2 = z^2 p (1 - p) / n.
TEST(WilsonInterval, BoundsSolveTheScoreEquation) {
  for (const auto& [confidence, z] :
       std::vector<std::pair<double, double>>{{0.90, z_90}, {0.95, z_95}, {0.99, z_99}}) {
    for (const auto& [x, n] : std::vector<std::pair<std::int64_t, std::int64_t>>{
             {1, 3}, {7, 20}, {16, 40}, {123, 1000}}) {
      const auto interval = wilson_interval(x, n, confidence);
      const double p_hat = static_cast<double>(x) / static_cast<double>(n);
      for (const double p : {interval.low, interval.high}) {
        const double lhs = (p_hat - p) * (p_hat - p);
        const double rhs = z * z * p * (1.0 - p) / static_cast<double>(n);
        EXPECT_NEAR(lhs, rhs, 1e-14) << x << "/" << n << " at " << confidence;
      }
      EXPECT_LT(interval.low, p_hat);
      EXPECT_GT(interval.high, p_hat);
    }
  }
}

TEST(WilsonInterval, AllSuccessesReachOneExactly) {
  const auto interval = wilson_interval(40, 40);
  EXPECT_EQ(interval.high, 1.0);
  EXPECT_NEAR(interval.low, 1.0 - 0.0876, kPrintedFourDigits);  // the mirror of 0/40
}

TEST(ClopperPearsonInterval, MatchesReferenceValues) {
  const auto interval = clopper_pearson_interval(7, 20);
  EXPECT_NEAR(interval.low, 0.1539, kPrintedFourDigits);
  EXPECT_NEAR(interval.high, 0.5922, kPrintedFourDigits);
}

// With no successes the upper bound solves (1 - p)^n = alpha / 2; with all, the lower one p^n =
// alpha / 2.
TEST(ClopperPearsonInterval, MatchesClosedFormsAtTheEnds) {
  for (const std::int64_t n : {1, 5, 40, 1000, 100000}) {
    const double nn = static_cast<double>(n);
    const auto none = clopper_pearson_interval(0, n);
    EXPECT_EQ(none.low, 0.0);
    EXPECT_NEAR(none.high / -std::expm1(std::log(0.025) / nn), 1.0, 1e-12) << n;
    const auto all = clopper_pearson_interval(n, n);
    EXPECT_EQ(all.high, 1.0);
    EXPECT_NEAR(all.low, std::exp(std::log(0.025) / nn), 1e-14) << n;
  }
}

// The lower bound p_L solves P(X >= x | p_L) = alpha / 2 and the upper one P(X <= x | p_U) = alpha
// / 2, here summed term by term. 2 of 260 is a case where GSL's own beta quantile fails to
// converge.
TEST(ClopperPearsonInterval, BoundsSolveTheTailEquations) {
  for (const auto& [x, n] : std::vector<std::pair<std::int64_t, std::int64_t>>{
           {1, 2}, {7, 20}, {16, 40}, {2, 260}, {258, 260}, {7, 291}, {5, 10000}, {5000, 10000}}) {
    for (const double confidence : {0.9, 0.95, 0.99}) {
      const auto interval = clopper_pearson_interval(x, n, confidence);
      const long double tail = 0.5L * (1.0L - confidence);
      EXPECT_NEAR(static_cast<double>(binomial_at_least(x, n, interval.low) / tail), 1.0, 1e-9)
          << x << "/" << n;
      EXPECT_NEAR(static_cast<double>(binomial_at_most(x, n, interval.high) / tail), 1.0, 1e-9)
          << x << "/" << n;
    }
  }
}

// One success in 10^8: the lower bound is about -ln(1 - alpha/2) / n, far below anything an
// absolute tolerance would resolve; the root finder must keep its relative accuracy.
TEST(ClopperPearsonInterval, KeepsRelativeAccuracyForTinyProportions) {
  const std::int64_t n = 100000000;
  const auto interval = clopper_pearson_interval(1, n);
  // P(X >= 1 | p) = 1 - (1 - p)^n = 0.025 exactly solved:
  const double low = -std::expm1(std::log1p(-0.025) / static_cast<double>(n));
  EXPECT_NEAR(interval.low / low, 1.0, 1e-9);
}

// Exact coverage for n = 30 over a grid of p: Clopper-Pearson never falls below the nominal level,
// and Wilson stays close to it (its minimum over p dips below; the mean over p is near 0.95).
TEST(ClopperPearsonInterval, CoverageIsAtLeastNominalForEveryProportion) {
  const std::int64_t n = 30;
  std::vector<ProportionInterval> exact, wilson;
  for (std::int64_t x = 0; x <= n; ++x) {
    exact.push_back(clopper_pearson_interval(x, n));
    wilson.push_back(wilson_interval(x, n));
  }
  double wilson_mean = 0.0;
  const int points = 999;
  for (int i = 1; i <= points; ++i) {
    const double p = i / (points + 1.0);
    long double exact_coverage = 0.0L, wilson_coverage = 0.0L;
    for (std::int64_t x = 0; x <= n; ++x) {
      const auto xi = static_cast<std::size_t>(x);
      if (exact[xi].low <= p && p <= exact[xi].high) exact_coverage += binomial_pmf(x, n, p);
      if (wilson[xi].low <= p && p <= wilson[xi].high) wilson_coverage += binomial_pmf(x, n, p);
    }
    EXPECT_GE(static_cast<double>(exact_coverage), 0.95 - 1e-12) << p;
    wilson_mean += static_cast<double>(wilson_coverage) / points;
  }
  EXPECT_NEAR(wilson_mean, 0.95, 0.01);
}

TEST(BinomialInterval, IsSymmetricUnderSwappingSuccessesAndFailures) {
  for (const auto method : {IntervalMethod::wilson, IntervalMethod::clopper_pearson}) {
    for (std::int64_t x = 0; x <= 25; ++x) {
      const auto direct = binomial_interval(method, x, 25);
      const auto mirror = binomial_interval(method, 25 - x, 25);
      EXPECT_NEAR(direct.low, 1.0 - mirror.high, 1e-13) << x;
      EXPECT_NEAR(direct.high, 1.0 - mirror.low, 1e-13) << x;
    }
  }
}

TEST(BinomialInterval, DispatchesOnTheMethod) {
  const auto w = binomial_interval(IntervalMethod::wilson, 7, 20);
  const auto c = binomial_interval(IntervalMethod::clopper_pearson, 7, 20);
  EXPECT_NEAR(w.low, 0.1812, kPrintedFourDigits);
  EXPECT_NEAR(c.low, 0.1539, kPrintedFourDigits);
}

TEST(BinomialInterval, RejectsInvalidArguments) {
  for (const auto method : {IntervalMethod::wilson, IntervalMethod::clopper_pearson}) {
    EXPECT_THROW(binomial_interval(method, 0, 0), IntervalError);
    EXPECT_THROW(binomial_interval(method, -1, 10), IntervalError);
    EXPECT_THROW(binomial_interval(method, 11, 10), IntervalError);
    EXPECT_THROW(binomial_interval(method, 3, 10, 1.0), IntervalError);
    EXPECT_THROW(binomial_interval(method, 3, 10, 0.0), IntervalError);
    EXPECT_THROW(binomial_interval(method, 3, 10, std::nan("")), IntervalError);
  }
}

}  // namespace
}  // namespace blockfrag
