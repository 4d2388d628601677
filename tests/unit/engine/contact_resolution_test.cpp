// ContactResolver on a block at rest flat on its base, against Shenton's onset criteria worked by
// hand for the paper's block (a = 0.5, b = 1, a/b = 0.5; docs/references.md, "Onset from rest"):
// rest, slide, rock about the corner lambda pushes towards, slide-rock where friction is below
// mu_cr; and no contact at all when the ground falls faster than g ("Vertical ground motion").
#include "engine/contact/contact_resolution.hpp"

#include <gtest/gtest.h>

#include "tests/support/contact_states.hpp"
#include "tests/support/paper_block.hpp"

namespace blockfrag {
namespace {

using testing::flat_state;

using testing::kGravity;

// The paper's block, resting flat with its centre of mass at x.
ContactOutcome resolve_from_rest(double mu, double lambda, double gravity_factor = 1.0,
                                 double x = 0.0) {
  BlockGeometry geometry(RectangularBlock{0.5, 1.0, 1.0});
  const ContactResolver resolver(geometry, Contact{mu, 0.6}, kGravity);
  return resolver.resolve(flat_state(1.0, x), lambda, gravity_factor);
}

// Shenton's mu_cr(A) = [A (4 beta^2 + 1) + 3 beta] / [beta^2 + 4 + 3 A beta] for beta = 0.5:
// (2 A + 1.5) / (4.25 + 1.5 A), the |F|/V a sticking corner needs from rest.
double mu_cr(double A) { return (2 * A + 1.5) / (4.25 + 1.5 * A); }

TEST(ContactResolverFromRest, RestsWhileLambdaStaysBelowFrictionAndTheTipThreshold) {
  // mu = 0.6, a/b = 0.5: rest while |lambda| <= min(mu, a/b) = 0.5.
  for (const double lambda : {0.0, 0.3, -0.45, 0.49, -0.49}) {
    const ContactOutcome out = resolve_from_rest(0.6, lambda, 1.0, 2.0);
    EXPECT_EQ(mode_kind(out.mode), ModeKind::rest) << "lambda = " << lambda;
    EXPECT_FALSE(out.impact);
    EXPECT_EQ(out.state.x, 2.0);
    EXPECT_EQ(out.state.y, 1.0);
    EXPECT_EQ(out.state.theta, 0.0);
    EXPECT_EQ(out.state.vx, 0.0);
    EXPECT_EQ(out.state.omega, 0.0);
  }
}

TEST(ContactResolverFromRest, SlidesTheWayLambdaPushesWhenFrictionIsBelowTheTipThreshold) {
  // mu = 0.3 < a/b = 0.5: past |lambda| = 0.3 the base slides with sign(lambda), also past a/b
  // (Shenton: a block with mu <= a/b never starts to rock). Slide-rock about the right corner would
  // have theta'' = (r_x + mu r_y) g / (I/M + r_x^2 + mu r_x r_y) = (0.5 - 0.3) g / 0.516667 > 0:
  // counter-clockwise, pressing the left corner into the ground, so nothing lifts.
  for (const double lambda : {0.31, 0.45, 0.8, 3.0}) {
    for (const int sign : {1, -1}) {
      const ContactOutcome out = resolve_from_rest(0.3, sign * lambda);
      const auto* slide = std::get_if<SlideMode>(&out.mode);
      ASSERT_NE(slide, nullptr) << "lambda = " << sign * lambda << ": "
                                << mode_name(mode_kind(out.mode));
      EXPECT_EQ(slide->slip_sign, sign) << "lambda = " << sign * lambda;
    }
  }
}

TEST(ContactResolverFromRest, RocksAboutTheCornerLambdaPushesTowardsWithHighFriction) {
  // mu = 1 > mu_cr(0.8) = (1.6 + 1.5) / (4.25 + 1.2) = 0.568807: past a/b = 0.5 it rocks. A
  // positive lambda pushes the block to +x, about its right corner at x + a = 2.5; a negative one
  // about its left corner at x - a = 1.5.
  ASSERT_NEAR(mu_cr(0.8), 3.1 / 5.45, 1e-15);
  const struct {
    double lambda;
    Corner pivot;
    double pivot_x;
  } cases[] = {{0.8, Corner::right, 2.5}, {-0.8, Corner::left, 1.5}, {0.51, Corner::right, 2.5}};
  for (const auto& c : cases) {
    const ContactOutcome out = resolve_from_rest(1.0, c.lambda, 1.0, 2.0);
    const auto* rock = std::get_if<RockMode>(&out.mode);
    ASSERT_NE(rock, nullptr) << "lambda = " << c.lambda << ": " << mode_name(mode_kind(out.mode));
    EXPECT_EQ(rock->pivot, c.pivot) << "lambda = " << c.lambda;
    EXPECT_DOUBLE_EQ(rock->pivot_x, c.pivot_x) << "lambda = " << c.lambda;
  }
}

TEST(ContactResolverFromRest, ThePapersBlockSlipsAsItStartsToRockAtLambdaOne) {
  // docs/references.md, "Onset from rest": mu_cr(1) = 3.5 / 5.75 = 0.6087 > mu = 0.6, so the
  // sticking corner's friction would leave the cone: slide-rock about the right corner. Sticking
  // needs F = -0.7 M g (towards -x), so the corner slips towards +x. Slipping, by eqs. 2.8-2.9:
  // theta'' = (0.5 - 0.6) g / (5/12 + 1/4 - 0.3) = -3 g / 11, V = g (1 + 3/22) = 25 g / 22,
  // x'' = (1 - 0.6 * 25/22) g = 7 g / 22, and the corner's x'' - theta'' r_y = (7 - 6) g / 22 > 0:
  // it does slip towards +x. Mirrored for lambda = -1.
  EXPECT_NEAR(mu_cr(1.0), 0.6087, 5e-5);
  {
    const ContactOutcome out = resolve_from_rest(0.6, 1.0);
    const auto* slide_rock = std::get_if<SlideRockMode>(&out.mode);
    ASSERT_NE(slide_rock, nullptr) << mode_name(mode_kind(out.mode));
    EXPECT_EQ(slide_rock->pivot, Corner::right);
    EXPECT_EQ(slide_rock->slip_sign, 1);
  }
  {
    const ContactOutcome out = resolve_from_rest(0.6, -1.0);
    const auto* slide_rock = std::get_if<SlideRockMode>(&out.mode);
    ASSERT_NE(slide_rock, nullptr) << mode_name(mode_kind(out.mode));
    EXPECT_EQ(slide_rock->pivot, Corner::left);
    EXPECT_EQ(slide_rock->slip_sign, -1);
  }
  // Just above mu_cr(1) friction holds the corner: pure rocking.
  const ContactOutcome out = resolve_from_rest(0.61, 1.0);
  const auto* rock = std::get_if<RockMode>(&out.mode);
  ASSERT_NE(rock, nullptr) << mode_name(mode_kind(out.mode));
  EXPECT_EQ(rock->pivot, Corner::right);
}

TEST(ContactResolverFromRest, NothingHoldsTheBlockWhenTheGroundFallsFasterThanG) {
  // gravity_factor = 1 + lambda_v <= 0: no load on the contact, the block flies.
  for (const double factor : {0.0, -0.5}) {
    EXPECT_EQ(mode_kind(resolve_from_rest(0.6, 0.0, factor).mode), ModeKind::flight)
        << "1 + lambda_v = " << factor;
  }
  EXPECT_EQ(mode_kind(resolve_from_rest(0.6, 0.0, 1.0).mode), ModeKind::rest);
}

TEST(ContactResolverFromRest, VerticalMotionScalesTheTipThreshold) {
  // docs/references.md, "Vertical ground motion": it rocks once lambda > (a/b)(1 + lambda_v).
  // lambda = 0.3 with 1 + lambda_v = 0.5: 0.3 > 0.25, rocks (mu = 1 > mu_cr(0.6) = 0.524272);
  // with 1 + lambda_v = 0.7: 0.3 < 0.35, rests.
  EXPECT_EQ(mode_kind(resolve_from_rest(1.0, 0.3, 0.5).mode), ModeKind::rock);
  EXPECT_EQ(mode_kind(resolve_from_rest(1.0, 0.3, 0.7).mode), ModeKind::rest);
}

}  // namespace
}  // namespace blockfrag
