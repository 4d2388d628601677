// The limit states as a set of curves: crossing_intensity against the two lognormal CDFs evaluated
// here with std::erfc (equal at the returned x, in opposite order on either side of it);
// severity_order against orders written out by hand, for fitted medians, ties, and curves without
// a fit placed by where their data put the median; crossing_pairs against crossings placed inside
// and outside the range by construction.
#include "postproc/fragility/curve_set.hpp"

#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

namespace blockfrag {
namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();
constexpr double inf = std::numeric_limits<double>::infinity();

double lognormal_cdf(double x, double median, double beta) {
  return 0.5 * std::erfc(-std::log(x / median) / (beta * std::sqrt(2.0)));
}

FragilityCurve fitted(double median, double beta) {
  FragilityCurve curve{};
  curve.median = median;
  curve.beta = beta;
  curve.fit_status = "ok";
  curve.median_low = curve.median_high = median;
  return curve;
}

FragilityCurve unfitted(const char* status, double median_low, double median_high) {
  FragilityCurve curve{};
  curve.median = curve.beta = nan;
  curve.fit_status = status;
  curve.median_low = median_low;
  curve.median_high = median_high;
  return curve;
}

TEST(CrossingIntensity, TheTwoCurvesAreEqualThereAndSwapOrder) {
  struct Pair {
    double m1, b1, m2, b2;
  };
  for (const Pair& c : {Pair{1.0, 0.3, 1.2, 0.6}, Pair{0.5, 0.2, 2.0, 0.8},
                        Pair{3.0, 0.9, 0.7, 0.35}, Pair{0.02, 0.25, 0.05, 0.5}}) {
    const double x = crossing_intensity(c.m1, c.b1, c.m2, c.b2);
    ASSERT_TRUE(std::isfinite(x) && x > 0) << x;
    const double p1 = lognormal_cdf(x, c.m1, c.b1), p2 = lognormal_cdf(x, c.m2, c.b2);
    EXPECT_NEAR(p1, p2, 1e-13) << c.m1 << " " << c.m2;
    // A crossing, not a touch: the order of the curves changes across x.
    const double below = lognormal_cdf(x / 1.05, c.m1, c.b1) - lognormal_cdf(x / 1.05, c.m2, c.b2);
    const double above = lognormal_cdf(x * 1.05, c.m1, c.b1) - lognormal_cdf(x * 1.05, c.m2, c.b2);
    EXPECT_LT(below * above, 0.0) << below << " " << above;
    // The same point whichever curve comes first.
    EXPECT_NEAR(crossing_intensity(c.m2, c.b2, c.m1, c.b1), x, 1e-14 * x);
  }
}

TEST(CrossingIntensity, CurvesWithOneMedianCrossAtItAndParallelOnesNever) {
  // Every lognormal curve is 1/2 at its median.
  EXPECT_NEAR(crossing_intensity(1.7, 0.3, 1.7, 0.6), 1.7, 1e-14);
  // Equal betas: the curves are shifted copies, with no crossing.
  EXPECT_TRUE(std::isnan(crossing_intensity(1.0, 0.4, 2.0, 0.4)));
  EXPECT_TRUE(std::isnan(crossing_intensity(2.0, 0.4, 1.0, 0.4)));
}

TEST(SeverityOrder, SortsFittedCurvesByMedianAndKeepsTiesInTheirOrder) {
  const std::vector<FragilityCurve> curves{fitted(2.0, 0.4), fitted(1.0, 0.3), fitted(3.0, 0.5),
                                           fitted(1.0, 0.6), fitted(0.5, 0.2)};
  EXPECT_EQ(severity_order(curves), (std::vector<std::size_t>{4, 1, 3, 0, 2}));
  EXPECT_TRUE(severity_order({}).empty());
}

TEST(SeverityOrder, PlacesCurvesWithoutAFitByTheMiddleOfTheirMedianBoundsInLogs) {
  // separated over (1.5, 3): the middle in logs is sqrt(4.5) = 2.12, between 2 and 4. separated
  // over (1, 4): the middle is 2 exactly, a tie with the fitted 2, after which it goes although it
  // comes first. no_exceedances at a largest level of 5 (5, inf): at 5, above the fitted 4.
  // all_exceedances below a smallest level of 0.3 (0, 0.3): at 0.3, below the fitted 1.
  ASSERT_EQ(0.5 * (std::log(1.0) + std::log(4.0)), std::log(2.0));  // the tie is exact
  const std::vector<FragilityCurve> curves{
      unfitted("separated", 1.0, 4.0),        // 0: at 2, after 3
      fitted(4.0, 0.5),                       // 1
      unfitted("separated", 1.5, 3.0),        // 2: at 2.12
      fitted(2.0, 0.5),                       // 3
      unfitted("no_exceedances", 5.0, inf),   // 4: at 5
      fitted(1.0, 0.5),                       // 5
      unfitted("all_exceedances", 0.0, 0.3),  // 6: at 0.3
  };
  EXPECT_EQ(severity_order(curves), (std::vector<std::size_t>{6, 5, 3, 0, 2, 1, 4}));
}

TEST(CrossingPairs, ReportsOnlyFittedCurvesThatCrossInsideTheRange) {
  // 0 (1, 0.3) and 1 (1.2, 0.6) cross at exp((0.6 ln 1 - 0.3 ln 1.2) / 0.3) = 1 / 1.2; 1 and 3
  // (3, 0.3) at exp((0.3 ln 1.2 - 0.6 ln 3) / -0.3) = 9 / 1.2 = 7.5; 0 and 3 are parallel; 0 and
  // 4 (2, 0.15) at exp((0.15 ln 1 - 0.3 ln 2) / -0.15) = 4; 1 and 4 at
  // exp((0.15 ln 1.2 - 0.6 ln 2) / -0.45) = 2^(4/3) / 1.2^(1/3) = 2.37; 3 and 4 at
  // exp((0.15 ln 3 - 0.3 ln 2) / -0.15) = 4 / 3. Curve 2 has no fit.
  const std::vector<FragilityCurve> curves{fitted(1.0, 0.3), fitted(1.2, 0.6),
                                           unfitted("separated", 0.9, 1.1), fitted(3.0, 0.3),
                                           fitted(2.0, 0.15)};
  ASSERT_NEAR(crossing_intensity(1.0, 0.3, 1.2, 0.6), 1 / 1.2, 1e-14);
  ASSERT_NEAR(crossing_intensity(1.2, 0.6, 3.0, 0.3), 7.5, 1e-13);
  ASSERT_NEAR(crossing_intensity(1.0, 0.3, 2.0, 0.15), 4.0, 1e-14);
  ASSERT_NEAR(crossing_intensity(1.2, 0.6, 2.0, 0.15), std::cbrt(16.0 / 1.2), 1e-14);
  ASSERT_NEAR(crossing_intensity(3.0, 0.3, 2.0, 0.15), 4.0 / 3.0, 1e-14);
  using Pairs = std::vector<std::pair<std::size_t, std::size_t>>;
  EXPECT_EQ(crossing_pairs(curves, 0.1, 10.0), (Pairs{{0, 1}, {0, 4}, {1, 3}, {1, 4}, {3, 4}}));
  EXPECT_EQ(crossing_pairs(curves, 0.9, 3.0), (Pairs{{1, 4}, {3, 4}}));
  EXPECT_EQ(crossing_pairs(curves, 1.5, 2.2), Pairs{});
  // The range's ends belong to it.
  const double x = crossing_intensity(1.0, 0.3, 2.0, 0.15);
  EXPECT_EQ(crossing_pairs(curves, x, 5.0), (Pairs{{0, 4}}));
  EXPECT_EQ(crossing_pairs(curves, 2.5, x), (Pairs{{0, 4}}));
}

}  // namespace
}  // namespace blockfrag
