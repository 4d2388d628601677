// Where an adaptive study's next batch goes: the pair placed where the fitted curve is the design's
// p and 1 - p (the default and the D-optimal pair, found by maximising the probit's Fisher
// information numerically), the median's interval width from its standard error, the stopping
// rules, and the bracketing batches when there is no fit yet.
#include "mpi_driver/study/adaptive_levels.hpp"

#include <cmath>
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "postproc/fragility/fragility_curve.hpp"

namespace blockfrag {
namespace {

double normal_cdf(double z) { return 0.5 * std::erfc(-z / std::sqrt(2.0)); }
double normal_pdf(double z) { return std::exp(-0.5 * z * z) / std::sqrt(2.0 * M_PI); }

// With n samples at each of the standardised levels -z and +z, the probit's information matrix
// for (location, scale) is diagonal with entries proportional to 2 w(z) and 2 z^2 w(z), w the
// binomial weight phi^2 / (Phi (1 - Phi)): its determinant is proportional to (z w(z))^2.
double information_determinant_root(double z) {
  const double p = normal_cdf(z);
  return z * normal_pdf(z) * normal_pdf(z) / (p * (1.0 - p));
}

AdaptiveDesign design_with(double target, std::int64_t budget) {
  AdaptiveDesign design;
  design.limit_state = "overturn";
  design.target_relative_width = target;
  design.max_samples = budget;
  return design;
}

// Counts that follow a lognormal curve exactly enough for its fit to exist.
FragilityCurve lognormal_counts(double median, double beta, std::int64_t per_level) {
  const std::vector<double> levels{0.25, 0.5, 1.0, 2.0, 4.0};
  std::vector<std::int64_t> trials, exceedances;
  for (const double level : levels) {
    trials.push_back(per_level);
    const double p = normal_cdf(std::log(level / median) / beta);
    exceedances.push_back(std::llround(p * static_cast<double>(per_level)));
  }
  return fragility_from_counts(levels, trials, exceedances);
}

TEST(AdaptiveLevels, TheRelativeWidthIsTheMediansLognormalInterval) {
  FragilityCurve curve = lognormal_counts(1.0, 0.5, 1000);
  ASSERT_EQ(curve.fit_status, "ok");
  curve.median = 2.0;
  curve.median_se = 0.1;
  EXPECT_NEAR(median_relative_width(curve), std::exp(1.96 * 0.05) - std::exp(-1.96 * 0.05), 1e-15);
  curve.fit_status = "separated";
  EXPECT_TRUE(std::isnan(median_relative_width(curve)));
}

// The maximum of (z w(z))^2 over z, by scanning.
double d_optimal_z() {
  double best_z = 0.0, best = 0.0;
  for (double z = 0.5; z < 2.0; z += 1e-5) {
    if (information_determinant_root(z) > best) {
      best = information_determinant_root(z);
      best_z = z;
    }
  }
  return best_z;
}

TEST(AdaptiveLevels, TheNextPairSitsWhereTheFitIsTheDesignsProbabilities) {
  const FragilityCurve curve = lognormal_counts(1.3, 0.6, 400);
  ASSERT_EQ(curve.fit_status, "ok");
  const auto fitted = [&](double im) {
    return normal_cdf(std::log(im / curve.median) / curve.beta);
  };
  AdaptiveDesign design = design_with(1e-6, 1'000'000);
  // The default is the D-optimal pair.
  const double d_optimal = 1.0 - normal_cdf(d_optimal_z());
  EXPECT_NEAR(design.pair_probability, d_optimal, 1e-3);
  for (const double p : {d_optimal, 0.3}) {
    design.pair_probability = p;
    const BatchDecision next = decide_next_batch(design, curve, curve.im, 2000, 800, 10.0);
    ASSERT_FALSE(next.stop);
    ASSERT_EQ(next.next_levels.size(), 2u);
    EXPECT_NEAR(fitted(next.next_levels[0]), p, 1e-12);
    EXPECT_NEAR(fitted(next.next_levels[1]), 1.0 - p, 1e-12);
    EXPECT_EQ(next.relative_width, median_relative_width(curve));
  }
}

TEST(AdaptiveLevels, LevelsStayBelowTheMeasuresLargest) {
  const FragilityCurve curve = lognormal_counts(1.3, 0.6, 400);
  const BatchDecision next =
      decide_next_batch(design_with(1e-6, 1'000'000), curve, curve.im, 2000, 800, 1.5);
  ASSERT_FALSE(next.stop);
  EXPECT_LT(next.next_levels[0], 1.3);
  EXPECT_EQ(next.next_levels[1], 1.5);
}

TEST(AdaptiveLevels, StopsAtTheTargetBeforeLookingAtTheBudget) {
  const FragilityCurve curve = lognormal_counts(1.3, 0.6, 400);
  const double width = median_relative_width(curve);
  const BatchDecision reached =
      decide_next_batch(design_with(width * 1.01, 2000), curve, curve.im, 2000, 800, 10.0);
  EXPECT_TRUE(reached.stop);
  EXPECT_EQ(reached.reason, "target reached");
  const BatchDecision spent =
      decide_next_batch(design_with(width * 0.99, 2799), curve, curve.im, 2000, 800, 10.0);
  EXPECT_TRUE(spent.stop);
  EXPECT_EQ(spent.reason, "budget spent");
  const BatchDecision fits =
      decide_next_batch(design_with(width * 0.99, 2800), curve, curve.im, 2000, 800, 10.0);
  EXPECT_FALSE(fits.stop);
}

TEST(AdaptiveLevels, WithoutExceedancesTheBatchLooksFurtherUp) {
  const std::vector<double> levels{0.2, 0.4};
  const FragilityCurve curve = fragility_from_counts(levels, {100, 100}, {0, 0});
  ASSERT_NE(curve.fit_status, "ok");
  const BatchDecision next =
      decide_next_batch(design_with(0.05, 10'000), curve, levels, 200, 200, 5.0);
  ASSERT_FALSE(next.stop);
  EXPECT_TRUE(std::isnan(next.relative_width));
  EXPECT_DOUBLE_EQ(next.next_levels[0], 0.8);
  EXPECT_DOUBLE_EQ(next.next_levels[1], 1.6);
}

TEST(AdaptiveLevels, StopsWhenNothingExceedsAtTheLargestLevel) {
  const std::vector<double> levels{1.0, 2.5};
  const FragilityCurve curve = fragility_from_counts(levels, {100, 100}, {0, 0});
  const BatchDecision next =
      decide_next_batch(design_with(0.05, 10'000), curve, levels, 200, 200, 2.5);
  EXPECT_TRUE(next.stop);
  EXPECT_EQ(next.reason, "no exceedance up to the measure's largest level");
  const BatchDecision below =
      decide_next_batch(design_with(0.05, 10'000), curve, {1.0, 2.0}, 200, 200, 2.5);
  EXPECT_FALSE(below.stop);
  EXPECT_EQ(below.next_levels, (std::vector<double>{2.5, 2.5}));
}

TEST(AdaptiveLevels, WhenEverythingExceededTheBatchLooksFurtherDown) {
  const std::vector<double> levels{0.4, 0.8};
  const FragilityCurve curve = fragility_from_counts(levels, {100, 100}, {100, 100});
  ASSERT_NE(curve.fit_status, "ok");
  const BatchDecision next =
      decide_next_batch(design_with(0.05, 10'000), curve, levels, 200, 200, 5.0);
  ASSERT_FALSE(next.stop);
  EXPECT_DOUBLE_EQ(next.next_levels[0], 0.1);
  EXPECT_DOUBLE_EQ(next.next_levels[1], 0.2);
}

TEST(AdaptiveLevels, SeparatedDataAreSplitBetweenTheirLevels) {
  const std::vector<double> levels{0.5, 2.0};
  const FragilityCurve curve = fragility_from_counts(levels, {100, 100}, {0, 100});
  ASSERT_NE(curve.fit_status, "ok");
  const BatchDecision next =
      decide_next_batch(design_with(0.05, 10'000), curve, levels, 200, 200, 5.0);
  ASSERT_FALSE(next.stop);
  for (const double level : next.next_levels) {
    EXPECT_GT(level, 0.5);
    EXPECT_LT(level, 2.0);
  }
  EXPECT_NEAR(next.next_levels[0], std::pow(0.5, 2.0 / 3.0) * std::pow(2.0, 1.0 / 3.0), 1e-12);
  EXPECT_NEAR(next.next_levels[1], std::pow(0.5, 1.0 / 3.0) * std::pow(2.0, 2.0 / 3.0), 1e-12);
}

}  // namespace
}  // namespace blockfrag
