// ContactResolver on a block turning about one base corner that touches the ground with no normal
// velocity: stick while Coulomb holds the sticking corner's friction (|F| <= mu V, eq. 2.7), else
// slip the way friction fails (eqs. 2.8-2.9), lift off when the free corner rises; a corner already
// slipping goes on slipping, or jams into stick past the Painleve boundary. Expected modes from
// the paper's equations (docs/references.md, "The paper the physics follows") worked by hand for
// the paper's block (a = 0.5, b = 1, I/M = 5/12) on its right corner, r = (0.5, -1).
#include <cmath>

#include <gtest/gtest.h>

#include "engine/contact/contact_resolution.hpp"
#include "tests/support/contact_states.hpp"
#include "tests/support/paper_block.hpp"

namespace blockfrag {
namespace {

using testing::turning_about;

using testing::kGravity;
using testing::kPaperHalfHeight;
using testing::kPaperHalfWidth;

// The paper's block turning at omega about its right (corner_x = a) or left (-a) corner at x = 0.
ContactOutcome resolve_turning(double corner_x, double theta, double omega, double lambda,
                               double mu, double extra_vx = 0.0) {
  BlockGeometry geometry(RectangularBlock{kPaperHalfWidth, kPaperHalfHeight, 1.0});
  const ContactResolver resolver(geometry, Contact{mu, 0.5}, kGravity);
  BlockState s = turning_about(corner_x, kPaperHalfHeight, theta, omega, 0.0);
  s.vx += extra_vx;
  return resolver.resolve(s, lambda);
}

// At theta = 0 on the right corner with omega < 0 the left corner is at the ground but rising at
// u_y = -omega (2a) > 0: only the right one is in contact. With D = I/M + r^2 = 5/3, eq. 2.6 gives
// theta'' = g (0.5 - lambda) 3/5 and eq. 2.7 F = -0.3 g - 0.4 lambda g + 0.5 w^2,
// V = 0.85 g + 0.3 lambda g - w^2 (per unit mass).

TEST(ContactResolverOneCorner, SticksWhileFrictionHoldsAndSlipsTheWayItFailsOtherwise) {
  // lambda = 1, w = -1: F = -0.7 g + 0.5 = -6.367, V = 1.15 g - 1 = 10.2815, |F|/V = 0.619268.
  // mu = 0.7 holds it: rock about the right corner (at x = 0). mu = 0.6 does not: F < 0 would
  // hold the corner back from +x, so it slips to +x. Slipping (s = +1, D+ = 5/12 + 1/4 - 0.3 =
  // 11/30): theta'' = -0.1 (g - 1) 30/11 = -2.402727, V = 10.011364, x'' = -0.6 V + g = 3.803182,
  // corner x'' - theta'' r_y - w^2 r_x = 3.803182 - 2.402727 - 0.5 = 0.900455 > 0: consistent.
  {
    const ContactOutcome out = resolve_turning(kPaperHalfWidth, 0.0, -1.0, 1.0, 0.7);
    const auto* rock = std::get_if<RockMode>(&out.mode);
    ASSERT_NE(rock, nullptr) << mode_name(mode_kind(out.mode));
    EXPECT_EQ(rock->pivot, Corner::right);
    EXPECT_NEAR(rock->pivot_x, 0.0, 1e-15);
    EXPECT_FALSE(out.impact);
    EXPECT_DOUBLE_EQ(out.state.omega, -1.0);
  }
  {
    const ContactOutcome out = resolve_turning(kPaperHalfWidth, 0.0, -1.0, 1.0, 0.6);
    const auto* slide_rock = std::get_if<SlideRockMode>(&out.mode);
    ASSERT_NE(slide_rock, nullptr) << mode_name(mode_kind(out.mode));
    EXPECT_EQ(slide_rock->pivot, Corner::right);
    EXPECT_EQ(slide_rock->slip_sign, 1);
  }
  {  // Mirrored: the left corner, omega = +1, lambda = -1.
    const ContactOutcome out = resolve_turning(-kPaperHalfWidth, 0.0, 1.0, -1.0, 0.6);
    const auto* slide_rock = std::get_if<SlideRockMode>(&out.mode);
    ASSERT_NE(slide_rock, nullptr) << mode_name(mode_kind(out.mode));
    EXPECT_EQ(slide_rock->pivot, Corner::left);
    EXPECT_EQ(slide_rock->slip_sign, -1);
  }
}

TEST(ContactResolverOneCorner, ATiltedCornerSticksJustInsideTheConeAndSlipsJustOutside) {
  // Tilted clockwise by 0.2 rad on its right corner, at rest, lambda = 0.9: only that corner
  // touches (the left one is sin(0.2) = 0.198669 above). Eqs. 2.6, 2.7 at r = Rot(-0.2)(0.5, -1)
  // = (0.291364, -1.079401), w = 0: theta'' = -4.003052, F = theta'' r_y - lambda g = -4.508101,
  // V = g - theta'' r_x = 10.976345, |F|/V = 0.410711 (computed below from the same equations).
  // 1 % inside the cone: rock. 1 % outside: slip to +x (F < 0), where slipping gives
  // D+ = 0.373683 > 0, V = 10.938404 > 0 and the corner's acceleration 0.201066 > 0.
  const double theta = -0.2, lambda = 0.9,
               k2 = (kPaperHalfWidth * kPaperHalfWidth + kPaperHalfHeight * kPaperHalfHeight) / 3;
  const double r_x = kPaperHalfWidth * std::cos(theta) + kPaperHalfHeight * std::sin(theta);
  const double r_y = kPaperHalfWidth * std::sin(theta) - kPaperHalfHeight * std::cos(theta);
  const double theta_dd = kGravity * (r_x + lambda * r_y) / (k2 + r_x * r_x + r_y * r_y);
  const double F = theta_dd * r_y - lambda * kGravity, V = kGravity - theta_dd * r_x;
  EXPECT_NEAR(std::abs(F) / V, 0.410711, 5e-7);
  {
    const ContactOutcome out =
        resolve_turning(kPaperHalfWidth, theta, 0.0, lambda, 1.01 * std::abs(F) / V);
    const auto* rock = std::get_if<RockMode>(&out.mode);
    ASSERT_NE(rock, nullptr) << mode_name(mode_kind(out.mode));
    EXPECT_EQ(rock->pivot, Corner::right);
  }
  {
    const ContactOutcome out =
        resolve_turning(kPaperHalfWidth, theta, 0.0, lambda, 0.99 * std::abs(F) / V);
    const auto* slide_rock = std::get_if<SlideRockMode>(&out.mode);
    ASSERT_NE(slide_rock, nullptr) << mode_name(mode_kind(out.mode));
    EXPECT_EQ(slide_rock->pivot, Corner::right);
    EXPECT_EQ(slide_rock->slip_sign, 1);
  }
}

TEST(ContactResolverOneCorner, ACornerWhoseStickNeedsAPullLiftsOffWhenItsFreeMotionRises) {
  // lambda = 0, w = -3.5: V = 0.85 g - 12.25 = -3.9115 < 0, sticking would need a pull. Slipping
  // either way, eq. 2.9 in eq. 2.7's V gives V = (g + w^2 r_y) (I/M) / D_s = -2.44 (5/12) / D_s:
  // -2.772727 (D+ = 11/30) and -1.051724 (D- = 29/30), a pull too. Free, the corner accelerates
  // upward at -g - w^2 r_y = 2.44 > 0: it lifts off.
  const ContactOutcome out = resolve_turning(kPaperHalfWidth, 0.0, -3.5, 0.0, 0.6);
  EXPECT_EQ(mode_kind(out.mode), ModeKind::flight);
}

TEST(ContactResolverOneCorner, ACornerWhoseStickNeedsAPullSlipsWhereSlippingStillPresses) {
  // lambda = 0, w = -3: sticking V = 0.85 g - 9 = -0.6615 < 0 pulls, but g + w^2 r_y = 0.81 > 0.
  // F = -0.3 g + 4.5 = 1.557 > 0. Slipping to -x (D- = 5/12 + 1/4 + 0.3 = 29/30):
  // theta'' = 1.1 (0.81) 30/29 = 0.921724, V = 0.81 (5/12) 30/29 = 0.349138 > 0, x'' = 0.6 V =
  // 0.209483, corner x'' - theta'' r_y - w^2 r_x = 0.209483 + 0.921724 - 4.5 = -3.368793 < 0:
  // consistent. To +x (D+ = 11/30): V = 0.920455 but the corner accelerates at -5.273182 < 0:
  // not. Slide-rock to -x.
  const ContactOutcome out = resolve_turning(kPaperHalfWidth, 0.0, -3.0, 0.0, 0.6);
  const auto* slide_rock = std::get_if<SlideRockMode>(&out.mode);
  ASSERT_NE(slide_rock, nullptr) << mode_name(mode_kind(out.mode));
  EXPECT_EQ(slide_rock->pivot, Corner::right);
  EXPECT_EQ(slide_rock->slip_sign, -1);
}

TEST(ContactResolverOneCorner, ASlippingCornerGoesOnSlippingWhereFrictionCouldHoldItStuck) {
  // lambda = 0, w = -1, the right corner slipping at u_x = +-0.5 m/s with mu = 0.9. Stuck, it
  // would need |F|/V = |-0.3 g + 0.5| / (0.85 g - 1) = 0.332902 < mu; but it slips, and slipping
  // is well posed (D+ = 2/3 - 0.45 > 0, D- = 2/3 + 0.45) with V = (g - 1)(5/12)/D > 0.
  for (const double u_x : {0.5, -0.5}) {
    const ContactOutcome out = resolve_turning(kPaperHalfWidth, 0.0, -1.0, 0.0, 0.9, u_x);
    const auto* slide_rock = std::get_if<SlideRockMode>(&out.mode);
    ASSERT_NE(slide_rock, nullptr) << "u_x = " << u_x << ": " << mode_name(mode_kind(out.mode));
    EXPECT_EQ(slide_rock->pivot, Corner::right);
    EXPECT_EQ(slide_rock->slip_sign, u_x > 0 ? 1 : -1);
    EXPECT_FALSE(out.painleve);
  }
}

TEST(ContactResolverOneCorner, ASlipPastThePainleveBoundaryJamsIntoStick) {
  // mu = 2, slipping to +x: D+ = 5/12 + 1/4 - 2 (0.5) = -1/3 <= 0, no slip solution. A tangential
  // impulse stops the corner (u_x = 0, u_y still 0) and takes kinetic energy away
  // (Delta T = -a3 u_x^2 / (2 det) < 0, engine/contact/impact.cpp); then friction mu = 2 holds it.
  const double u_x = 0.5;
  const ContactOutcome out = resolve_turning(kPaperHalfWidth, 0.0, -1.0, 0.0, 2.0, u_x);
  EXPECT_TRUE(out.painleve);
  const auto* rock = std::get_if<RockMode>(&out.mode);
  ASSERT_NE(rock, nullptr) << mode_name(mode_kind(out.mode));
  EXPECT_EQ(rock->pivot, Corner::right);
  const BlockState& s = out.state;
  EXPECT_NEAR(s.vx - s.omega * -kPaperHalfHeight, 0.0, 1e-12);  // the corner's u_x
  EXPECT_NEAR(s.vy + s.omega * kPaperHalfWidth, 0.0, 1e-12);    // and u_y
  BlockState before = turning_about(kPaperHalfWidth, kPaperHalfHeight, 0.0, -1.0, 0.0);
  before.vx += u_x;
  EXPECT_LT(testing::rectangle_kinetic_energy(kPaperHalfWidth, kPaperHalfHeight, s),
            testing::rectangle_kinetic_energy(kPaperHalfWidth, kPaperHalfHeight, before));
}

}  // namespace
}  // namespace blockfrag
