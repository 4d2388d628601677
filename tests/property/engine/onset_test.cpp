// Onset from rest (Shenton 1996): when and in which mode a resting block starts to move.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "engine/simulate.hpp"
#include "tests/support/scene_builders.hpp"

namespace blockfrag {
namespace {

using testing::block_scene;

double shenton_mu_cr(double A, double beta) {
  return (A * (4 * beta * beta + 1) + 3 * beta) / (beta * beta + 4 + 3 * A * beta);
}

TEST(Onset, RockingStartsWhenLambdaFirstExceedsAspectRatio) {
  // lambda = sin(pi t) crosses a/b = 0.5 at t = 1/6 s.
  const Summary s = simulate(block_scene(0.5, 1.0, 2.0, 0.5, SinePulse{1.0, 2.0, 1.0}, 0.5));
  ASSERT_TRUE(s.rock_start_time.has_value());
  EXPECT_NEAR(*s.rock_start_time, 1.0 / 6.0, 1e-9);
  EXPECT_FALSE(s.slide_start_time.has_value());
  EXPECT_EQ(s.modes.at(1).mode, ModeKind::rock);
}

TEST(Onset, SlidingStartsWhenLambdaFirstExceedsFriction) {
  const double mu = 0.3;  // < a/b = 0.5: the block cannot rock
  const Summary s = simulate(block_scene(0.5, 1.0, mu, 0.5, SinePulse{1.0, 2.0, 1.0}, 0.5));
  ASSERT_TRUE(s.slide_start_time.has_value());
  EXPECT_NEAR(*s.slide_start_time, std::asin(mu) / std::numbers::pi, 1e-9);
  EXPECT_FALSE(s.rock_start_time.has_value());
}

TEST(Onset, NothingMovesBelowBothThresholds) {
  const Summary s = simulate(block_scene(0.5, 1.0, 0.6, 0.5, CosinePulse{0.45, 1.0, 3.0}, 4.0));
  EXPECT_EQ(s.max_abs_theta, 0.0);
  EXPECT_EQ(s.max_abs_slide, 0.0);
  ASSERT_EQ(s.modes.size(), 1u);
  EXPECT_EQ(s.modes[0].mode, ModeKind::rest);
}

TEST(Onset, RockOrSlideRockFollowsShentonsCriticalFriction) {
  // A step of lambda = A: rock if mu >= mu_cr(A), slide-rock below (beta = 0.5).
  const double beta = 0.5;
  for (const double A : {0.6, 0.75, 1.5, 2.0}) {
    const double mu_cr = shenton_mu_cr(A, beta);
    for (const double factor : {0.99, 1.01}) {
      const double mu = factor * mu_cr;
      const Summary s = simulate(block_scene(0.5, 1.0, mu, 0.5, RectangularPulse{A, 0.05}, 0.05));
      const ModeKind expected = factor > 1 ? ModeKind::rock : ModeKind::slide_rock;
      EXPECT_EQ(s.modes.at(0).mode, expected) << "A = " << A << " mu = " << mu;
      ASSERT_TRUE(s.rock_start_time.has_value()) << "A = " << A << " mu = " << mu;
      EXPECT_EQ(*s.rock_start_time, 0.0);
    }
  }
  EXPECT_NEAR(shenton_mu_cr(0.6, beta), 0.524272, 1e-6);
  EXPECT_NEAR(shenton_mu_cr(2.0, beta), 0.758621, 1e-6);
}

TEST(Onset, SlenderBlockWithLowFrictionSlidesFlat) {
  // mu < beta < A: slide, never rock.
  const Summary s = simulate(block_scene(0.5, 1.0, 0.4, 0.5, RectangularPulse{0.8, 0.2}, 1.0));
  EXPECT_EQ(s.modes.at(0).mode, ModeKind::slide);
  EXPECT_EQ(s.max_abs_theta, 0.0);
}

}  // namespace
}  // namespace blockfrag
