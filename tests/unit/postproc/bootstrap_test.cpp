// The bootstrap against what it must reproduce: binomial_quantile against GSL's binomial CDF (in
// the tail where u lies) and against the binomial's mean and variance; the intervals against the
// standard errors of the observed information (a 95 % interval about 3.92 SE wide), against the
// true median of synthetic data (coverage about 95 %), and against refits of resamples chosen here
// through the uniforms; the band against its definition (200 points, the refitted curves' pointwise
// quantiles, whose 1/2 crossings are the median's interval).
#include "postproc/fragility/bootstrap.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include <gsl/gsl_cdf.h>
#include <gtest/gtest.h>

#include "postproc/fragility/cloud_fragility.hpp"
#include "postproc/fragility/fit_diagnostics.hpp"
#include "postproc/fragility/lognormal_fit.hpp"
#include "postproc/fragility/sample_quantile.hpp"
#include "tests/support/fragility_draws.hpp"

namespace blockfrag {
namespace {

using testing::binomial_draw;
using testing::normal_cdf;
using testing::uniform;

// SplitMix64's finaliser.
std::uint64_t mix(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15u;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9u;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebu;
  return x ^ (x >> 31);
}

// A counter-based stream, as the driver's Philox one: any (resample, draw) in any order.
UniformDraw counter_uniforms(std::uint64_t seed) {
  return [seed](std::uint64_t resample, std::uint64_t draw) {
    const std::uint64_t bits = mix(mix(mix(seed) ^ resample) ^ draw);
    return (static_cast<double>(bits >> 11) + 0.5) * 0x1.0p-53;
  };
}

// Whether k is the u-quantile of Binomial(n, p) by GSL's CDF: P(X <= k - 1) < u <= P(X <= k),
// compared in the tail where u lies (P for u <= 1/2, Q = P(X > k) against 1 - u, exact, above) so
// that u = 1e-12 and 1 - 1e-12 are resolved. GSL's binomial CDF is itself good to about 1e-9
// relative at n = 1e6 (as measured against a long double sum of the pmf; better for smaller n): a u
// within a relative 1e-9 of a step of the CDF could rightly go to either side, and is allowed to
// (the grid's u all lie 1e-4 or more from every step, so the allowance decides nothing here).
::testing::AssertionResult is_quantile(std::int64_t k, double u, std::int64_t n, double p) {
  if (k < 0 || k > n) return ::testing::AssertionFailure() << "k = " << k << " outside [0, n]";
  const double tol = 1e-9;
  const auto un = static_cast<unsigned>(n);
  bool below_ok = true, at_ok = true;
  if (u <= 0.5) {
    if (k > 0) below_ok = gsl_cdf_binomial_P(static_cast<unsigned>(k - 1), p, un) < u * (1 + tol);
    at_ok = gsl_cdf_binomial_P(static_cast<unsigned>(k), p, un) >= u * (1 - tol);
  } else {
    const double v = 1.0 - u;
    if (k > 0) below_ok = gsl_cdf_binomial_Q(static_cast<unsigned>(k - 1), p, un) > v * (1 - tol);
    at_ok = gsl_cdf_binomial_Q(static_cast<unsigned>(k), p, un) <= v * (1 + tol);
  }
  if (below_ok && at_ok) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << "k = " << k << " is not the quantile at u = " << u << " of Binomial(" << n << ", " << p
         << "): P(k - 1) = "
         << (k > 0 ? gsl_cdf_binomial_P(static_cast<unsigned>(k - 1), p, un) : 0.0)
         << ", P(k) = " << gsl_cdf_binomial_P(static_cast<unsigned>(k), p, un);
}

TEST(BinomialQuantile, InvertsGslsCdf) {
  for (const std::int64_t n : {1, 5, 40, 1000, 1'000'000}) {
    for (const double p : {0.0, 1e-9, 0.3, 0.5, 0.97, 1.0}) {
      for (const double u : {1e-12, 1e-7, 0.013, 0.37, 0.62, 0.9993, 1.0 - 1e-7, 1.0 - 1e-12}) {
        EXPECT_TRUE(is_quantile(binomial_quantile(u, n, p), u, n, p))
            << "n = " << n << ", p = " << p << ", u = " << u;
      }
    }
  }
}

TEST(BinomialQuantile, EndsAndSmallCases) {
  // p = 0 and p = 1 are certain; no trials give 0.
  EXPECT_EQ(binomial_quantile(0.999, 40, 0.0), 0);
  EXPECT_EQ(binomial_quantile(1e-9, 40, 1.0), 40);
  EXPECT_EQ(binomial_quantile(0.5, 0, 0.5), 0);
  // One trial: X = 1 exactly when u > 1 - p.
  EXPECT_EQ(binomial_quantile(0.69, 1, 0.3), 0);
  EXPECT_EQ(binomial_quantile(0.71, 1, 0.3), 1);
  // Two trials at 1/2: P(X <= 0) = 1/4, P(X <= 1) = 3/4.
  EXPECT_EQ(binomial_quantile(0.2, 2, 0.5), 0);
  EXPECT_EQ(binomial_quantile(0.3, 2, 0.5), 1);
  EXPECT_EQ(binomial_quantile(0.7, 2, 0.5), 1);
  EXPECT_EQ(binomial_quantile(0.8, 2, 0.5), 2);
}

TEST(BinomialQuantile, OfUniformsHasTheBinomialMeanAndVariance) {
  // 5,000 uniforms: the mean is within 4 standard errors (sqrt(n p (1 - p) / 5000)) of n p, and
  // the variance within 4 of its own (relative sqrt((2 + excess kurtosis) / 5000), under 3 % for
  // these cases; 12 % allowed) of n p (1 - p). An off-by-one quantile moves the mean by a whole
  // unit, 50 standard errors at n = 5.
  std::mt19937_64 engine(42);
  const int draws = 5000;
  for (const auto& [n, p] : std::vector<std::pair<std::int64_t, double>>{
           {5, 0.3}, {40, 0.97}, {1000, 0.5}, {1'000'000, 0.3}}) {
    double sum = 0.0, sum2 = 0.0;
    for (int i = 0; i < draws; ++i) {
      const auto k = static_cast<double>(binomial_quantile(uniform(engine), n, p));
      sum += k;
      sum2 += k * k;
    }
    const double nd = static_cast<double>(n), variance = nd * p * (1 - p);
    const double mean = sum / draws, sample_variance = (sum2 - draws * mean * mean) / (draws - 1);
    EXPECT_NEAR(mean, nd * p, 4 * std::sqrt(variance / draws)) << n << " " << p;
    EXPECT_NEAR(sample_variance / variance, 1.0, 0.12) << n << " " << p;
  }
}

using Stripes = testing::FragilityCounts;
const Stripes& baker = testing::kBakerStripes;

void expect_bitwise_equal(const BootstrapResult& a, const BootstrapResult& b) {
  EXPECT_EQ(a.resamples, b.resamples);
  EXPECT_EQ(a.fitted, b.fitted);
  EXPECT_EQ(a.median_low, b.median_low);
  EXPECT_EQ(a.median_high, b.median_high);
  EXPECT_EQ(a.beta_low, b.beta_low);
  EXPECT_EQ(a.beta_high, b.beta_high);
  EXPECT_EQ(a.band_im, b.band_im);
  EXPECT_EQ(a.band_low, b.band_low);
  EXPECT_EQ(a.band_high, b.band_high);
}

TEST(Bootstrap, IsAFunctionOfItsUniforms) {
  const auto once =
      bootstrap_stripes(baker.im, baker.trials, baker.exceedances, 50, counter_uniforms(1));
  const auto again =
      bootstrap_stripes(baker.im, baker.trials, baker.exceedances, 50, counter_uniforms(1));
  expect_bitwise_equal(once, again);
  const auto other =
      bootstrap_stripes(baker.im, baker.trials, baker.exceedances, 50, counter_uniforms(2));
  EXPECT_NE(once.median_low, other.median_low);
  EXPECT_NE(once.beta_high, other.beta_high);

  std::mt19937_64 engine(9);
  std::vector<double> im(300);
  std::vector<bool> exceeded(300);
  for (std::size_t i = 0; i < im.size(); ++i) {
    im[i] = 0.2 * std::pow(10.0, uniform(engine));
    exceeded[i] = uniform(engine) < normal_cdf(std::log(im[i] / 0.7) / 0.5);
  }
  const auto cloud_once = bootstrap_cloud(im, exceeded, 20, counter_uniforms(1));
  const auto cloud_again = bootstrap_cloud(im, exceeded, 20, counter_uniforms(1));
  expect_bitwise_equal(cloud_once, cloud_again);
  const auto cloud_other = bootstrap_cloud(im, exceeded, 20, counter_uniforms(2));
  EXPECT_NE(cloud_once.median_low, cloud_other.median_low);
  EXPECT_EQ(cloud_once.fitted, 20);
}

// The band's grid, its order, and how it relates to the median's interval: each refitted curve is
// at or above 1/2 exactly where x is at or above its median, so the band's upper edge crosses 1/2
// where the 2.5 % of the medians lies (median_low) and its lower edge where the 97.5 % does.
void expect_a_consistent_band(const BootstrapResult& r, double im_max, double median, double beta) {
  ASSERT_EQ(r.band_im.size(), 200u);
  ASSERT_EQ(r.band_low.size(), 200u);
  ASSERT_EQ(r.band_high.size(), 200u);
  EXPECT_NEAR(r.band_im.front(), im_max / 200, 1e-15 * im_max);
  EXPECT_NEAR(r.band_im.back(), 1.1 * im_max, 1e-15 * im_max);
  const double step = (1.1 - 1.0 / 200) * im_max / 199;
  int inside = 0;
  for (std::size_t k = 0; k < 200; ++k) {
    if (k > 0) {
      EXPECT_NEAR(r.band_im[k] - r.band_im[k - 1], step, 1e-12 * im_max) << k;
      // The refitted curves all rise with x, and so do their pointwise quantiles.
      EXPECT_GE(r.band_low[k], r.band_low[k - 1]) << k;
      EXPECT_GE(r.band_high[k], r.band_high[k - 1]) << k;
    }
    const double x = r.band_im[k];
    EXPECT_LE(r.band_low[k], r.band_high[k]) << k;
    EXPECT_GE(r.band_low[k], 0.0);
    EXPECT_LE(r.band_high[k], 1.0);
    const double fitted = normal_cdf(std::log(x / median) / beta);
    if (r.band_low[k] <= fitted && fitted <= r.band_high[k]) ++inside;
    // Away from the interval's ends by more than the gaps between neighbouring order statistics
    // (a few tenths of a percent here), the crossing is on the right side.
    if (x < 0.99 * r.median_low) {
      EXPECT_LT(r.band_high[k], 0.5) << x;
    }
    if (x > 1.01 * r.median_low) {
      EXPECT_GT(r.band_high[k], 0.5) << x;
    }
    if (x < 0.99 * r.median_high) {
      EXPECT_LT(r.band_low[k], 0.5) << x;
    }
    if (x > 1.01 * r.median_high) {
      EXPECT_GT(r.band_low[k], 0.5) << x;
    }
  }
  // A pointwise 95 % band of refits around the fit holds the fit nearly everywhere.
  EXPECT_GE(inside, 190);
}

TEST(Bootstrap, StripesIntervalsAreAbout3Point92StandardErrorsWide) {
  // 8 levels x 2,000 trials on Phi(ln(x / 0.8) / 0.4): plenty of data, so the bootstrap's spread
  // and the observed information agree, and the 95 % interval is median +- 1.96 SE. With 400
  // resamples each end of a percentile interval has a standard error of about 0.13 SE (that of a
  // 2.5 % order statistic), so the width is 3.92 SE to about 5 % (one standard error): 15 % is 3 of
  // them. An interval of 90 % or 99 % (3.29 or 5.15 SE wide) is outside.
  const double m = 0.8, beta = 0.4;
  Stripes d{{0.3, 0.45, 0.6, 0.75, 0.9, 1.1, 1.4, 1.8}, std::vector<std::int64_t>(8, 2000), {}};
  for (const double x : d.im)
    d.exceedances.push_back(std::llround(2000 * normal_cdf(std::log(x / m) / beta)));
  const LognormalFit fit = fit_lognormal_fragility(d.im, d.trials, d.exceedances);
  ASSERT_EQ(fit.status, FitStatus::ok);
  const StandardErrors se = fit_standard_errors(d.im, d.trials, d.exceedances, fit);
  const auto r = bootstrap_stripes(d.im, d.trials, d.exceedances, 400, counter_uniforms(17));
  EXPECT_EQ(r.resamples, 400);
  EXPECT_EQ(r.fitted, 400);
  EXPECT_NEAR((r.median_high - r.median_low) / (3.92 * se.median), 1.0, 0.15);
  EXPECT_NEAR((r.beta_high - r.beta_low) / (3.92 * se.beta), 1.0, 0.15);
  // Centred on the fit: the middle of the two ends is within 0.1 SE (its standard error) x 4.
  EXPECT_NEAR(0.5 * (r.median_low + r.median_high), fit.median, 0.4 * se.median);
  EXPECT_NEAR(0.5 * (r.beta_low + r.beta_high), fit.beta, 0.4 * se.beta);
  expect_a_consistent_band(r, 1.8, fit.median, fit.beta);
}

TEST(Bootstrap, CloudIntervalsAreAbout3Point92StandardErrorsWide) {
  // 800 samples log-uniform over [0.2, 2]: the per-sample fit's observed information against the
  // spread of 200 refits of resampled clouds. With 200 resamples the width's standard error is
  // about 7 %: 20 % is 3 of them (a refit cost grows with the samples; more resamples would cost
  // more than they check).
  std::mt19937_64 engine(2024);
  std::vector<double> im(800);
  std::vector<bool> exceeded(800);
  for (std::size_t i = 0; i < im.size(); ++i) {
    im[i] = 0.2 * std::pow(10.0, uniform(engine));
    exceeded[i] = uniform(engine) < normal_cdf(std::log(im[i] / 0.7) / 0.5);
  }
  const FragilityCurve curve = fragility_from_samples(im, exceeded);
  ASSERT_EQ(curve.fit_status, "ok");
  const auto r = bootstrap_cloud(im, exceeded, 200, counter_uniforms(5));
  EXPECT_EQ(r.fitted, 200);
  EXPECT_NEAR((r.median_high - r.median_low) / (3.92 * curve.median_se), 1.0, 0.2);
  EXPECT_NEAR((r.beta_high - r.beta_low) / (3.92 * curve.beta_se), 1.0, 0.2);
  expect_a_consistent_band(r, *std::max_element(im.begin(), im.end()), curve.median, curve.beta);
}

TEST(Bootstrap, StripesIntervalsCoverTheTrueValuesAbout95PercentOfTheTime) {
  // 100 datasets of 8 levels x 100 trials from Phi(ln(x / 0.8) / 0.4), each bootstrapped with 200
  // resamples. If the intervals are 95 % ones the count that holds the truth is Binomial(100,
  // 0.95): 95 with a standard deviation of 2.2; 3 of those below is 88. (Too wide an interval is
  // what the width tests catch.) Intervals of the wrong quantiles (say 25 % and 75 %), or around a
  // biased centre, hold the truth far less often.
  const double m = 0.8, beta = 0.4;
  const std::vector<double> im{0.3, 0.45, 0.6, 0.75, 0.9, 1.1, 1.4, 1.8};
  std::mt19937_64 engine(606);
  int median_covered = 0, beta_covered = 0;
  for (int k = 0; k < 100; ++k) {
    Stripes d{im, std::vector<std::int64_t>(im.size(), 100), {}};
    for (const double x : im)
      d.exceedances.push_back(binomial_draw(engine, 100, normal_cdf(std::log(x / m) / beta)));
    const auto r = bootstrap_stripes(d.im, d.trials, d.exceedances, 200,
                                     counter_uniforms(static_cast<std::uint64_t>(k)));
    ASSERT_EQ(r.fitted, 200);
    if (r.median_low <= m && m <= r.median_high) ++median_covered;
    if (r.beta_low <= beta && beta <= r.beta_high) ++beta_covered;
  }
  EXPECT_GE(median_covered, 88);
  EXPECT_GE(beta_covered, 88);
}

// Uniforms chosen by hand: resample b's draw j is table[b][j].
UniformDraw from_table(std::vector<std::vector<double>> table) {
  return [table = std::move(table)](std::uint64_t resample, std::uint64_t draw) {
    return table.at(resample).at(draw);
  };
}

// The type 7 quantile of two values a <= b: a + q (b - a).
double between(double a, double b, double q) { return a + q * (b - a); }

TEST(Bootstrap, StripesIntervalsAreThoseOfTheRefitsThatExist) {
  // Three levels of 2 trials at observed proportion 1/2: a uniform below 1/4 draws 0 exceedances,
  // one in (1/4, 3/4] draws 1, one above 3/4 draws 2. Five resamples, two of which have a fit.
  const std::vector<double> im{1.0, 2.0, 4.0};
  const std::vector<std::int64_t> trials{2, 2, 2}, exceedances{1, 1, 1};
  constexpr double zero = 0.1, one = 0.5, two = 0.9;
  const std::vector<std::vector<std::int64_t>> drawn{
      {1, 1, 2}, {0, 0, 0}, {1, 1, 1}, {0, 1, 2}, {0, 1, 1}};
  const std::vector<FitStatus> status{FitStatus::ok, FitStatus::no_exceedances, FitStatus::no_trend,
                                      FitStatus::separated, FitStatus::ok};
  std::vector<std::vector<double>> table;
  std::vector<double> medians, betas;
  for (std::size_t b = 0; b < drawn.size(); ++b) {
    std::vector<double> row;
    for (const auto z : drawn[b]) row.push_back(z == 0 ? zero : z == 1 ? one : two);
    table.push_back(row);
    const LognormalFit fit = fit_lognormal_fragility(im, trials, drawn[b]);
    ASSERT_EQ(fit.status, status[b]) << b;
    if (fit.status == FitStatus::ok) {
      medians.push_back(fit.median);
      betas.push_back(fit.beta);
    }
  }
  const auto r = bootstrap_stripes(im, trials, exceedances, 5, from_table(table));
  EXPECT_EQ(r.resamples, 5);
  EXPECT_EQ(r.fitted, 2);
  std::sort(medians.begin(), medians.end());
  std::sort(betas.begin(), betas.end());
  ASSERT_LT(medians[0], medians[1]);  // the two refits differ: the interpolation is checked
  EXPECT_NEAR(r.median_low, between(medians[0], medians[1], 0.025), 1e-14);
  EXPECT_NEAR(r.median_high, between(medians[0], medians[1], 0.975), 1e-14);
  EXPECT_NEAR(r.beta_low, between(betas[0], betas[1], 0.025), 1e-14);
  EXPECT_NEAR(r.beta_high, between(betas[0], betas[1], 0.975), 1e-14);

  // No refit at all: the intervals and the band are NaN, and say so.
  const auto none = bootstrap_stripes(im, trials, exceedances, 2, from_table({table[1], table[2]}));
  EXPECT_EQ(none.fitted, 0);
  EXPECT_TRUE(std::isnan(none.median_low));
  EXPECT_TRUE(std::isnan(none.beta_high));
  ASSERT_EQ(none.band_low.size(), 200u);
  EXPECT_TRUE(std::isnan(none.band_low[100]));
}

TEST(Bootstrap, StripeFitsAreTheRefitsOfTheDrawnResamples) {
  // The same levels and table: each resample's refit is the fit of the counts its uniforms draw,
  // resampled_exceedances gives those counts, and the intervals are the quantiles of the refits.
  const std::vector<double> im{1.0, 2.0, 4.0};
  const std::vector<std::int64_t> trials{2, 2, 2}, exceedances{1, 1, 1};
  const std::vector<std::vector<double>> table{
      {0.5, 0.5, 0.9}, {0.1, 0.1, 0.1}, {0.1, 0.5, 0.9}, {0.1, 0.5, 0.5}};
  const std::vector<std::vector<std::int64_t>> drawn{{1, 1, 2}, {0, 0, 0}, {0, 1, 2}, {0, 1, 1}};
  const auto uniforms = from_table(table);
  const auto fits = bootstrap_stripe_fits(im, trials, exceedances, 4, uniforms);
  ASSERT_EQ(fits.size(), 4u);
  std::vector<double> medians;
  for (std::size_t b = 0; b < drawn.size(); ++b) {
    EXPECT_EQ(resampled_exceedances(trials, exceedances, b, uniforms), drawn[b]) << b;
    const LognormalFit direct = fit_lognormal_fragility(im, trials, drawn[b]);
    EXPECT_EQ(fits[b].status, direct.status) << b;
    if (direct.status != FitStatus::ok) continue;
    EXPECT_EQ(fits[b].median, direct.median) << b;
    EXPECT_EQ(fits[b].beta, direct.beta) << b;
    medians.push_back(direct.median);
  }
  const auto summary = bootstrap_stripes(im, trials, exceedances, 4, uniforms);
  EXPECT_EQ(summary.median_low, sample_quantile(medians, 0.025));
  EXPECT_EQ(summary.median_high, sample_quantile(medians, 0.975));
}

TEST(Bootstrap, StripesResamplesThatRepeatADrawKeepItsRefit) {
  // The levels of the test above, drawing {1, 1, 2} three times and {0, 2, 1} once between them:
  // the intervals are those of the four refits, each of its own draw (a refit kept from the wrong
  // draw moves an order statistic the interval reads).
  const std::vector<double> im{1.0, 2.0, 4.0};
  const std::vector<std::int64_t> trials{2, 2, 2}, exceedances{1, 1, 1};
  const std::vector<std::vector<std::int64_t>> drawn{{1, 1, 2}, {1, 1, 2}, {0, 2, 1}, {1, 1, 2}};
  std::vector<std::vector<double>> table;
  std::vector<double> medians, betas;
  for (const auto& draw : drawn) {
    std::vector<double> row;
    for (const auto z : draw) row.push_back(z == 0 ? 0.1 : z == 1 ? 0.5 : 0.9);
    table.push_back(row);
    const LognormalFit fit = fit_lognormal_fragility(im, trials, draw);
    ASSERT_EQ(fit.status, FitStatus::ok);
    medians.push_back(fit.median);
    betas.push_back(fit.beta);
  }
  ASSERT_NE(medians[0], medians[2]);
  ASSERT_NE(betas[0], betas[2]);
  // Type 7 of four values at 2.5 % and 97.5 %: 0.075 and 2.925 order statistics from the first.
  std::sort(medians.begin(), medians.end());
  std::sort(betas.begin(), betas.end());
  const auto r = bootstrap_stripes(im, trials, exceedances, 4, from_table(table));
  EXPECT_EQ(r.fitted, 4);
  EXPECT_NEAR(r.median_low, between(medians[0], medians[1], 0.075), 1e-14);
  EXPECT_NEAR(r.median_high, between(medians[2], medians[3], 0.925), 1e-14);
  EXPECT_NEAR(r.beta_low, between(betas[0], betas[1], 0.075), 1e-14);
  EXPECT_NEAR(r.beta_high, between(betas[2], betas[3], 0.925), 1e-14);
}

TEST(Bootstrap, CloudResamplesPickSamplesUniformly) {
  // Six samples; a uniform in [k / 6, (k + 1) / 6) picks sample k. Two resamples chosen by hand,
  // refitted here as clouds of the picked samples.
  const std::vector<double> im{0.5, 0.7, 1.0, 1.4, 2.0, 2.8};
  const std::vector<bool> exceeded{false, true, false, true, false, true};
  const std::vector<std::vector<std::size_t>> picks{{0, 1, 2, 3, 4, 5}, {0, 1, 1, 2, 3, 5}};
  std::vector<std::vector<double>> table;
  std::vector<double> medians;
  for (const auto& pick : picks) {
    std::vector<double> row, picked_im;
    std::vector<std::int64_t> ones(pick.size(), 1), picked_exceeded;
    for (const auto k : pick) {
      row.push_back((static_cast<double>(k) + 0.5) / 6.0);
      picked_im.push_back(im[k]);
      picked_exceeded.push_back(exceeded[k] ? 1 : 0);
    }
    table.push_back(row);
    const LognormalFit fit = fit_lognormal_fragility(picked_im, ones, picked_exceeded);
    ASSERT_EQ(fit.status, FitStatus::ok);
    medians.push_back(fit.median);
  }
  const auto r = bootstrap_cloud(im, exceeded, 2, from_table(table));
  EXPECT_EQ(r.fitted, 2);
  std::sort(medians.begin(), medians.end());
  ASSERT_LT(medians[0], medians[1]);
  EXPECT_NEAR(r.median_low, between(medians[0], medians[1], 0.025), 1e-14);
  EXPECT_NEAR(r.median_high, between(medians[0], medians[1], 0.975), 1e-14);
  // The band's grid follows the largest intensity.
  EXPECT_NEAR(r.band_im.back(), 1.1 * 2.8, 1e-14);
}

}  // namespace
}  // namespace blockfrag
