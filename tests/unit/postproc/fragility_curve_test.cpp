// A fragility curve from counts: the per-level probabilities and Wilson intervals (checked against
// the interval's closed form), levels without trials, and the fit's outcome carried into the curve.
#include "postproc/fragility/fragility_curve.hpp"

#include <cmath>
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "postproc/fragility/lognormal_fit.hpp"

namespace blockfrag {
namespace {

// Wilson's score interval written out: centre (p + z^2/2n) / (1 + z^2/n), half-width
// z sqrt(p (1 - p) / n + z^2 / 4n^2) / (1 + z^2/n), z = 1.959963985 for 95 %.
std::pair<double, double> wilson(double z_count, double n) {
  const double z = 1.959963984540054, p = z_count / n, d = 1.0 + z * z / n;
  const double centre = (p + z * z / (2.0 * n)) / d;
  const double half = z * std::sqrt(p * (1.0 - p) / n + z * z / (4.0 * n * n)) / d;
  return {centre - half, centre + half};
}

TEST(FragilityFromCounts, ProbabilitiesAndWilsonIntervalsPerLevel) {
  const auto curve = fragility_from_counts({0.5, 1.0, 2.0}, {10, 10, 40}, {0, 3, 38});
  ASSERT_EQ(curve.probability.size(), 3u);
  EXPECT_DOUBLE_EQ(curve.probability[0], 0.0);
  EXPECT_DOUBLE_EQ(curve.probability[1], 0.3);
  EXPECT_DOUBLE_EQ(curve.probability[2], 0.95);
  const std::vector<std::pair<double, double>> expected{wilson(0, 10), wilson(3, 10),
                                                        wilson(38, 40)};
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_NEAR(curve.ci_low[k], expected[k].first, 1e-12) << k;
    EXPECT_NEAR(curve.ci_high[k], expected[k].second, 1e-12) << k;
  }
  EXPECT_NEAR(curve.ci_low[1], 0.1078, 1e-4);  // the textbook interval for 3 of 10
  EXPECT_NEAR(curve.ci_high[1], 0.6032, 1e-4);
}

TEST(FragilityFromCounts, TheFitIsTheLognormalFitOfTheSameCounts) {
  const std::vector<double> im{0.2, 0.3, 0.4, 0.6, 0.7, 0.8, 0.9, 1.0};
  const std::vector<std::int64_t> trials(8, 40), exceedances{0, 0, 0, 4, 6, 13, 12, 16};
  const auto curve = fragility_from_counts(im, trials, exceedances);
  const auto fit = fit_lognormal_fragility(im, trials, exceedances);
  ASSERT_EQ(fit.status, FitStatus::ok);
  EXPECT_EQ(curve.fit_status, "ok");
  EXPECT_EQ(curve.median, fit.median);
  EXPECT_EQ(curve.beta, fit.beta);
  EXPECT_EQ(curve.log_likelihood, fit.log_likelihood);
  EXPECT_EQ(curve.im, im);
  EXPECT_EQ(curve.trials, trials);
  EXPECT_EQ(curve.exceedances, exceedances);
}

TEST(FragilityFromCounts, ALevelWithoutTrialsHasNoProbabilityAndNoFitMeansNaNs) {
  const auto curve = fragility_from_counts({0.5, 1.0}, {0, 20}, {0, 0});
  EXPECT_TRUE(std::isnan(curve.probability[0]));
  EXPECT_TRUE(std::isnan(curve.ci_low[0]));
  EXPECT_TRUE(std::isnan(curve.ci_high[0]));
  EXPECT_DOUBLE_EQ(curve.probability[1], 0.0);
  EXPECT_EQ(curve.fit_status, "no_exceedances");
  EXPECT_TRUE(std::isnan(curve.median));
  EXPECT_TRUE(std::isnan(curve.beta));
  EXPECT_TRUE(std::isnan(curve.log_likelihood));
}

}  // namespace
}  // namespace blockfrag
