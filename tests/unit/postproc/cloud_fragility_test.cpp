// The cloud fit against the binned fit where both apply (samples at a few repeated intensities are
// stripes: the two likelihoods are the same function), against a known curve it must recover
// (synthetic Bernoulli data drawn from it), and the display bins against counts made by hand.
#include "postproc/fragility/cloud_fragility.hpp"

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "postproc/fragility/lognormal_fit.hpp"
#include "tests/support/fragility_draws.hpp"

namespace blockfrag {
namespace {

using testing::normal_cdf;
using testing::uniform;

TEST(CloudFragility, SamplesAtRepeatedIntensitiesGiveTheBinnedFit) {
  // The check data of docs/references.md (Baker 2015), as 320 single samples.
  const std::vector<double> levels = {0.2, 0.3, 0.4, 0.6, 0.7, 0.8, 0.9, 1.0};
  const std::vector<std::int64_t> z = {0, 0, 0, 4, 6, 13, 12, 16};
  std::vector<double> im;
  std::vector<bool> exceeded;
  for (std::size_t j = 0; j < levels.size(); ++j) {
    for (std::int64_t i = 0; i < 40; ++i) {
      im.push_back(levels[j]);
      exceeded.push_back(i < z[j]);
    }
  }
  const FragilityCurve cloud = fragility_from_samples(im, exceeded, 8);
  const LognormalFit binned = fit_lognormal_fragility(levels, std::vector<std::int64_t>(8, 40), z);
  ASSERT_EQ(cloud.fit_status, "ok");
  EXPECT_EQ(cloud.median, binned.median);
  EXPECT_EQ(cloud.beta, binned.beta);
  EXPECT_NEAR(cloud.median, 1.076116, 5e-7);  // docs/references.md, Baker (2015)
  EXPECT_NEAR(cloud.beta, 0.429237, 5e-7);
  EXPECT_EQ(cloud.log_likelihood, binned.log_likelihood);
}

TEST(CloudFragility, RecoversAKnownCurveFromACloudOfSingleSamples) {
  // 20,000 intensities log-uniform over [0.1, 3], each exceeding with Phi(ln(x / 0.8) / 0.4).
  // The standard errors of the fit at this size are about 0.006 (median) and 0.006 (beta):
  // 5 of them is a check that fails for a wrong likelihood, not for bad luck.
  std::mt19937_64 engine(20261124);
  const std::size_t n = 20000;
  std::vector<double> im(n);
  std::vector<bool> exceeded(n);
  for (std::size_t i = 0; i < n; ++i) {
    im[i] = 0.1 * std::pow(30.0, uniform(engine));
    exceeded[i] = uniform(engine) < normal_cdf(std::log(im[i] / 0.8) / 0.4);
  }
  const FragilityCurve cloud = fragility_from_samples(im, exceeded);
  ASSERT_EQ(cloud.fit_status, "ok");
  EXPECT_NEAR(cloud.median, 0.8, 0.03);
  EXPECT_NEAR(cloud.beta, 0.4, 0.03);
  // The display bins hold every sample, and their points follow the true curve.
  std::int64_t total = 0;
  for (std::size_t k = 0; k < cloud.im.size(); ++k) {
    total += cloud.trials[k];
    EXPECT_LE(cloud.ci_low[k], cloud.probability[k]);
    EXPECT_GE(cloud.ci_high[k], cloud.probability[k]);
    // Within a bin the curve changes: compare at the bin's geometric mean, loosely.
    EXPECT_NEAR(cloud.probability[k], normal_cdf(std::log(cloud.im[k] / 0.8) / 0.4), 0.08);
  }
  EXPECT_EQ(total, static_cast<std::int64_t>(n));
  EXPECT_EQ(cloud.im.size(), 10u);
}

TEST(CloudFragility, BinsAreEqualInLogIntensityAndEmptyOnesAreLeftOut) {
  // ln IM from ln 1 to ln 16 in 4 bins of width ln 2: [1, 2), [2, 4), [4, 8), [8, 16].
  const std::vector<double> im = {1.0, 1.5, 4.0, 5.0, 7.0, 16.0};
  const std::vector<bool> exceeded = {false, false, true, false, true, true};
  const FragilityCurve curve = fragility_from_samples(im, exceeded, 4);
  ASSERT_EQ(curve.im.size(), 3u);  // [2, 4) is empty
  EXPECT_EQ(curve.trials, (std::vector<std::int64_t>{2, 3, 1}));
  EXPECT_EQ(curve.exceedances, (std::vector<std::int64_t>{0, 2, 1}));
  EXPECT_NEAR(curve.im[0], std::sqrt(1.5), 1e-15);              // geometric mean of 1 and 1.5
  EXPECT_NEAR(curve.im[1], std::cbrt(4.0 * 5.0 * 7.0), 1e-13);  // of 4, 5 and 7
  EXPECT_NEAR(curve.im[2], 16.0, 1e-14);
}

}  // namespace
}  // namespace blockfrag
