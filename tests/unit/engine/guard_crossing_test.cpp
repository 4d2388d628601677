// Where a step's guards first cross zero: at a sign change of the end values, at a sample inside
// the step, and at a dip narrower than the samples' spacing.
#include "engine/integrate/guard_crossing.hpp"

#include <array>
#include <cmath>

#include <gtest/gtest.h>

namespace blockfrag {
namespace {

// Nothing is known about where a guard is least.
std::array<bool, 1> unknown(const std::array<bool, 1>&) { return {false}; }

// A parabola with its minimum c below zero at t = m, scaled by k: zero at m -+ sqrt(c / k).
struct Parabola {
  double k, m, c;
  std::array<double, 1> operator()(double t) const { return {k * (t - m) * (t - m) - c}; }
  double first_zero() const { return m - std::sqrt(c / k); }
};

TEST(GuardCrossing, FindsAGuardThatEndsTheStepBelowZero) {
  const Parabola g{1.0, 1.2, 0.01};  // zero at 1.1
  GuardWatch<1> watch(g(0.0));
  const auto crossing = watch.first_crossing(g, 0.0, 1.15, g(1.15), unknown);
  EXPECT_EQ(crossing.which, 0);
  EXPECT_NEAR(crossing.after, g.first_zero(), 1e-12);
  EXPECT_LE(crossing.before, crossing.after);
}

TEST(GuardCrossing, FindsADipBetweenSamplesWhereTheSamplesTurnBackUp) {
  // Both ends near zero (so the step is looked inside), the dip between the samples at 8/16 and
  // 9/16: every sample is positive, the guard is below zero on (0.5218, 0.5382). Found by the
  // random scenes test as a rocking corner turning back 2.9e-7 R under the ground inside a step.
  const Parabola g{0.15, 0.53, 1e-5};
  ASSERT_LT(g(0.0)[0], kNearZero);
  for (int k = 0; k <= kInteriorSamples; ++k) {
    ASSERT_GT(g(static_cast<double>(k) / kInteriorSamples)[0], 0.0) << k;
  }
  GuardWatch<1> watch(g(0.0));
  const auto crossing = watch.first_crossing(g, 0.0, 1.0, g(1.0), unknown);
  EXPECT_EQ(crossing.which, 0);
  EXPECT_NEAR(crossing.after, g.first_zero(), 1e-12);
}

TEST(GuardCrossing, AGuardThatStaysPositiveDoesNotCross) {
  // The same shape lifted above zero: the parabola's minimum is evaluated and found positive.
  const Parabola g{0.15, 0.53, -1e-5};
  GuardWatch<1> watch(g(0.0));
  EXPECT_EQ(watch.first_crossing(g, 0.0, 1.0, g(1.0), unknown).which, -1);
}

TEST(GuardCrossing, AGuardLeastAtTheStepsEndsIsNotLookedInside) {
  // Rising through the step from just above zero: looked inside unless known to be least at an
  // end, and then evaluated nowhere but at the ends the caller gave.
  int evaluations = 0;
  const auto g = [&](double t) {
    ++evaluations;
    return std::array<double, 1>{1e-3 + 0.01 * t};
  };
  GuardWatch<1> watch(g(0.0));
  evaluations = 0;
  EXPECT_EQ(watch.first_crossing(g, 0.0, 1.0, {0.011}, unknown).which, -1);
  EXPECT_GT(evaluations, 0);
  evaluations = 0;
  const auto least_at_start_or_end = [](const std::array<bool, 1>&) {
    return std::array<bool, 1>{true};
  };
  EXPECT_EQ(watch.first_crossing(g, 0.0, 1.0, {0.011}, least_at_start_or_end).which, -1);
  EXPECT_EQ(evaluations, 0);
}

TEST(GuardCrossing, AGuardAtLeastNearZeroAtBothEndsIsNotLookedInside) {
  // Far enough from zero at both ends, a guard is taken to stay positive through the step even
  // where it would dip below zero inside: the steps are short enough for its values that it does
  // not. Just under kNearZero at one end, the dip is looked for and found.
  int evaluations = 0;
  const auto dip = [&](double t) {
    ++evaluations;
    return std::array<double, 1>{kNearZero - 4 * (kNearZero + 0.01) * t * (1 - t)};
  };
  GuardWatch<1> watch({kNearZero});
  evaluations = 0;
  EXPECT_EQ(watch.first_crossing(dip, 0.0, 1.0, {kNearZero}, unknown).which, -1);
  EXPECT_EQ(evaluations, 0);
  const double just_under = std::nextafter(kNearZero, 0.0);
  EXPECT_EQ(watch.first_crossing(dip, 0.0, 1.0, {just_under}, unknown).which, 0);
  EXPECT_GT(evaluations, 0);
}

}  // namespace
}  // namespace blockfrag
