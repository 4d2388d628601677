// The rocking restitution rule (engine/contact/rocking_restitution.hpp) against closed forms: a
// given r leaves the block turning about the landing corner at r omega-, Housner's value is the
// plastic sticking impulse (angular momentum about the landing corner conserved), no given r adds
// kinetic energy, the landing corner must be able to stick, and the rule turns with the ground.
#include "engine/contact/rocking_restitution.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <utility>
#include <variant>

#include <gtest/gtest.h>

#include "engine/contact/contact_resolution.hpp"
#include "engine/contact/planar_impact.hpp"
#include "tests/support/contact_states.hpp"

namespace blockfrag {
namespace {

constexpr double kRockingUnitStill = 1e-9;  // m/s
const RockingRestitution kHousnersValue{true, 1.0};

RockingRestitution given_ratio(double r) { return {false, r}; }

// The block turns at omega about `pivot` (it does not move) with `landing` on the ground too; both
// minus the centre of mass, the ground flat. The landing corner is contact 0.
RockingImpactInput turning_onto(Vec2 pivot, Vec2 landing, double omega, double k2, double mu,
                                RockingRestitution r) {
  return {{{landing, {0.0, 1.0}}, {pivot, {0.0, 1.0}}},
          0,
          {omega * pivot.y, -omega * pivot.x, omega},
          k2,
          mu,
          kRockingUnitStill,
          r};
}

double rocking_unit_energy(const RigidVelocity& v, double k2) {
  return 0.5 * (v.vx * v.vx + v.vy * v.vy + k2 * v.omega * v.omega);
}

// Angular momentum per unit mass about the point at p (minus the centre of mass).
double momentum_about(Vec2 p, const RigidVelocity& v, double k2) {
  return k2 * v.omega - (p.x * v.vy - p.y * v.vx);
}

// A rectangle of half-sizes a, b turning counter-clockwise about its right corner: its left one
// lands.
struct RockingRectangle {
  double a, b;
  Vec2 right() const { return {a, -b}; }
  Vec2 left() const { return {-a, -b}; }
  double k2() const { return (a * a + b * b) / 3.0; }
  RockingImpactInput landing(double mu, RockingRestitution r, double omega = 1.7) const {
    return turning_onto(right(), left(), omega, k2(), mu, r);
  }
};

TEST(RockingRestitution, AGivenRatioLeavesTheBlockTurningAboutTheLandingCornerAtRTimesOmega) {
  const RockingRectangle block{0.3, 1.0};
  const double omega = 1.7;
  for (const double r : {0.2, 0.6, 1.0}) {
    SCOPED_TRACE(r);
    const RockingImpactInput in = block.landing(5.0, given_ratio(r), omega);
    const auto impact = rocking_impact(in);
    ASSERT_TRUE(impact.has_value());
    EXPECT_DOUBLE_EQ(impact->after.omega, r * omega);
    EXPECT_FALSE(impact->energy_capped);
    const ContactVelocity landing = contact_velocity(in.touching[0], impact->after);
    EXPECT_NEAR(landing.tangent, 0.0, 1e-15);
    EXPECT_NEAR(landing.normal, 0.0, 1e-15);
    // The old pivot rises at omega+ times the base's width.
    EXPECT_NEAR(contact_velocity(in.touching[1], impact->after).normal, 2.0 * block.a * r * omega,
                1e-14);
    // The corners are equally far from the centre of mass: the energy falls by r^2.
    EXPECT_NEAR(rocking_unit_energy(impact->after, block.k2()) /
                    rocking_unit_energy(in.velocity, block.k2()),
                r * r, 1e-14);
  }
}

TEST(RockingRestitution, HousnersValueIsOneMinusThreeHalvesSinSquaredAlphaFromThePlasticImpulse) {
  for (const double a : {0.1, 0.25, 0.5}) {
    SCOPED_TRACE(a);
    const RockingRectangle block{a, 1.0};
    const RockingImpactInput in = block.landing(5.0, kHousnersValue);
    const auto impact = rocking_impact(in);
    ASSERT_TRUE(impact.has_value());
    const double sin2 = a * a / (a * a + 1.0);
    EXPECT_NEAR(impact->after.omega / in.velocity.omega, 1.0 - 1.5 * sin2, 1e-14);
    EXPECT_NEAR(angular_momentum_ratio(block.right(), block.left(), block.k2()), 1.0 - 1.5 * sin2,
                1e-15);
    // Newton's law with e = 0 at the landing corner, as a seat's single contact applies it.
    const PlanarImpact plastic =
        resolve_contact_impact({{in.touching[0]}, in.velocity, block.k2(), 5.0, 0.0, 1.0});
    EXPECT_EQ(impact->after.vx, plastic.after.vx);
    EXPECT_EQ(impact->after.vy, plastic.after.vy);
    EXPECT_EQ(impact->after.omega, plastic.after.omega);
  }
}

// A polygon whose base corners are at different distances from the centre of mass.
struct LopsidedBlock {
  BlockGeometry geometry{PolygonBlock{{{0.0, 0.0}, {1.0, 0.0}, {0.3, 2.0}, {0.0, 2.0}}, 1.0}};
  Vec2 near() const { return nearer_first()[0]; }
  Vec2 far() const { return nearer_first()[1]; }
  double k2() const { return geometry.inertia_per_mass(); }
  std::array<Vec2, 2> nearer_first() const {
    const Vec2 l = geometry.base_corner(Corner::left), r = geometry.base_corner(Corner::right);
    return l.x * l.x + l.y * l.y < r.x * r.x + r.y * r.y ? std::array{l, r} : std::array{r, l};
  }
  // omega's sign that brings `landing` down while turning about `pivot` (on one base line).
  static double omega_onto(Vec2 pivot, Vec2 landing) { return landing.x < pivot.x ? 1.3 : -1.3; }
};

TEST(RockingRestitution, HousnersValueOfAPolygonConservesAngularMomentumAboutTheLandingCorner) {
  const LopsidedBlock block;
  ASSERT_GT(std::abs(std::hypot(block.far().x, block.far().y) -
                     std::hypot(block.near().x, block.near().y)),
            0.05);
  for (const auto& [pivot, landing] :
       {std::pair{block.near(), block.far()}, std::pair{block.far(), block.near()}}) {
    const RockingImpactInput in = turning_onto(
        pivot, landing, LopsidedBlock::omega_onto(pivot, landing), block.k2(), 5.0, kHousnersValue);
    const auto impact = rocking_impact(in);
    ASSERT_TRUE(impact.has_value());
    EXPECT_NEAR(momentum_about(landing, impact->after, block.k2()),
                momentum_about(landing, in.velocity, block.k2()),
                1e-14 * std::abs(momentum_about(landing, in.velocity, block.k2())));
    EXPECT_NEAR(impact->after.omega / in.velocity.omega,
                angular_momentum_ratio(pivot, landing, block.k2()), 1e-14);
    EXPECT_LT(rocking_unit_energy(impact->after, block.k2()),
              rocking_unit_energy(in.velocity, block.k2()));
  }
}

// For r <= 1 the energy after is r^2 (I/M + |landing|^2) / (I/M + |pivot|^2) of the energy before:
// above 1 only when the landing corner is the farther one and r is close enough to 1. There the
// block keeps its energy instead.
TEST(RockingRestitution, AGivenRatioNeverAddsKineticEnergy) {
  const LopsidedBlock block;
  const Vec2 near = block.near(), far = block.far();
  const double k2 = block.k2();
  const double i_near = k2 + near.x * near.x + near.y * near.y;
  const double i_far = k2 + far.x * far.x + far.y * far.y;
  const double r_keeps = std::sqrt(i_near / i_far);  // the r that keeps the energy onto `far`
  for (const double r : {0.5 * r_keeps, 0.99 * r_keeps, 1.01 * r_keeps, 1.0}) {
    SCOPED_TRACE(r);
    const double omega = LopsidedBlock::omega_onto(near, far);
    const RockingImpactInput onto_far = turning_onto(near, far, omega, k2, 5.0, given_ratio(r));
    const auto impact = rocking_impact(onto_far);
    ASSERT_TRUE(impact.has_value());
    const double before = rocking_unit_energy(onto_far.velocity, k2);
    const double after = rocking_unit_energy(impact->after, k2);
    EXPECT_EQ(impact->energy_capped, r > r_keeps);
    if (r > r_keeps) {
      EXPECT_NEAR(after / before, 1.0, 1e-14);
      EXPECT_NEAR(impact->after.omega, r_keeps * omega, 1e-14);
    } else {
      EXPECT_NEAR(after / before, r * r * i_far / i_near, 1e-14);
    }
    // Onto the nearer corner the energy falls by more than r^2.
    const RockingImpactInput onto_near = turning_onto(
        far, near, LopsidedBlock::omega_onto(far, near), k2, 5.0, given_ratio(std::min(r, 1.0)));
    const auto back = rocking_impact(onto_near);
    ASSERT_TRUE(back.has_value());
    EXPECT_FALSE(back->energy_capped);
    EXPECT_NEAR(rocking_unit_energy(back->after, k2) / rocking_unit_energy(onto_near.velocity, k2),
                std::min(r, 1.0) * std::min(r, 1.0) * i_near / i_far, 1e-14);
  }
}

// The ground must give the impulse M (v+ - v-) = M omega- (b (1 - r), a (1 + r)) at the landing
// corner: it sticks while mu >= (1 - r) / ((1 + r) tan alpha), Housner's value included.
TEST(RockingRestitution, TheLandingCornerMustStickInsideTheFrictionCone) {
  const RockingRectangle block{0.3, 1.0};
  const double housner = 1.0 - 1.5 * 0.09 / 1.09;
  for (const auto& [rule, r] :
       {std::pair{given_ratio(0.6), 0.6}, std::pair{kHousnersValue, housner}}) {
    SCOPED_TRACE(r);
    const double mu = (1.0 - r) / ((1.0 + r) * block.a / block.b);
    EXPECT_TRUE(rocking_impact(block.landing(1.001 * mu, rule)).has_value());
    EXPECT_FALSE(rocking_impact(block.landing(0.999 * mu, rule)).has_value());
  }
}

TEST(RockingRestitution, IsNoRuleUnlessTheBlockTurnsAboutAStillPivotOntoTheLandingCorner) {
  const RockingRectangle block{0.3, 1.0};
  RockingImpactInput slipping = block.landing(5.0, given_ratio(0.8));
  slipping.velocity.vx += 1e-6;  // the pivot slips
  EXPECT_FALSE(rocking_impact(slipping).has_value());
  // Turning the other way the "landing" corner rises.
  EXPECT_FALSE(rocking_impact(block.landing(5.0, given_ratio(0.8), -1.7)).has_value());
}

// A wide block's Housner value is negative (sin^2 alpha > 2/3): the plastic impulse would turn it
// back onto its old pivot, which is no rocking impact. A given r keeps it rocking.
TEST(RockingRestitution, HousnersValueOfAWideBlockIsNoRockingImpact) {
  const RockingRectangle wide{2.0, 1.0};
  ASSERT_LT(angular_momentum_ratio(wide.right(), wide.left(), wide.k2()), 0.0);
  EXPECT_FALSE(rocking_impact(wide.landing(5.0, kHousnersValue)).has_value());
  EXPECT_TRUE(rocking_impact(wide.landing(5.0, given_ratio(0.5))).has_value());
}

Vec2 turned_by(Vec2 v, double phi) {
  return {v.x * std::cos(phi) - v.y * std::sin(phi), v.x * std::sin(phi) + v.y * std::cos(phi)};
}

// On a seat's sloping segment the same impact, turned with the ground, turns its result.
TEST(RockingRestitution, TurnsWithTheGround) {
  const RockingRectangle block{0.3, 1.0};
  const double phi = 0.4;
  for (const RockingRestitution rule : {given_ratio(0.7), kHousnersValue}) {
    const RockingImpactInput flat = block.landing(5.0, rule);
    RockingImpactInput sloped = flat;
    for (PlanarContact& c : sloped.touching) {
      c.r = turned_by(c.r, phi);
      c.normal = turned_by(c.normal, phi);
    }
    const Vec2 v = turned_by({flat.velocity.vx, flat.velocity.vy}, phi);
    sloped.velocity = {v.x, v.y, flat.velocity.omega};
    const auto on_flat = rocking_impact(flat), on_slope = rocking_impact(sloped);
    ASSERT_TRUE(on_flat.has_value() && on_slope.has_value());
    EXPECT_NEAR(on_slope->after.omega, on_flat->after.omega, 1e-14);
    const Vec2 expected = turned_by({on_flat->after.vx, on_flat->after.vy}, phi);
    EXPECT_NEAR(on_slope->after.vx, expected.x, 1e-14);
    EXPECT_NEAR(on_slope->after.vy, expected.y, 1e-14);
  }
}

// The flat ground's resolver: the rocking impact rocks on about the landing corner whatever e is,
// where without the key e = 0.3 throws the block off the ground.
TEST(RockingRestitution, TheFlatGroundsResolverRocksOnAboutTheLandingCorner) {
  const double a = 0.3, b = 1.0, omega = 1.0, g = 9.81;
  BlockGeometry geometry(RectangularBlock{a, b, 1.0});
  const BlockState before = testing::turning_about(a, b, 0.0, omega, a);
  const ContactOutcome ruled =
      ContactResolver(geometry, Contact{2.0, 0.3, given_ratio(0.6)}, g).resolve(before, 0.0);
  const auto* rock = std::get_if<RockMode>(&ruled.mode);
  ASSERT_NE(rock, nullptr);
  EXPECT_EQ(rock->pivot, Corner::left);
  EXPECT_DOUBLE_EQ(ruled.state.omega, 0.6 * omega);
  EXPECT_LE(ruled.impact_energy_gain, 0.0);
  const ContactOutcome newton =
      ContactResolver(geometry, Contact{2.0, 0.3}, g).resolve(before, 0.0);
  EXPECT_TRUE(std::holds_alternative<FlightMode>(newton.mode));
}

}  // namespace
}  // namespace blockfrag
