// A surface's grid: each cell's counts, proportion and Wilson interval in row-by-row order, the
// fit over the cells' coordinates, the sums over the second measure, and the goodness of fit:
// on data drawn from a probit surface the deviance averages its degrees of freedom (cells - 3)
// and the p-values fall below 0.05 about 5 % of the time; on data from another shape they do not.
#include "postproc/fragility/surface_grid.hpp"

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "postproc/fragility/binomial_interval.hpp"
#include "postproc/fragility/bootstrap.hpp"
#include "tests/support/fragility_draws.hpp"

namespace blockfrag {
namespace {

using testing::normal_cdf;

using testing::kSurfaceAmplitudes;
using testing::kSurfacePeriods;

// n trials a cell, row by row, from probability(x1, x2) by inversion of seeded uniforms.
template <class Probability>
SurfaceGrid drawn(std::uint64_t seed, std::int64_t n, const Probability& probability) {
  std::mt19937_64 engine(seed);
  std::vector<std::int64_t> trials, exceedances;
  for (const double x1 : kSurfaceAmplitudes) {
    for (const double x2 : kSurfacePeriods) {
      const double u = (static_cast<double>(engine() >> 11) + 0.5) * 0x1p-53;
      trials.push_back(n);
      exceedances.push_back(binomial_quantile(u, n, probability(x1, x2)));
    }
  }
  return surface_from_counts(kSurfaceAmplitudes, kSurfacePeriods, trials, exceedances);
}

double probit_surface(double x1, double x2) {
  return normal_cdf((std::log(x1 / 0.8) + 0.5 * std::log(x2)) / 0.4);
}

TEST(SurfaceGrid, KeepsEachCellInRowOrderWithItsInterval) {
  const SurfaceGrid grid = drawn(3, 100, probit_surface);
  ASSERT_EQ(grid.trials.size(), kSurfaceAmplitudes.size() * kSurfacePeriods.size());
  for (std::size_t k1 = 0; k1 < kSurfaceAmplitudes.size(); ++k1) {
    for (std::size_t k2 = 0; k2 < kSurfacePeriods.size(); ++k2) {
      const std::size_t c = k1 * kSurfacePeriods.size() + k2;
      EXPECT_EQ(grid.probability[c], static_cast<double>(grid.exceedances[c]) / 100.0);
      const ProportionInterval wilson = wilson_interval(grid.exceedances[c], 100);
      EXPECT_EQ(grid.ci_low[c], wilson.low);
      EXPECT_EQ(grid.ci_high[c], wilson.high);
    }
  }
  // The fit is over each cell's own (amplitude, period): the same as fitting the cells directly.
  std::vector<double> x1, x2;
  for (const double a : kSurfaceAmplitudes) {
    for (const double t : kSurfacePeriods) {
      x1.push_back(a);
      x2.push_back(t);
    }
  }
  const SurfaceFit direct = fit_fragility_surface(x1, x2, grid.trials, grid.exceedances);
  EXPECT_EQ(grid.fit.coefficients, direct.coefficients);
  // A grid with a cell without trials: NaN there, the rest fitted.
  std::vector<std::int64_t> trials = grid.trials, exceedances = grid.exceedances;
  trials[4] = exceedances[4] = 0;
  const SurfaceGrid holed =
      surface_from_counts(kSurfaceAmplitudes, kSurfacePeriods, trials, exceedances);
  EXPECT_TRUE(std::isnan(holed.probability[4]) && std::isnan(holed.ci_low[4]));
  EXPECT_EQ(holed.gof.dof, 30 - 1 - 3);
}

TEST(SurfaceGrid, SumsEachFirstLevelOverTheSecond) {
  EXPECT_EQ(summed_over_im2({1, 2, 3, 4, 5, 6}, 3), (std::vector<std::int64_t>{6, 15}));
  EXPECT_EQ(summed_over_im2({1, 2, 3, 4, 5, 6}, 2), (std::vector<std::int64_t>{3, 7, 11}));
}

TEST(SurfaceGrid, DevianceOfProbitDataAveragesItsDegreesOfFreedom) {
  // 300 draws of 30 cells: dof 27, the mean deviance's standard error sqrt(2 27 / 300) = 0.42;
  // 4 of them is 1.7. The fraction of p < 0.05 is 0.05 +- 0.0126: within 0.02 to 0.09.
  constexpr int draws = 300;
  double sum = 0.0;
  int rejected = 0;
  for (int k = 0; k < draws; ++k) {
    const SurfaceGrid grid = drawn(500 + static_cast<std::uint64_t>(k), 200, probit_surface);
    ASSERT_EQ(grid.fit.status, SurfaceFitStatus::ok);
    ASSERT_EQ(grid.gof.dof, 27);
    sum += grid.gof.deviance;
    if (grid.gof.p_value < 0.05) ++rejected;
  }
  EXPECT_NEAR(sum / draws, 27.0, 1.7);
  EXPECT_GE(rejected, 6);
  EXPECT_LE(rejected, 27);
}

TEST(SurfaceGrid, RejectsDataOfAnotherShape) {
  // The probability steps with the period instead of following a probit in ln T.
  const SurfaceGrid grid = drawn(7, 200, [](double x1, double x2) {
    return normal_cdf(std::log(x1 / (x2 < 1.2 ? 1.2 : 0.5)) / 0.3);
  });
  ASSERT_EQ(grid.fit.status, SurfaceFitStatus::ok);
  EXPECT_LT(grid.gof.p_value, 1e-6);
  EXPECT_GT(grid.gof.max_misfit, 0.1);
  // Without a fit there is no goodness of fit.
  const SurfaceGrid none = drawn(7, 50, [](double, double) { return 0.0; });
  EXPECT_EQ(none.fit.status, SurfaceFitStatus::no_exceedances);
  EXPECT_EQ(none.gof.dof, 0);
  EXPECT_TRUE(std::isnan(none.gof.deviance) && std::isnan(none.gof.p_value));
}

}  // namespace
}  // namespace blockfrag
