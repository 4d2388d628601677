// The contact rules of the one-degree-of-freedom models against their definitions
// (docs/physics.md, "Effects: which model runs"; docs/references.md, "Rocking without sliding"
// and "Sliding without rocking"): Housner's block starts to rock past a/b about the corner lambda
// pushes towards and at each landing hands over to the other corner with omega times
// 1 - 1.5 sin^2(alpha) (unchanged without impact losses), lying flat below the settle velocity;
// Newmark's block slides from rest past |lambda| = mu and goes on while its base moves.
#include "engine/contact/reduced_contact.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "engine/tolerances.hpp"
#include "tests/support/contact_states.hpp"
#include "tests/support/paper_block.hpp"

namespace blockfrag {
namespace {

using testing::flat_state;
using testing::turning_about;

using testing::kGravity;
using testing::kPaperHalfHeight;
using testing::kPaperHalfWidth;
// The paper's block: R = sqrt(1.25), sqrt(g R) = 3.311784 m/s, base width 2a = 1 m.
using testing::paper_block;
const double sqrt_gR = std::sqrt(kGravity * std::hypot(kPaperHalfWidth, kPaperHalfHeight));

TEST(HousnerRules, StartsToRockOnlyPastTheTipThresholdAboutThePushedCorner) {
  BlockGeometry block = paper_block();
  const HousnerRules rules(block, true, kGravity);
  for (const double lambda : {0.0, 0.49, -0.49, 0.5, -0.5}) {  // |lambda| <= a/b = 0.5
    const ContactOutcome out = rules.start(flat_state(kPaperHalfHeight, 2.0), lambda);
    EXPECT_EQ(mode_kind(out.mode), ModeKind::rest) << "lambda = " << lambda;
  }
  // Past a/b: about the right corner (x + a = 2.5) for lambda > 0, the left (1.5) for lambda < 0;
  // however large lambda is, since Housner's block never slides.
  const struct {
    double lambda;
    Corner pivot;
    double pivot_x;
  } cases[] = {{0.51, Corner::right, 2.5}, {3.0, Corner::right, 2.5}, {-0.51, Corner::left, 1.5}};
  for (const auto& c : cases) {
    const ContactOutcome out = rules.start(flat_state(kPaperHalfHeight, 2.0), c.lambda);
    const auto* rock = std::get_if<RockMode>(&out.mode);
    ASSERT_NE(rock, nullptr) << "lambda = " << c.lambda;
    EXPECT_EQ(rock->pivot, c.pivot);
    EXPECT_DOUBLE_EQ(rock->pivot_x, c.pivot_x);
    EXPECT_EQ(out.state.omega, 0.0);
  }
}

TEST(HousnerRules, ABlockReleasedTiltedRocksOnItsLowerCorner) {
  // Tilted clockwise (theta < 0) the right corner is the lower one, whatever lambda says.
  BlockGeometry block = paper_block();
  for (const double lambda : {0.0, -2.0}) {
    const ContactOutcome out =
        HousnerRules(block, true, kGravity)
            .start(turning_about(kPaperHalfWidth, kPaperHalfHeight, -0.1, 0.0, 4.0), lambda);
    const auto* rock = std::get_if<RockMode>(&out.mode);
    ASSERT_NE(rock, nullptr) << "lambda = " << lambda;
    EXPECT_EQ(rock->pivot, Corner::right);
    EXPECT_NEAR(rock->pivot_x, 4.0, 1e-15);
  }
}

TEST(HousnerRules, ALandingHandsOverToTheOtherCornerWithHousnersRatio) {
  // a/b = 0.5: sin^2(alpha) = 0.2, omega+ = 0.7 omega-. Coming back about the right corner
  // (omega > 0) to theta = 0, it goes on about the left one at x - a = -0.5, the centre moving
  // at omega+ x (centre - corner) = (-omega+ b, omega+ a) = (-0.7, 0.35).
  BlockGeometry block = paper_block();
  EXPECT_NEAR(housner_impact_ratio(block, Corner::right), 0.7, 1e-15);
  EXPECT_NEAR(housner_impact_ratio(block, Corner::left), 0.7, 1e-15);
  const ContactOutcome out =
      HousnerRules(block, true, kGravity)
          .impact(turning_about(kPaperHalfWidth, kPaperHalfHeight, 0.0, 1.0, kPaperHalfWidth),
                  Corner::right, 0.0);
  EXPECT_TRUE(out.impact);
  const auto* rock = std::get_if<RockMode>(&out.mode);
  ASSERT_NE(rock, nullptr);
  EXPECT_EQ(rock->pivot, Corner::left);
  EXPECT_NEAR(rock->pivot_x, -kPaperHalfWidth, 1e-15);
  EXPECT_NEAR(out.state.omega, 0.7, 1e-15);
  EXPECT_NEAR(out.state.vx, -0.7, 1e-15);
  EXPECT_NEAR(out.state.vy, 0.35, 1e-15);
  EXPECT_EQ(out.state.theta, 0.0);
}

TEST(HousnerRules, WithoutImpactLossesTheHandOverKeepsOmega) {
  // effects ["rocking"]: the pivot changes, omega and the energy do not; no impact is counted.
  BlockGeometry block = paper_block();
  const ContactOutcome out =
      HousnerRules(block, false, kGravity)
          .impact(turning_about(-kPaperHalfWidth, kPaperHalfHeight, 0.0, -2.0, -kPaperHalfWidth),
                  Corner::left, 0.0);
  EXPECT_FALSE(out.impact);
  const auto* rock = std::get_if<RockMode>(&out.mode);
  ASSERT_NE(rock, nullptr);
  EXPECT_EQ(rock->pivot, Corner::right);
  EXPECT_NEAR(rock->pivot_x, kPaperHalfWidth, 1e-15);
  EXPECT_EQ(out.state.omega, -2.0);
}

TEST(HousnerRules, ALandingSlowerThanTheSettleVelocityLaysTheBlockFlat) {
  // The other corner lands at |omega| 2a; once slower than kSettleVelocity sqrt(g R) =
  // 1.4803675e-4 m/s (after the impact's 0.7) the block lies flat: omega = 2e-4 rad/s leaves
  // 1.4e-4 m/s (flat, at rest under lambda = 0), 2.2e-4 leaves 1.54e-4 (rocks on). Without losses
  // 2e-4 stays 2e-4: it rocks on. Flat under lambda = 0.6 > a/b it starts to rock again at once.
  ASSERT_NEAR(kSettleVelocity * sqrt_gR, 1.4803675e-4, 5e-12);
  BlockGeometry block = paper_block();
  const HousnerRules lossy(block, true, kGravity), lossless(block, false, kGravity);
  const auto after = [&](const HousnerRules& rules, double omega, double lambda) {
    return rules.impact(
        turning_about(kPaperHalfWidth, kPaperHalfHeight, 0.0, omega, kPaperHalfWidth),
        Corner::right, lambda);
  };
  const ContactOutcome settled = after(lossy, 2e-4, 0.0);
  EXPECT_EQ(mode_kind(settled.mode), ModeKind::rest);
  EXPECT_EQ(settled.state.omega, 0.0);
  EXPECT_EQ(settled.state.y, kPaperHalfHeight);
  EXPECT_EQ(mode_kind(after(lossy, 2.2e-4, 0.0).mode), ModeKind::rock);
  EXPECT_EQ(mode_kind(after(lossless, 2e-4, 0.0).mode), ModeKind::rock);
  const ContactOutcome pushed = after(lossy, 2e-4, 0.6);
  const auto* rock = std::get_if<RockMode>(&pushed.mode);
  ASSERT_NE(rock, nullptr);
  EXPECT_EQ(rock->pivot, Corner::right);
  EXPECT_EQ(pushed.state.omega, 0.0);
}

TEST(NewmarkRules, SlidesFromRestOnlyPastFriction) {
  const NewmarkRules rules(paper_block(), 0.3, kGravity);
  for (const double lambda : {0.0, 0.29, -0.3}) {
    EXPECT_EQ(mode_kind(rules.resolve(flat_state(kPaperHalfHeight), lambda).mode), ModeKind::rest)
        << "lambda = " << lambda;
  }
  // Past mu the way lambda pushes; never rocks, even past a/b = 0.5.
  for (const double lambda : {0.31, -0.31, 0.9, -5.0}) {
    const ContactOutcome out = rules.resolve(flat_state(kPaperHalfHeight), lambda);
    const auto* slide = std::get_if<SlideMode>(&out.mode);
    ASSERT_NE(slide, nullptr) << "lambda = " << lambda;
    EXPECT_EQ(slide->slip_sign, lambda > 0 ? 1 : -1) << "lambda = " << lambda;
  }
}

TEST(NewmarkRules, KeepsSlidingWhileTheBaseMovesAndRestsOnceItStops) {
  // The resting velocity is kRestingVelocity sqrt(g R) = 3.311784e-9 m/s.
  const NewmarkRules rules(paper_block(), 0.3, kGravity);
  const auto moving = [&](double vx) {
    BlockState s = flat_state(kPaperHalfHeight);
    s.vx = vx;
    return s;
  };
  // Moving, it slides the way it moves, whatever lambda (even against it, even below mu).
  for (const double vx : {0.2, -0.2, 1e-8, -1e-8}) {
    const ContactOutcome out = rules.resolve(moving(vx), vx > 0 ? -0.1 : 0.1);
    const auto* slide = std::get_if<SlideMode>(&out.mode);
    ASSERT_NE(slide, nullptr) << "vx = " << vx;
    EXPECT_EQ(slide->slip_sign, vx > 0 ? 1 : -1) << "vx = " << vx;
  }
  // Slower than the resting velocity it has stopped: rest, vx = 0, unless lambda passes mu.
  const ContactOutcome stopped = rules.resolve(moving(2e-9), 0.1);
  EXPECT_EQ(mode_kind(stopped.mode), ModeKind::rest);
  EXPECT_EQ(stopped.state.vx, 0.0);
  const ContactOutcome pushed = rules.resolve(moving(2e-9), -0.5);
  const auto* restart = std::get_if<SlideMode>(&pushed.mode);
  ASSERT_NE(restart, nullptr);
  EXPECT_EQ(restart->slip_sign, -1);
}

}  // namespace
}  // namespace blockfrag
