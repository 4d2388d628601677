// The fit's standard errors against the expected (Fisher) information of the probit-in-ln(x)
// binomial model, written here in closed form, and against the spread of fits to data drawn from a
// known curve; the goodness of fit against the deviance's formula evaluated by hand (levels with
// z = 0 and z = n included), against the chi-square tail in closed form (2 and 1 degrees of
// freedom) and GSL's, against the share of small p-values under the lognormal (about 5 %), and
// against data from a curve with a plateau that no lognormal follows.
#include "postproc/fragility/fit_diagnostics.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include <gsl/gsl_cdf.h>
#include <gtest/gtest.h>

#include "postproc/fragility/cloud_fragility.hpp"
#include "postproc/fragility/fragility_curve.hpp"
#include "postproc/fragility/lognormal_fit.hpp"
#include "tests/support/fragility_draws.hpp"

namespace blockfrag {
namespace {

using testing::binomial_draw;
using testing::fit;
using testing::FragilityCounts;
using testing::normal_cdf;
using testing::uniform;

double normal_pdf(double x) { return std::exp(-0.5 * x * x) / std::sqrt(2.0 * M_PI); }

FragilityCounts drawn_from(std::mt19937_64& engine, const std::vector<double>& im, std::int64_t n,
                           double median, double beta) {
  FragilityCounts d{im, std::vector<std::int64_t>(im.size(), n), {}};
  for (const double x : im)
    d.exceedances.push_back(binomial_draw(engine, n, normal_cdf(std::log(x / median) / beta)));
  return d;
}

StandardErrors errors(const FragilityCounts& d, const LognormalFit& f) {
  return fit_standard_errors(d.im, d.trials, d.exceedances, f);
}

double sample_sd(const std::vector<double>& values) {
  double mean = 0.0, sum = 0.0;
  for (const double v : values) mean += v;
  mean /= static_cast<double>(values.size());
  for (const double v : values) sum += (v - mean) * (v - mean);
  return std::sqrt(sum / static_cast<double>(values.size() - 1));
}

double mean_of(const std::vector<double>& values) {
  double sum = 0.0;
  for (const double v : values) sum += v;
  return sum / static_cast<double>(values.size());
}

TEST(StandardErrors, MatchTheExpectedInformationWithHugeCounts) {
  // I = sum_j n_j phi(u_j)^2 / (p_j (1 - p_j)) g_j g_j^T, u_j = ln(x_j / m) / beta,
  // g_j = du_j / d(ln m, ln beta) = (-1 / beta, -u_j). With z_j = round(n_j p_j) the residuals
  // z_j - n_j p_j are at most 1/2, against n_j p_j and n_j (1 - p_j) of 7e3 or more: a relative
  // 7e-5 at worst, and the observed information (which adds sum_j (z_j - n_j p_j) times second
  // derivatives) differs from I by less than that (1e-7 as measured); the numerical Hessian adds
  // about 1e-7. 1e-4 bounds both, far below the size of any real mistake (a missing factor, a step
  // in the wrong variable, the delta method left out).
  const double m = 0.9, beta = 0.45;
  const std::int64_t n = 1'000'000;
  FragilityCounts d{{0.3, 0.5, 0.7, 1.0, 1.4, 2.0}, std::vector<std::int64_t>(6, n), {}};
  for (const double x : d.im)
    d.exceedances.push_back(
        std::llround(static_cast<double>(n) * normal_cdf(std::log(x / m) / beta)));
  const LognormalFit f = fit(d);
  ASSERT_EQ(f.status, FitStatus::ok);
  ASSERT_NEAR(f.median, m, 1e-5);
  ASSERT_NEAR(f.beta, beta, 1e-5);

  // The expected information at the fitted curve.
  double i00 = 0.0, i01 = 0.0, i11 = 0.0;
  for (std::size_t j = 0; j < d.im.size(); ++j) {
    const double u = std::log(d.im[j] / f.median) / f.beta;
    const double p = normal_cdf(u), phi = normal_pdf(u);
    const double w = static_cast<double>(d.trials[j]) * phi * phi / (p * (1.0 - p));
    const double g0 = -1.0 / f.beta, g1 = -u;
    i00 += w * g0 * g0;
    i01 += w * g0 * g1;
    i11 += w * g1 * g1;
  }
  const double det = i00 * i11 - i01 * i01;
  const double se_median = f.median * std::sqrt(i11 / det);
  const double se_beta = f.beta * std::sqrt(i00 / det);

  const StandardErrors se = errors(d, f);
  EXPECT_NEAR(se.median / se_median, 1.0, 1e-4) << se.median << " vs " << se_median;
  EXPECT_NEAR(se.beta / se_beta, 1.0, 1e-4) << se.beta << " vs " << se_beta;
  // The scale of the answer: about 1e-4 of the median with a million trials a level.
  EXPECT_GT(se.median, 1e-5 * m);
  EXPECT_LT(se.median, 1e-3 * m);
}

TEST(StandardErrors, MatchTheSpreadOfFitsToDataDrawnFromAKnownCurve) {
  // 500 datasets of 8 levels x 200 trials from Phi(ln(x / 0.8) / 0.4). The sample standard
  // deviation of 500 estimates has a relative sampling error of 1 / sqrt(2 x 500) = 3.2 %; the
  // asymptotic standard error is a little off at 1,600 trials (a few %, the estimates are slightly
  // skewed). 12 % is over 3 sampling errors plus that, and a wrong factor of the information (a
  // missing 2 in a central difference, an SE of ln m reported for m) is off by 25 % or more.
  std::mt19937_64 engine(7101);
  const std::vector<double> im{0.3, 0.45, 0.6, 0.75, 0.9, 1.1, 1.4, 1.8};
  const double m = 0.8, beta = 0.4;
  const int datasets = 500;
  std::vector<double> medians, betas, se_medians, se_betas;
  for (int k = 0; k < datasets; ++k) {
    const FragilityCounts d = drawn_from(engine, im, 200, m, beta);
    const LognormalFit f = fit(d);
    ASSERT_EQ(f.status, FitStatus::ok);
    const StandardErrors se = errors(d, f);
    medians.push_back(f.median);
    betas.push_back(f.beta);
    se_medians.push_back(se.median);
    se_betas.push_back(se.beta);
  }
  EXPECT_NEAR(sample_sd(medians) / mean_of(se_medians), 1.0, 0.12)
      << sample_sd(medians) << " vs " << mean_of(se_medians);
  EXPECT_NEAR(sample_sd(betas) / mean_of(se_betas), 1.0, 0.12)
      << sample_sd(betas) << " vs " << mean_of(se_betas);
  // ... and the fits are centred on the truth: the mean of 500 is within 4 of its own standard
  // errors (SE / sqrt(500)), plus 1e-3 for beta: the maximum likelihood estimate is biased by
  // order 1 / (total trials) relative, a few 1e-4 here.
  EXPECT_NEAR(mean_of(medians), m, 4 * mean_of(se_medians) / std::sqrt(datasets));
  EXPECT_NEAR(mean_of(betas), beta, 4 * mean_of(se_betas) / std::sqrt(datasets) + 1e-3);
}

TEST(StandardErrors, RefuseAFitThatDoesNotExist) {
  const FragilityCounts d{{0.5, 1.0}, {10, 10}, {0, 0}};
  const LognormalFit f = fit(d);
  ASSERT_EQ(f.status, FitStatus::no_exceedances);
  EXPECT_THROW(errors(d, f), FitError);
}

// The deviance by hand: 2 sum_j [z ln(z / e) + (n - z) ln((n - z) / (n - e))], e = n p_j, with the
// z = 0 and z = n terms written out (0 ln 0 = 0).
TEST(GoodnessOfFit, DevianceIsTheFormulaWithEmptyAndFullLevels) {
  const std::vector<double> im{0.4, 0.8, 1.2, 2.0, 3.0};
  const std::vector<std::int64_t> trials{10, 20, 0, 12, 15};
  const std::vector<std::int64_t> exceedances{0, 7, 0, 9, 15};
  const double m = 1.1, beta = 0.5;
  std::vector<double> p;
  for (const double x : im) p.push_back(normal_cdf(std::log(x / m) / beta));
  const double by_hand =
      2 * (10 * std::log(10 / (10 * (1 - p[0]))) +                                  // z = 0
           7 * std::log(7 / (20 * p[1])) + 13 * std::log(13 / (20 * (1 - p[1]))) +  // 7 of 20
           9 * std::log(9 / (12 * p[3])) + 3 * std::log(3 / (12 * (1 - p[3]))) +    // 9 of 12
           15 * std::log(15 / (15 * p[4])));                                        // z = n
  const double misfit = std::max({p[0], std::abs(0.35 - p[1]), std::abs(0.75 - p[3]), 1 - p[4]});

  const GoodnessOfFit gof = goodness_of_fit(im, trials, exceedances, m, beta);
  EXPECT_NEAR(gof.deviance, by_hand, 1e-12 * by_hand);
  EXPECT_EQ(gof.dof, 2);  // four levels with trials
  // Chi-square with 2 degrees of freedom: P(X > d) = exp(-d / 2).
  EXPECT_NEAR(gof.p_value, std::exp(-by_hand / 2), 1e-12);
  EXPECT_EQ(gof.p_value, gsl_cdf_chisq_Q(gof.deviance, 2));
  EXPECT_NEAR(gof.max_misfit, misfit, 1e-15);
  EXPECT_GT(gof.deviance, 1.0);  // the curve is not the data's: the check is not of zeros
}

TEST(GoodnessOfFit, DataOnTheCurveHaveNoDeviance) {
  // n p_j whole numbers: the saturated model and the curve coincide.
  const double m = 2.0, beta = 0.6;
  const std::vector<double> im{m * std::exp(-beta * 0.6744897501960817), m,
                               m * std::exp(beta * 0.6744897501960817)};  // p = 1/4, 1/2, 3/4
  const GoodnessOfFit gof = goodness_of_fit(im, {{8, 8, 8}}, {{2, 4, 6}}, m, beta);
  EXPECT_NEAR(gof.deviance, 0.0, 1e-12);
  EXPECT_EQ(gof.dof, 1);
  EXPECT_NEAR(gof.p_value, 1.0, 1e-6);
  EXPECT_NEAR(gof.max_misfit, 0.0, 1e-12);
}

TEST(GoodnessOfFit, DegreesOfFreedomAreLevelsWithTrialsLessTwo) {
  const double m = 1.0, beta = 0.5;
  // Three levels with trials (one without): 1 degree of freedom, P(X > d) = erfc(sqrt(d / 2)).
  const GoodnessOfFit three =
      goodness_of_fit({{0.5, 1.0, 1.5, 2.0}}, {{10, 0, 10, 10}}, {{1, 0, 4, 9}}, m, beta);
  EXPECT_EQ(three.dof, 1);
  EXPECT_NEAR(three.p_value, std::erfc(std::sqrt(three.deviance / 2)), 1e-12);
  EXPECT_EQ(three.p_value, gsl_cdf_chisq_Q(three.deviance, 1));
  // Two, one or no levels with trials: no degree of freedom (never negative), no p-value.
  for (const std::vector<std::int64_t>& trials :
       {std::vector<std::int64_t>{10, 0, 10, 0}, std::vector<std::int64_t>{0, 0, 10, 0},
        std::vector<std::int64_t>{0, 0, 0, 0}}) {
    const GoodnessOfFit gof =
        goodness_of_fit({{0.5, 1.0, 1.5, 2.0}}, trials, {{1, 0, 4, 0}}, m, beta);
    EXPECT_EQ(gof.dof, 0);
    EXPECT_TRUE(std::isnan(gof.p_value));
    EXPECT_TRUE(std::isfinite(gof.deviance));
  }
}

TEST(GoodnessOfFit, GivenExpectedCountsReplaceTheCurve) {
  // A cloud's bins: the expected exceedances are given, the median and beta are not used.
  const std::vector<double> im{0.5, 1.0}, expected{2.5, 6.0};
  const std::vector<std::int64_t> trials{10, 10}, exceedances{3, 5};
  const double by_hand = 2 * (3 * std::log(3 / 2.5) + 7 * std::log(7 / 7.5) +
                              5 * std::log(5 / 6.0) + 5 * std::log(5 / 4.0));
  const GoodnessOfFit gof = goodness_of_fit(im, trials, exceedances, 123.0, 9.0, expected);
  EXPECT_NEAR(gof.deviance, by_hand, 1e-13);
  EXPECT_NEAR(gof.max_misfit, 0.1, 1e-15);  // |0.5 - 0.6|
}

TEST(GoodnessOfFit, PValuesAreUniformUnderTheLognormal) {
  // 1,000 datasets of 8 levels x 100 trials from a lognormal, fitted: the deviance is then about
  // chi-square with 6 degrees of freedom (every expected count here is 8 or more, where the
  // approximation holds well). The count of p < 0.05 is then Binomial(1000, 0.05): 50 with a
  // standard deviation of 6.9; 4 of those either side is what we allow. A deviance against the
  // wrong expected counts, or a wrong dof (5 or 7), moves the count by more than 20 (and the mean
  // deviance, 6 +- 4 x 0.11, by about 1).
  std::mt19937_64 engine(5313);
  const std::vector<double> im{0.45, 0.55, 0.65, 0.8, 1.0, 1.2, 1.45, 1.7};
  const int datasets = 1000;
  int small = 0;
  double deviance_sum = 0.0;
  for (int k = 0; k < datasets; ++k) {
    const FragilityCounts d = drawn_from(engine, im, 100, 0.9, 0.45);
    const LognormalFit f = fit(d);
    ASSERT_EQ(f.status, FitStatus::ok);
    const GoodnessOfFit gof = goodness_of_fit(d.im, d.trials, d.exceedances, f.median, f.beta);
    ASSERT_EQ(gof.dof, 6);
    if (gof.p_value < 0.05) ++small;
    deviance_sum += gof.deviance;
  }
  EXPECT_GE(small, 50 - 28);
  EXPECT_LE(small, 50 + 28);
  EXPECT_NEAR(deviance_sum / datasets, 6.0, 4 * std::sqrt(12.0 / datasets));
}

TEST(GoodnessOfFit, RejectsACurveWithAPlateau) {
  // Half the blocks fail about 0.4, the other half about 2.5: a plateau at 1/2 between, which no
  // lognormal follows. 10,000 trials a level make the deviance huge; max_misfit is the gap between
  // the true curve and the fitted one, to the binomial noise of a point (sqrt(1/4 / 10^4) = 0.005,
  // 4 of them allowed).
  const auto truth = [](double x) {
    return 0.5 * normal_cdf(std::log(x / 0.4) / 0.15) + 0.5 * normal_cdf(std::log(x / 2.5) / 0.15);
  };
  std::mt19937_64 engine(88);
  const std::vector<double> im{0.2, 0.3, 0.4, 0.55, 0.8, 1.0, 1.3, 1.8, 2.5, 3.5, 5.0};
  FragilityCounts d{im, std::vector<std::int64_t>(im.size(), 10'000), {}};
  for (const double x : im) d.exceedances.push_back(binomial_draw(engine, 10'000, truth(x)));
  const LognormalFit f = fit(d);
  ASSERT_EQ(f.status, FitStatus::ok);
  const GoodnessOfFit gof = goodness_of_fit(d.im, d.trials, d.exceedances, f.median, f.beta);
  double gap = 0.0;
  for (const double x : im)
    gap = std::max(gap, std::abs(truth(x) - normal_cdf(std::log(x / f.median) / f.beta)));
  EXPECT_EQ(gof.dof, 9);
  EXPECT_LT(gof.p_value, 1e-6);
  EXPECT_GT(gap, 0.05);  // the shape is clearly not lognormal
  EXPECT_NEAR(gof.max_misfit, gap, 0.02);
}

TEST(FitDiagnostics, FragilityFromCountsCarriesThem) {
  const std::vector<double> im{0.2, 0.3, 0.4, 0.6, 0.7, 0.8, 0.9, 1.0};
  const std::vector<std::int64_t> trials(8, 40), exceedances{0, 0, 0, 4, 6, 13, 12, 16};
  const FragilityCurve curve = fragility_from_counts(im, trials, exceedances);
  const LognormalFit f = fit_lognormal_fragility(im, trials, exceedances);
  const StandardErrors se = fit_standard_errors(im, trials, exceedances, f);
  const GoodnessOfFit gof = goodness_of_fit(im, trials, exceedances, f.median, f.beta);
  EXPECT_EQ(curve.median_se, se.median);
  EXPECT_EQ(curve.beta_se, se.beta);
  EXPECT_EQ(curve.deviance, gof.deviance);
  EXPECT_EQ(curve.gof_dof, 6);
  EXPECT_EQ(curve.gof_p_value, gof.p_value);
  EXPECT_EQ(curve.max_misfit, gof.max_misfit);
  EXPECT_GT(curve.median_se, 0.0);

  const FragilityCurve none = fragility_from_counts({0.5, 1.0}, {20, 20}, {0, 0});
  EXPECT_TRUE(std::isnan(none.median_se));
  EXPECT_TRUE(std::isnan(none.beta_se));
  EXPECT_TRUE(std::isnan(none.deviance));
  EXPECT_EQ(none.gof_dof, 0);
  EXPECT_TRUE(std::isnan(none.gof_p_value));
}

TEST(FitDiagnostics, ACloudsDevianceIsOverItsBinsWithEachSamplesFittedProbability) {
  // 600 samples at intensities spread over [0.2, 2]: the display bins' expected exceedances are
  // the sums of their samples' fitted probabilities, recomputed here from the bins' edges.
  std::mt19937_64 engine(31);
  const std::size_t n = 600, bins = 6;
  std::vector<double> im(n);
  std::vector<bool> exceeded(n);
  for (std::size_t i = 0; i < n; ++i) {
    im[i] = 0.2 * std::pow(10.0, uniform(engine));
    exceeded[i] = uniform(engine) < normal_cdf(std::log(im[i] / 0.7) / 0.5);
  }
  const FragilityCurve curve = fragility_from_samples(im, exceeded, bins);
  ASSERT_EQ(curve.fit_status, "ok");
  const double low = std::log(*std::min_element(im.begin(), im.end()));
  const double high = std::log(*std::max_element(im.begin(), im.end()));
  std::vector<double> expected(bins, 0.0), count(bins, 0.0), hits(bins, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const auto k = std::min(
        bins - 1, static_cast<std::size_t>((std::log(im[i]) - low) / ((high - low) / bins)));
    expected[k] += normal_cdf(std::log(im[i] / curve.median) / curve.beta);
    count[k] += 1;
    hits[k] += exceeded[i] ? 1 : 0;
  }
  double deviance = 0.0, misfit = 0.0;
  int levels = 0;
  for (std::size_t k = 0; k < bins; ++k) {
    if (count[k] == 0) continue;
    ++levels;
    const double z = hits[k], e = expected[k], m = count[k];
    if (z > 0) deviance += 2 * z * std::log(z / e);
    if (m > z) deviance += 2 * (m - z) * std::log((m - z) / (m - e));
    misfit = std::max(misfit, std::abs(z - e) / m);
  }
  EXPECT_EQ(curve.gof_dof, levels - 2);
  EXPECT_NEAR(curve.deviance, deviance, 1e-9 * deviance);
  EXPECT_NEAR(curve.max_misfit, misfit, 1e-12);
  EXPECT_EQ(curve.gof_p_value, gsl_cdf_chisq_Q(curve.deviance, curve.gof_dof));
  // The standard errors are the per-sample fit's: about 0.5 / sqrt(600) of the median's log.
  EXPECT_GT(curve.median_se, 0.2 * 0.7 * 0.5 / std::sqrt(600.0));
  EXPECT_LT(curve.median_se, 5 * 0.7 * 0.5 / std::sqrt(600.0));
}

}  // namespace
}  // namespace blockfrag
