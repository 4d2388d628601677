// The rock and slide-rock systems against the paper's equations worked by hand for the paper's
// block (a = 0.5, b = 1, I/M = 5/12, R = sqrt(1.25)) on its right corner, r = (0.5, -1) at
// theta = 0 (docs/references.md, "The paper the physics follows" and "Rocking without sliding"):
// theta'', the contact forces, the guards by name and the events they stand for, and the map
// between coordinates and the full state (the pivot stays on the ground where the mode says).
#include <cmath>
#include <numbers>
#include <utility>

#include <gtest/gtest.h>

#include "engine/modes/modes.hpp"
#include "tests/support/paper_block.hpp"

namespace blockfrag {
namespace {

using testing::kGravity;
using testing::paper_block;
const double R = std::sqrt(1.25);
// The systems' block and ground motions, shared by this file's tests (gtest runs them one at a
// time): each remembers the last angle or time it was asked for, so the systems hold them
// non-const.
BlockGeometry paper_geometry = paper_block();
MotionPiece lambda_one({MotionPiece::Shape::constant, 1.0}, 0.0, 10.0);
MotionPiece lambda_zero({}, 0.0, 10.0);

SystemContext context(MotionPiece& horizontal, double mu) {
  return {&paper_geometry, &horizontal, &lambda_zero, kGravity, mu};
}

// Rock (eqs. 2.6, 2.7), D = I/M + r^2 = 5/3: theta'' = g (r_x + lambda r_y) / D = g (0.5 - 1) 3/5
// = -0.3 g = -2.943 rad/s^2 at lambda = 1 (docs/references.md gives |theta''| = 2.943), whatever
// omega is; F = theta'' r_y + w^2 r_x - lambda g = -0.7 g + 0.5 w^2, V = g - theta'' r_x + w^2 r_y
// = 1.15 g - w^2.

TEST(RockSystem, AngularAccelerationIsThePapersClosedForm) {
  const RockSystem rock{context(lambda_one, 0.6), Corner::right, 0.5};
  for (const double omega : {0.0, -1.0, 2.0}) {
    OdeState<2> dq{};
    rock(0.0, {0.0, omega}, dq);
    EXPECT_EQ(dq[0], omega);
    EXPECT_NEAR(dq[1], -2.943, 1e-12) << "omega = " << omega;
  }
  // lambda = 0: theta'' = 0.5 g 3/5 = 0.3 g, falling back counter-clockwise.
  const RockSystem unforced{context(lambda_zero, 0.6), Corner::right, 0.5};
  OdeState<2> dq{};
  unforced(0.0, {0.0, 0.0}, dq);
  EXPECT_NEAR(dq[1], 0.3 * kGravity, 1e-12);
}

TEST(RockSystem, ContactForcesFollowFromTheConstraint) {
  const RockSystem rock{context(lambda_one, 0.6), Corner::right, 0.5};
  const ContactForces still = rock.forces(0.0, {0.0, 0.0});
  EXPECT_NEAR(still.friction, -0.7 * kGravity, 1e-12);  // -6.867 N/kg
  EXPECT_NEAR(still.normal, 1.15 * kGravity, 1e-12);    // 11.2815 N/kg
  const ContactForces turning = rock.forces(0.0, {0.0, -1.0});
  EXPECT_NEAR(turning.friction, -0.7 * kGravity + 0.5, 1e-12);
  EXPECT_NEAR(turning.normal, 1.15 * kGravity - 1.0, 1e-12);
}

TEST(RockSystem, GuardsMeasureWhatTheirEventsNeed) {
  EXPECT_EQ(RockSystem::kEvents[RockSystem::normal_force], GuardEvent::lift_off);
  EXPECT_EQ(RockSystem::kEvents[RockSystem::friction_cone], GuardEvent::friction_limit);
  EXPECT_EQ(RockSystem::kEvents[RockSystem::other_corner_height], GuardEvent::corner_lands);
  EXPECT_EQ(RockSystem::kEvents[RockSystem::overturn_margin], GuardEvent::overturns);
  // Per weight: V / g = 1.15; (mu V - |F|) / g = 1.15 mu - 0.7: -0.01 for mu = 0.6 (mu_cr(1) =
  // 0.6087, friction cannot hold), 0.45 for mu = 1. Flat, the other corner is at the pivot's
  // height; pi/2 from overturning.
  for (const double mu : {0.6, 1.0}) {
    const RockSystem rock{context(lambda_one, mu), Corner::right, 0.5};
    const auto guard = rock.guards(0.0, {0.0, 0.0});
    EXPECT_NEAR(guard[RockSystem::normal_force], 1.15, 1e-15);
    EXPECT_NEAR(guard[RockSystem::friction_cone], 1.15 * mu - 0.7, 1e-15);
    EXPECT_NEAR(guard[RockSystem::other_corner_height], 0.0, 1e-15);
    EXPECT_NEAR(guard[RockSystem::overturn_margin], std::numbers::pi / 2, 1e-15);
  }
  // Tilted by -0.2 rad the left corner is 2a sin(0.2) = 0.198669 m up: 0.177695 R; and
  // pi/2 - 0.2 = 1.370796 from overturning.
  const RockSystem rock{context(lambda_one, 0.6), Corner::right, 0.5};
  const auto guard = rock.guards(0.0, {-0.2, 0.0});
  EXPECT_NEAR(guard[RockSystem::other_corner_height], std::sin(0.2) / R, 1e-15);
  EXPECT_NEAR(guard[RockSystem::other_corner_height], 0.177695, 5e-7);
  EXPECT_NEAR(guard[RockSystem::overturn_margin], 1.370796, 5e-7);
}

TEST(RockSystem, FullStateKeepsThePivotStillOnTheGroundAndMapsBack) {
  // r = Rot(theta)(0.5, -1); the pivot x + r_x = pivot_x at height y + r_y = 0, its velocity
  // (vx - w r_y, vy + w r_x) = 0.
  const double pivot_x = 1.25;
  const RockSystem rock{context(lambda_one, 0.6), Corner::right, pivot_x};
  for (const OdeState<2> q :
       {OdeState<2>{0.0, 0.0}, OdeState<2>{-0.3, 1.7}, OdeState<2>{0.2, -0.4}}) {
    const BlockState s = rock.full(0.0, q);
    const double r_x = 0.5 * std::cos(q[0]) + std::sin(q[0]);
    const double r_y = 0.5 * std::sin(q[0]) - std::cos(q[0]);
    EXPECT_EQ(s.theta, q[0]);
    EXPECT_EQ(s.omega, q[1]);
    EXPECT_NEAR(s.x + r_x, pivot_x, 1e-15);
    EXPECT_NEAR(s.y + r_y, 0.0, 1e-15);
    EXPECT_NEAR(s.vx - q[1] * r_y, 0.0, 1e-15);
    EXPECT_NEAR(s.vy + q[1] * r_x, 0.0, 1e-15);
    EXPECT_EQ(rock.coordinates(s), q);
  }
}

// Slide-rock (eqs. 2.8, 2.9) slipping to +x with mu = 0.6: D+ = I/M + r_x^2 + mu r_x r_y = 5/12 +
// 1/4 - 0.3 = 11/30, theta'' = (r_x + mu r_y)(g + w^2 r_y) / D+ = -3 (g - w^2) / 11, V = g -
// theta'' r_x + w^2 r_y = 25 (g - w^2) / 22, F = -mu V, x'' = F + lambda g, and the corner's
// x'' - theta'' r_y - w^2 r_x.

TEST(SlideRockSystem, AccelerationsFollowThePapersSlipEquations) {
  // At lambda = 1, w = 0: theta'' = -3 g/11, x'' = (1 - 15/22) g = 7 g/22, corner (7 - 6) g/22.
  // At lambda = 0: theta'' the same (it does not depend on lambda), corner (-15 - 6) g/22.
  const SlideRockSystem forced{context(lambda_one, 0.6), Corner::right, 1};
  const SlideRockSystem unforced{context(lambda_zero, 0.6), Corner::right, 1};
  OdeState<4> dq{};
  forced(0.0, {0.0, 0.0, 0.5, 0.2}, dq);
  EXPECT_EQ(dq[0], 0.0);
  EXPECT_NEAR(dq[1], -3 * kGravity / 11, 1e-12);
  EXPECT_EQ(dq[2], 0.2);
  EXPECT_NEAR(dq[3], kGravity / 22, 1e-12);
  unforced(0.0, {0.0, 0.0, 0.5, 0.2}, dq);
  EXPECT_NEAR(dq[1], -3 * kGravity / 11, 1e-12);
  EXPECT_NEAR(dq[3], -21 * kGravity / 22, 1e-12);
  // w = -1: theta'' = -3 (g - 1) / 11; x'' = g - 15 (g - 1)/22; corner x'' - theta'' - 0.5.
  forced(0.0, {0.0, -1.0, 0.5, 0.2}, dq);
  EXPECT_EQ(dq[0], -1.0);
  EXPECT_NEAR(dq[1], -3 * (kGravity - 1) / 11, 1e-12);
  EXPECT_NEAR(dq[3], kGravity - 15 * (kGravity - 1) / 22 - 3 * (kGravity - 1) / 11 - 0.5, 1e-12);
}

TEST(SlideRockSystem, FrictionIsMuTimesTheNormalForceAgainstTheSlip) {
  const SlideRockSystem to_plus{context(lambda_one, 0.6), Corner::right, 1};
  const ContactForces f = to_plus.forces(0.0, {0.0, 0.0, 0.5, 0.2});
  EXPECT_NEAR(f.normal, 25 * kGravity / 22, 1e-12);
  EXPECT_NEAR(f.friction, -0.6 * 25 * kGravity / 22, 1e-12);
  // Slipping to -x: D- = 5/12 + 1/4 + 0.3 = 29/30, theta'' = (0.5 + 0.6) g 30/29 = 33 g/29,
  // V = g - 0.5 theta'' = 25 g/58, F = +0.6 V.
  const SlideRockSystem to_minus{context(lambda_one, 0.6), Corner::right, -1};
  const ContactForces f_minus = to_minus.forces(0.0, {0.0, 0.0, 0.5, -0.2});
  EXPECT_NEAR(f_minus.normal, 25 * kGravity / 58, 1e-12);
  EXPECT_NEAR(f_minus.friction, 0.6 * 25 * kGravity / 58, 1e-12);
}

TEST(SlideRockSystem, GuardsMeasureWhatTheirEventsNeed) {
  EXPECT_EQ(SlideRockSystem::kEvents[SlideRockSystem::normal_force], GuardEvent::lift_off);
  EXPECT_EQ(SlideRockSystem::kEvents[SlideRockSystem::slip_velocity], GuardEvent::slip_stops);
  EXPECT_EQ(SlideRockSystem::kEvents[SlideRockSystem::other_corner_height],
            GuardEvent::corner_lands);
  EXPECT_EQ(SlideRockSystem::kEvents[SlideRockSystem::overturn_margin], GuardEvent::overturns);
  EXPECT_EQ(SlideRockSystem::kEvents[SlideRockSystem::painleve_distance],
            GuardEvent::painleve_boundary);
  // V / g = 25/22; the slip velocity 0.2 m/s over sqrt(g R) = 3.311784 m/s; the Painleve distance
  // D+ / (I/M) - kPainleveMargin = (11/30)(12/5) - 1e-6 = 0.88 - 1e-6.
  const SlideRockSystem to_plus{context(lambda_one, 0.6), Corner::right, 1};
  const auto guard = to_plus.guards(0.0, {0.0, 0.0, 0.5, 0.2});
  EXPECT_NEAR(guard[SlideRockSystem::normal_force], 25.0 / 22, 1e-15);
  EXPECT_NEAR(guard[SlideRockSystem::slip_velocity], 0.2 / std::sqrt(kGravity * R), 1e-15);
  EXPECT_NEAR(guard[SlideRockSystem::other_corner_height], 0.0, 1e-15);
  EXPECT_NEAR(guard[SlideRockSystem::overturn_margin], std::numbers::pi / 2, 1e-15);
  EXPECT_NEAR(guard[SlideRockSystem::painleve_distance], 0.88 - 1e-6, 1e-15);
  // The slip guard is positive while the corner moves the way it slips: -0.2 m/s ends it.
  EXPECT_LT(to_plus.guards(0.0, {0.0, 0.0, 0.5, -0.2})[SlideRockSystem::slip_velocity], 0.0);
  // D+ = 2/3 - mu/2 closes with friction: mu = 1.2 leaves 1/15, (1/15)(12/5) = 0.16; past
  // mu = 4/3 it is negative (the Painleve case): 1.4 gives -1/30, -0.08.
  for (const auto& [mu, distance] : {std::pair{1.2, 0.16}, std::pair{1.4, -0.08}}) {
    const SlideRockSystem slip{context(lambda_one, mu), Corner::right, 1};
    EXPECT_NEAR(slip.guards(0.0, {0.0, 0.0, 0.5, 0.2})[SlideRockSystem::painleve_distance],
                distance - 1e-6, 1e-14)
        << "mu = " << mu;
  }
}

TEST(SlideRockSystem, FullStatePutsThePivotOnTheGroundAtItsSlipAndMapsBack) {
  // q = (theta, w, pivot x, pivot x'): the corner x + r_x = q[2] at height y + r_y = 0, moving at
  // (vx - w r_y, vy + w r_x) = (q[3], 0).
  const SlideRockSystem slip{context(lambda_one, 0.6), Corner::right, 1};
  for (const OdeState<4> q : {OdeState<4>{0.0, 0.0, 0.5, 0.2}, OdeState<4>{-0.3, 1.7, -2.0, 0.9},
                              OdeState<4>{0.2, -0.4, 3.0, 1e-3}}) {
    const BlockState s = slip.full(0.0, q);
    const double r_x = 0.5 * std::cos(q[0]) + std::sin(q[0]);
    const double r_y = 0.5 * std::sin(q[0]) - std::cos(q[0]);
    EXPECT_EQ(s.theta, q[0]);
    EXPECT_EQ(s.omega, q[1]);
    EXPECT_NEAR(s.x + r_x, q[2], 1e-15);
    EXPECT_NEAR(s.y + r_y, 0.0, 1e-15);
    EXPECT_NEAR(s.vx - q[1] * r_y, q[3], 1e-15);
    EXPECT_NEAR(s.vy + q[1] * r_x, 0.0, 1e-15);
    const OdeState<4> back = slip.coordinates(s);
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(back[i], q[i], 1e-15) << "coordinate " << i;
  }
}

}  // namespace
}  // namespace blockfrag
