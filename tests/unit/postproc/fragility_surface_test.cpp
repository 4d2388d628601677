// The fragility surface's maximum-likelihood fit against data drawn from a known surface: exact
// proportions recover it, binomial draws (seeded) land within their standard errors of it, and
// those standard errors match the spread of estimates over repeated draws; each case without a
// maximum is reported as such; the gradient of a likelihood written here from the definition
// vanishes at the estimate.
#include "postproc/fragility/fragility_surface.hpp"

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "postproc/fragility/bootstrap.hpp"
#include "postproc/fragility/lognormal_fit.hpp"
#include "tests/support/fragility_draws.hpp"

namespace blockfrag {
namespace {

using testing::normal_cdf;

struct Grid {
  std::vector<double> im1, im2;
  std::vector<std::int64_t> trials, exceedances;
};

// A pulse-like truth: the median amplitude 0.8 g at a 1 s period falls as T^-0.5, beta 0.4:
// b = (-ln 0.8 / 0.4, 1 / 0.4, 0.5 / 0.4).
const std::array<double, 3> truth{-std::log(0.8) / 0.4, 2.5, 1.25};
using testing::kSurfaceAmplitudes;
using testing::kSurfacePeriods;

double true_probability(double x1, double x2) {
  return normal_cdf(truth[0] + truth[1] * std::log(x1) + truth[2] * std::log(x2));
}

// Every (amplitude, period) cell with n trials; exceedances from count(p).
template <class Count>
Grid grid_of(std::int64_t n, const Count& count) {
  Grid grid;
  for (const double x1 : kSurfaceAmplitudes) {
    for (const double x2 : kSurfacePeriods) {
      grid.im1.push_back(x1);
      grid.im2.push_back(x2);
      grid.trials.push_back(n);
      grid.exceedances.push_back(count(true_probability(x1, x2)));
    }
  }
  return grid;
}

// Binomial draws by inversion of uniforms from a seeded engine.
Grid drawn_grid(std::int64_t n, std::uint64_t seed) {
  std::mt19937_64 engine(seed);
  return grid_of(n, [&](double p) {
    const double u = (static_cast<double>(engine() >> 11) + 0.5) * 0x1p-53;
    return binomial_quantile(u, n, p);
  });
}

SurfaceFit fit_surface(const Grid& g) {
  return fit_fragility_surface(g.im1, g.im2, g.trials, g.exceedances);
}

// ln L from the definition, without the binomial coefficients.
double independent_log_likelihood(const Grid& g, const std::array<double, 3>& b) {
  double sum = 0.0;
  for (std::size_t j = 0; j < g.im1.size(); ++j) {
    const double p = normal_cdf(b[0] + b[1] * std::log(g.im1[j]) + b[2] * std::log(g.im2[j]));
    const double n = static_cast<double>(g.trials[j]), z = static_cast<double>(g.exceedances[j]);
    if (z > 0) sum += z * std::log(p);
    if (n > z) sum += (n - z) * std::log(1.0 - p);
  }
  return sum;
}

TEST(FragilitySurface, RecoversTheSurfaceFromExactProportions) {
  // 10^8 trials a cell: the rounding of the counts moves each proportion by at most 5e-9.
  const Grid g = grid_of(100'000'000, [](double p) { return std::llround(1e8 * p); });
  const SurfaceFit r = fit_surface(g);
  ASSERT_EQ(r.status, SurfaceFitStatus::ok);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(r.coefficients[i], truth[i], 1e-5) << i;
  EXPECT_NEAR(r.beta1, 0.4, 1e-6);
  EXPECT_NEAR(r.ln_median_intercept, std::log(0.8), 1e-6);
  EXPECT_NEAR(r.ln_median_slope, -0.5, 1e-6);
  EXPECT_NEAR(r.median_im1(2.0), 0.8 / std::sqrt(2.0), 1e-6);
  EXPECT_NEAR(r.probability(r.median_im1(0.7), 0.7), 0.5, 1e-12);
  EXPECT_LE(r.newton_decrement, 1e-10);
}

TEST(FragilitySurface, GradientOfAnIndependentLikelihoodVanishesAtTheEstimate) {
  const Grid g = drawn_grid(200, 1);
  const SurfaceFit r = fit_surface(g);
  ASSERT_EQ(r.status, SurfaceFitStatus::ok);
  // Central differences of ln L ~ 1e3 with h = 1e-6 are good to about 1e-7.
  const auto slope_at = [&](std::array<double, 3> b, int i) {
    const double h = 1e-6;
    auto plus = b, minus = b;
    plus[i] += h;
    minus[i] -= h;
    return (independent_log_likelihood(g, plus) - independent_log_likelihood(g, minus)) / (2 * h);
  };
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(slope_at(r.coefficients, i), 0.0, 1e-4) << i;
    // One standard error away the slope is about 1 / SE (more when b_i correlates with the
    // others): the check can fail.
    auto off = r.coefficients;
    off[i] += r.standard_errors[i];
    EXPECT_LT(slope_at(off, i), -0.5 / r.standard_errors[i]) << i;
  }
}

TEST(FragilitySurface, TruthLiesWithinThreeStandardErrorsOfDrawnData) {
  for (const std::uint64_t seed : {11u, 12u, 13u, 14u, 15u}) {
    const SurfaceFit r = fit_surface(drawn_grid(200, seed));
    ASSERT_EQ(r.status, SurfaceFitStatus::ok) << seed;
    for (int i = 0; i < 3; ++i) {
      EXPECT_LT(std::abs(r.coefficients[i] - truth[i]), 3 * r.standard_errors[i])
          << "seed " << seed << " b" << i << " = " << r.coefficients[i] << " +- "
          << r.standard_errors[i] << ", true " << truth[i];
    }
    EXPECT_LT(std::abs(r.beta1 - 0.4), 3 * r.beta1_se) << seed;
    EXPECT_LT(std::abs(r.ln_median_slope + 0.5), 3 * r.ln_median_slope_se) << seed;
  }
}

TEST(FragilitySurface, StandardErrorsMatchTheSpreadOfRepeatedDraws) {
  // 400 draws: the sample standard deviation is good to about 1 / sqrt(800) = 3.5 %; 15 % is
  // four of those. The mean estimate lies within 4 standard errors of the mean (SE / 20) of the
  // truth (the bias of the maximum likelihood at 200 trials a cell is far smaller).
  constexpr int draws = 400;
  std::array<double, 3> sum{}, sum_squares{}, se_sum{};
  for (int k = 0; k < draws; ++k) {
    const SurfaceFit r = fit_surface(drawn_grid(200, 1000 + static_cast<std::uint64_t>(k)));
    ASSERT_EQ(r.status, SurfaceFitStatus::ok) << k;
    for (int i = 0; i < 3; ++i) {
      sum[i] += r.coefficients[i];
      sum_squares[i] += r.coefficients[i] * r.coefficients[i];
      se_sum[i] += r.standard_errors[i];
    }
  }
  for (int i = 0; i < 3; ++i) {
    const double mean = sum[i] / draws;
    const double spread = std::sqrt((sum_squares[i] - draws * mean * mean) / (draws - 1));
    const double se = se_sum[i] / draws;
    EXPECT_NEAR(spread / se, 1.0, 0.15) << "b" << i << ": spread " << spread << ", SE " << se;
    EXPECT_NEAR(mean, truth[i], 4 * se / std::sqrt(draws)) << "b" << i;
  }
}

TEST(FragilitySurface, ReportsSeparatedData) {
  // Every cell above the line ln x1 + ln x2 = 0 exceeds, every one below does not: the
  // likelihood grows without bound as the surface steepens.
  Grid g = grid_of(50, [](double) { return 0; });
  for (std::size_t j = 0; j < g.im1.size(); ++j) {
    if (std::log(g.im1[j]) + std::log(g.im2[j]) > 0) g.exceedances[j] = 50;
  }
  EXPECT_EQ(fit_surface(g).status, SurfaceFitStatus::separated);
  // Quasi-complete: the cells on the line (x1 x2 = 1 at (2, 0.5) and (1, 1) if present) may mix.
  g.im1.push_back(1.0);
  g.im2.push_back(1.0);
  g.trials.push_back(50);
  g.exceedances.push_back(20);
  EXPECT_EQ(fit_surface(g).status, SurfaceFitStatus::separated);
  // One cell below the line with an exceedance breaks the separation: a maximum exists again.
  g.exceedances[0] = 1;
  EXPECT_EQ(fit_surface(g).status, SurfaceFitStatus::ok);
}

TEST(FragilitySurface, ReportsDataWithoutAMaximum) {
  EXPECT_EQ(fit_surface(grid_of(40, [](double) { return 0; })).status,
            SurfaceFitStatus::no_exceedances);
  EXPECT_EQ(fit_surface(grid_of(40, [](double) { return 40; })).status,
            SurfaceFitStatus::all_exceedances);
  EXPECT_EQ(fit_surface(Grid{}).status, SurfaceFitStatus::no_data);
  // One period: the cells lie on a line, b2 is not identified.
  Grid one_period = drawn_grid(200, 3);
  for (double& x2 : one_period.im2) x2 = 1.0;
  EXPECT_EQ(fit_surface(one_period).status, SurfaceFitStatus::collinear);
  const SurfaceFit none = fit_surface(one_period);
  EXPECT_TRUE(std::isnan(none.coefficients[1]));
  EXPECT_TRUE(std::isnan(none.median_im1(1.0)));
}

TEST(FragilitySurface, AFallingSurfaceIsNotAFragility) {
  // The amplitudes reversed: P falls with IM1. The maximum exists, with b1 < 0.
  Grid g = drawn_grid(200, 5);
  for (double& x1 : g.im1) x1 = 1.0 / x1;
  const SurfaceFit r = fit_surface(g);
  EXPECT_EQ(r.status, SurfaceFitStatus::not_increasing);
  EXPECT_LT(r.coefficients[1], 0.0);
  EXPECT_TRUE(std::isnan(r.beta1));
}

TEST(FragilitySurface, RefusesInvalidCounts) {
  Grid g = drawn_grid(10, 1);
  g.exceedances[3] = 11;
  EXPECT_THROW(fit_surface(g), FitError);
  g = drawn_grid(10, 1);
  g.im2[0] = 0.0;
  EXPECT_THROW(fit_surface(g), FitError);
  g.im2.pop_back();
  EXPECT_THROW(fit_surface(g), FitError);
}

}  // namespace
}  // namespace blockfrag
