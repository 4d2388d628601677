// The risk integral against closed forms: a power-law hazard k0 x^-k with a lognormal fragility
// gives k0 theta^-k exp(k^2 beta^2 / 2) (Cornell, Jalayer, Hamburger & Foutch 2002, eq. 10's
// form); with points straight in ln x from 0 at a to 1 at b it gives (lambda(a) - lambda(b)) /
// (k ln(b / a)) (integrated by hand below); a rate that falls to 0 gives its whole first rate to
// a certain limit state; and 1 - exp(-lambda t) the 10 % in 50 years of a 475-year motion.
#include "postproc/risk/risk_integral.hpp"

#include <cmath>
#include <numeric>
#include <vector>

#include <gtest/gtest.h>

namespace blockfrag {
namespace {

// k0 x^-k at n intensities evenly spaced in ln x from low to high: what a hazard file holds.
HazardCurve power_law_hazard(double k0, double k, double low, double high, int n) {
  HazardCurve curve;
  for (int i = 0; i < n; ++i) {
    const double x = low * std::pow(high / low, static_cast<double>(i) / (n - 1));
    curve.im.push_back(x);
    curve.annual_rate.push_back(k0 * std::pow(x, -k));
  }
  return curve;
}

double cornell(double k0, double k, double theta, double beta) {
  return k0 * std::pow(theta, -k) * std::exp(0.5 * k * k * beta * beta);
}

TEST(RiskIntegral, PowerLawHazardAndLognormalFragilityGiveCornellsClosedForm) {
  struct Case {
    double k0, k, theta, beta;
  };
  // Slopes of real hazard curves (2 to 4) and the betas of block studies (0.3 to 0.6). The grid
  // reaches 7.5 beta k below and 7 beta above the median: the integrand, a normal in ln x centred
  // k beta^2 below ln theta, leaves less than 1e-6 of itself outside.
  for (const Case c : {Case{1e-4, 2.5, 0.6, 0.5}, Case{3e-5, 3.5, 1.2, 0.35},
                       Case{2e-4, 2.0, 0.8, 0.6}, Case{1e-4, 4.0, 0.4, 0.3}}) {
    const double low = c.theta * std::exp(-(c.k * c.beta + 6.5) * c.beta);
    const double high = c.theta * std::exp(7.0 * c.beta);
    const HazardCurve hazard = power_law_hazard(c.k0, c.k, low, high, 45);
    const auto risk =
        integrate_risk(hazard, lognormal_exceedance(c.theta, c.beta), {c.theta / 2, c.theta * 2});
    const double exact = cornell(c.k0, c.k, c.theta, c.beta);
    EXPECT_NEAR(risk.lambda / exact, 1.0, 1e-4) << c.k << ' ' << c.theta << ' ' << c.beta;
    // The bins and the motions past the curve's end make up lambda.
    const double bins = std::accumulate(risk.bin_lambda.begin(), risk.bin_lambda.end(), 0.0);
    EXPECT_NEAR(bins + risk.lambda_beyond_hazard, risk.lambda, 1e-15 * risk.lambda);
    // Below theta / 2 (z = ln(x / theta) / beta below c), by parts with a = k beta:
    // integral Phi(z) a e^(-a z) dz to c over its value to infinity, e^(a^2 / 2), is
    // Phi(c + a) - Phi(c) e^(-a c - a^2 / 2).
    const double a = c.k * c.beta, cut = -std::log(2.0) / c.beta;
    const auto phi = [](double z) { return 0.5 * std::erfc(-z / std::sqrt(2.0)); };
    const double below = phi(cut + a) - phi(cut) * std::exp(-a * cut - 0.5 * a * a);
    EXPECT_NEAR(risk.lambda_below_levels / risk.lambda, below, 1e-6) << c.k;
  }
}

TEST(RiskIntegral, PointsStraightInLogIntensityGiveTheirClosedForm) {
  const double k0 = 1e-4, k = 3.0, a = 0.3, b = 1.2;
  const HazardCurve hazard = power_law_hazard(k0, k, 0.01, 5.0, 30);
  const auto risk = integrate_risk(hazard, points_exceedance({a, b}, {0.0, 1.0}), {a, b});
  const double rate_a = k0 * std::pow(a, -k), rate_b = k0 * std::pow(b, -k);
  const double exact = (rate_a - rate_b) / (k * std::log(b / a));
  EXPECT_NEAR(risk.lambda / exact, 1.0, 1e-10);
  // Nothing below a (P = 0 there); above b every motion exceeds, at the rate of exceeding b.
  EXPECT_NEAR(risk.lambda_below_levels, 0.0, 1e-18);
  EXPECT_NEAR(risk.lambda_above_levels / rate_b, 1.0, 1e-10);
  EXPECT_NEAR(risk.share_beyond_levels(), rate_b / exact, 1e-10);
  // Motions past the curve's 5 g exceed at its rate.
  EXPECT_NEAR(risk.lambda_beyond_hazard / (k0 * std::pow(5.0, -k)), 1.0, 1e-12);
}

TEST(RiskIntegral, ARateFallingToZeroGivesItsWholeRateToACertainLimitState) {
  const HazardCurve hazard{{0.1, 0.4, 1.0}, {2e-2, 5e-3, 0.0}};
  const auto certain = integrate_risk(hazard, [](double) { return 1.0; }, {0.2});
  EXPECT_NEAR(certain.lambda, 2e-2, 1e-15);
  EXPECT_NEAR(certain.bin_lambda[0], 2e-2 - 5e-3, 1e-15);
  EXPECT_NEAR(certain.bin_lambda[1], 5e-3, 1e-15);
  EXPECT_EQ(certain.lambda_beyond_hazard, 0.0);
  // Linear in ln x on the last segment: half its rate is spent by its middle in ln x.
  EXPECT_NEAR(hazard_rate(hazard, std::sqrt(0.4)), 2.5e-3, 1e-15);
}

TEST(RiskIntegral, HazardRateIsAPowerLawBetweenItsIntensities) {
  const HazardCurve hazard = power_law_hazard(1e-4, 2.7, 0.05, 3.0, 7);
  for (const double x : {0.05, 0.0731, 0.2, 0.99, 2.9999, 3.0}) {
    EXPECT_NEAR(hazard_rate(hazard, x) / (1e-4 * std::pow(x, -2.7)), 1.0, 1e-12) << x;
  }
}

TEST(RiskIntegral, ProbabilityInYearsOfA475YearMotionIsTenPercentIn50) {
  EXPECT_NEAR(probability_in_years(1.0 / 475.0, 50.0), 0.1, 1e-3);
  EXPECT_NEAR(probability_in_years(1.0 / 2475.0, 50.0), 0.02, 1e-4);
  // Small rates keep their digits: 1 - exp(-x) is x to first order.
  EXPECT_NEAR(probability_in_years(1e-12, 1.0), 1e-12, 1e-24);
}

TEST(RiskIntegral, RefusesCurvesThatBreakItsRules) {
  const auto certain = [](double) { return 1.0; };
  EXPECT_THROW(integrate_risk({{0.1}, {1e-2}}, certain, {0.2}), ContractViolation);
  EXPECT_THROW(integrate_risk({{0.2, 0.1}, {1e-2, 1e-3}}, certain, {0.2}), ContractViolation);
  EXPECT_THROW(integrate_risk({{0.1, 0.2}, {1e-3, 1e-2}}, certain, {0.2}), ContractViolation);
  EXPECT_THROW(integrate_risk({{0.1, 0.2}, {1e-2, 1e-3}}, certain, {}), ContractViolation);
}

}  // namespace
}  // namespace blockfrag
