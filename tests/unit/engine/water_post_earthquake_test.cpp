// Every summary of a scene with a reservoir reports the block's safety factors after the
// earthquake (engine/summary.hpp, PostEarthquakeCheck): for a block standing at rest at the end,
// the static factors under full uplift at its final pose (on the flat ground, wherever it slid:
// mu (W - U) / P and W B/2 / (P d/3 + U 2B/3) for a rectangle, with U = 1/2 rho g d B, c = 1);
// nothing for a block that overturned; no check at all without a reservoir.
#include <cmath>

#include <gtest/gtest.h>

#include "engine/simulate.hpp"

namespace blockfrag {
namespace {

constexpr double kAfterG = 9.81, kAfterRho = 1000.0;

// 10 m by 16 m, mu = 0.7, the water 12 m deep against it; uplift area factor 0.5, which the check
// after the earthquake replaces by 1.
Scene after_scene(bool wet, double amplitude_g, double period = 0.5) {
  Scene scene;
  scene.block = {5.0, 8.0, 2400.0 * 160.0};
  scene.contact = {0.7, 0.2};
  scene.ground_motion = SinePulse{amplitude_g, period, 1.0};
  scene.duration.reset();  // runs until it settles
  if (wet) {
    scene.reservoir =
        Reservoir{4.0, 100.0, kAfterRho, Hydrodynamic::westergaard, UpliftRule::zero_in_gap, 0.5};
  }
  return scene;
}

TEST(PostEarthquakeCheck, AStandingBlockGetsItsFactorsUnderFullUplift) {
  const Summary summary = simulate(after_scene(true, 0.3));
  ASSERT_EQ(summary.status, Status::ok);
  ASSERT_FALSE(summary.overturned);
  ASSERT_TRUE(summary.settled);
  ASSERT_TRUE(summary.post_earthquake.has_value());
  const double w = 2400.0 * 160.0 * kAfterG, d = 12.0, b = 10.0;
  const double push = 0.5 * kAfterRho * kAfterG * d * d, u = 0.5 * kAfterRho * kAfterG * d * b;
  ASSERT_TRUE(summary.post_earthquake->sliding_safety_factor.has_value());
  EXPECT_NEAR(*summary.post_earthquake->sliding_safety_factor, 0.7 * (w - u) / push, 1e-12);
  EXPECT_NEAR(*summary.post_earthquake->overturning_safety_factor,
              w * b / 2 / (push * d / 3 + u * 2 * b / 3), 1e-12);
}

TEST(PostEarthquakeCheck, AnOverturnedBlockHasNone) {
  const Summary summary = simulate(after_scene(true, 2.0, 4.0));
  ASSERT_TRUE(summary.overturned);
  ASSERT_TRUE(summary.post_earthquake.has_value());
  EXPECT_FALSE(summary.post_earthquake->sliding_safety_factor.has_value());
  EXPECT_FALSE(summary.post_earthquake->overturning_safety_factor.has_value());
}

TEST(PostEarthquakeCheck, NoReservoirNoCheck) {
  EXPECT_FALSE(simulate(after_scene(false, 0.3)).post_earthquake.has_value());
}

}  // namespace
}  // namespace blockfrag
