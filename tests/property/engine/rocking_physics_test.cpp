// Free rocking against Housner (1963): impact ratio, energy, period, amplitude map.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "engine/simulate.hpp"
#include "tests/support/scene_builders.hpp"

namespace blockfrag {
namespace {

using testing::block_scene;
using testing::housner_p;

// A block released tilted by theta0 onto its right corner, no ground motion.
Scene free_rocking(double a, double b, double theta0, double mu, double e, double duration) {
  Scene scene = block_scene(a, b, mu, e, NoMotion{}, duration, 1e-12);
  scene.initial.theta = theta0;
  return scene;
}

class HousnerRatio : public ::testing::TestWithParam<double> {};

TEST_P(HousnerRatio, AngularVelocityRatioAcrossImpactIsOneMinusThreeHalvesSinSquaredAlpha) {
  const double aspect = GetParam();
  const double b = 1.0, a = aspect * b, alpha = std::atan(aspect);
  const auto run = simulate_with_history(free_rocking(a, b, -0.5 * alpha, 5.0, 0.0, 1.0), 0.01);
  ASSERT_GE(run.impacts.size(), 1u);
  const ImpactRecord& first = run.impacts.front();
  const double eta = 1.0 - 1.5 * std::sin(alpha) * std::sin(alpha);
  EXPECT_NEAR(first.omega_after / first.omega_before, eta, 1e-9);
  EXPECT_NEAR(first.kinetic_energy_after / first.kinetic_energy_before, eta * eta, 1e-9);
  EXPECT_EQ(first.mode_after, ModeKind::rock);
}

INSTANTIATE_TEST_SUITE_P(AspectRatios, HousnerRatio, ::testing::Values(0.5, 0.25, 0.1));

TEST(HousnerRocking, QuarterPeriodFromRestMatchesTheExactIntegral) {
  // docs/references.md: p T for alpha = 26.565 deg at theta0/alpha = 0.1, 0.5, 0.9; the first
  // impact comes a quarter period after release.
  const double a = 0.5, b = 1.0, alpha = std::atan(a / b), p = housner_p(a, b);
  const double expected[][2] = {{0.1, 1.897113}, {0.5, 5.301239}, {0.9, 11.992385}};
  for (const auto& [fraction, pT] : expected) {
    const Summary s = simulate(free_rocking(a, b, -fraction * alpha, 5.0, 0.0, 10.0));
    ASSERT_TRUE(s.first_impact_time.has_value());
    EXPECT_NEAR(4.0 * p * *s.first_impact_time, pT, 2e-6) << "theta0/alpha = " << fraction;
  }
}

TEST(HousnerRocking, AmplitudeMapAcrossImpactsMatchesReferenceSequence) {
  // From 0.9 alpha (a/b = 0.5): 23.908546 -> 7.584897 -> 3.420653 -> 1.621171 deg.
  const double a = 0.5, b = 1.0, alpha = std::atan(a / b), p = housner_p(a, b);
  const auto run = simulate_with_history(free_rocking(a, b, -0.9 * alpha, 5.0, 0.0, 10.0), 0.01);
  ASSERT_GE(run.impacts.size(), 3u);
  const double expected_deg[] = {7.584897, 3.420653, 1.621171};
  for (int n = 0; n < 3; ++n) {
    // After the impact at theta = 0, all of the energy above rest turns into height.
    const double w = run.impacts[static_cast<std::size_t>(n)].omega_after;
    const double amplitude = alpha - std::acos(std::cos(alpha) + w * w / (2 * p * p));
    EXPECT_NEAR(amplitude * 180 / std::numbers::pi, expected_deg[n], 1e-5) << "impact " << n;
  }
}

TEST(HousnerRocking, EnergyIsConservedBetweenImpacts) {
  const double a = 0.5, b = 1.0, g = 9.81;
  const auto run = simulate_with_history(free_rocking(a, b, -0.4, 5.0, 0.0, 3.0), 0.001);
  double reference = NAN;
  int checked = 0;
  for (const HistoryRow& row : run.history) {
    if (row.mode != ModeKind::rock) continue;
    const double energy =
        0.5 * (row.vx * row.vx + row.vy * row.vy + (a * a + b * b) / 3.0 * row.omega * row.omega) +
        g * row.y;
    if (row.t < run.impacts.front().time) {
      if (std::isnan(reference)) reference = energy;
      EXPECT_NEAR(energy / reference - 1.0, 0.0, 1e-8) << "t = " << row.t;
      ++checked;
    }
  }
  EXPECT_GT(checked, 100);
}

TEST(Impacts, KineticEnergyNeverIncreasesAcrossAnImpact) {
  for (const double e : {0.0, 0.3, 0.6, 1.0}) {
    for (const double mu : {0.2, 0.6, 1.5}) {
      Scene scene = block_scene(0.3, 1.0, mu, e, CosinePulse{1.2, 1.0, 2.0}, 4.0, 1e-9);
      const auto run = simulate_with_history(scene, 0.01);
      for (const ImpactRecord& impact : run.impacts) {
        EXPECT_LE(impact.kinetic_energy_after, impact.kinetic_energy_before * (1 + 1e-12))
            << "e = " << e << " mu = " << mu << " t = " << impact.time;
      }
      EXPECT_LE(run.summary.max_impact_energy_gain, 1e-12);
    }
  }
}

TEST(Flight, IsAParabolaWithConstantAngularVelocity) {
  // e > 0 at a rocking impact throws the block into the air (docs/references.md: both corners
  // leave).
  const auto run = simulate_with_history(free_rocking(0.5, 1.0, -0.3, 5.0, 0.6, 1.5), 0.0005);
  const double g = 9.81;
  int rows = 0;
  for (std::size_t i = 1; i < run.history.size(); ++i) {
    const HistoryRow& before = run.history[i - 1];
    const HistoryRow& now = run.history[i];
    if (before.mode != ModeKind::flight || now.mode != ModeKind::flight) continue;
    const double dt = now.t - before.t;
    if (now.omega != before.omega) continue;  // an impact in between
    EXPECT_NEAR(now.vy - before.vy, -g * dt, 1e-12);
    EXPECT_NEAR(now.y - before.y, before.vy * dt - 0.5 * g * dt * dt, 1e-12);
    EXPECT_NEAR(now.theta - before.theta, before.omega * dt, 1e-12);
    EXPECT_NEAR(now.vx, before.vx, 1e-12);  // no ground motion: no horizontal force
    ++rows;
  }
  EXPECT_GT(rows, 50);
}

TEST(Flight, SameCornerLandsAgainAfterTheReferenceTime) {
  // docs/references.md: a/b = 0.5, b = 1, e = 0.6, a rocking block reaching theta = 0 at 1 rad/s
  // makes a sticking impact, flies, and the same corner lands again 0.125829 s later. Release it
  // from the tilt whose potential energy gives exactly 1 rad/s at theta = 0.
  const double a = 0.5, b = 1.0, alpha = std::atan(a / b), p = housner_p(a, b);
  const double theta0 = alpha - std::acos(std::cos(alpha) + 1.0 / (2 * p * p));
  const auto run = simulate_with_history(free_rocking(a, b, -theta0, 5.0, 0.6, 1.0), 0.001);
  ASSERT_GE(run.impacts.size(), 2u);
  const ImpactRecord& first = run.impacts[0];
  const ImpactRecord& second = run.impacts[1];
  EXPECT_NEAR(first.omega_before, 1.0, 1e-9);
  EXPECT_EQ(first.mode_after, ModeKind::flight);
  EXPECT_NEAR(first.omega_after, 0.52, 1e-9);
  EXPECT_NEAR(first.kinetic_energy_after / first.kinetic_energy_before, 0.6736, 1e-9);
  EXPECT_NEAR(second.time - first.time, 0.125829, 1e-6);
}

}  // namespace
}  // namespace blockfrag
