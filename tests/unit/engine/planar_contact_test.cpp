// The contact forces of a block on a seat at any number of contacts (engine/contact/
// planar_contact.hpp): one corner on flat ground against today's ContactResolver and the paper's
// closed forms (engine/contact/contact_dynamics.hpp); the gap's second derivative against finite
// differences; the type B block resting in its fold; the Painleve cases reported.
#include "engine/contact/planar_contact.hpp"

#include <cmath>
#include <random>
#include <variant>

#include <gtest/gtest.h>

#include "engine/contact/contact_dynamics.hpp"
#include "engine/contact/contact_resolution.hpp"
#include "engine/tolerances.hpp"
#include "tests/support/paper_block.hpp"

namespace blockfrag {
namespace {

using testing::kGravity;

PlanarForcesInput one_contact(Vec2 r, const RigidVelocity& v, double k2, double lambda, double mu,
                              double length) {
  return {{{r, {0.0, 1.0}, ContactKind::block_vertex}},
          v,
          k2,
          {lambda * kGravity, -kGravity},
          mu,
          kRestingVelocity * std::sqrt(kGravity * length),
          kGravity,
          length};
}

// Random rectangles on one base corner with the corner at rest or slipping, random lambda, mu and
// omega: the mode today's resolver picks and the state chosen here agree wherever the problem is
// determinate and today's resolver needed no Painleve repair, and so do theta'' and the forces.
TEST(PlanarContactForces, OneCornerAgreesWithTodaysResolver) {
  std::mt19937_64 random(20261124);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int compared = 0, stick = 0, slip = 0, off = 0, painleve = 0, not_unique = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const double a = 0.1 + unit(random), b = 0.1 + 2 * unit(random);
    const double mu = 1.5 * unit(random), lambda = 3 * unit(random) - 1.5;
    const Corner pivot = unit(random) < 0.5 ? Corner::left : Corner::right;
    const double tilt = 0.01 + 0.5 * unit(random);
    const double theta = pivot == Corner::right ? -tilt : tilt;
    const double omega = 12 * unit(random) - 6;
    const double slip_speed = unit(random) < 0.5 ? 0.0 : 2 * unit(random) - 1;
    BlockGeometry geometry(RectangularBlock{a, b, 1.0});
    const Vec2 r = rotate(geometry.base_corner(pivot), std::cos(theta), std::sin(theta));
    BlockState s{0.0, -r.y, theta, omega * r.y + slip_speed, -omega * r.x, omega};

    const ContactOutcome today =
        ContactResolver(geometry, Contact{mu, 0.5}, kGravity).resolve(s, lambda);
    const PlanarForces here = resolve_contact_forces(one_contact(
        r, {s.vx, s.vy, s.omega}, geometry.inertia_per_mass(), lambda, mu, geometry.size()));
    // Where today's resolver needs its Painleve repair this one reports the case.
    EXPECT_EQ(today.painleve, here.determinacy != Determinacy::unique) << trial;
    painleve += today.painleve;
    not_unique += here.determinacy != Determinacy::unique;
    if (today.painleve || here.determinacy != Determinacy::unique) continue;
    ++compared;
    const ContactState state = here.states[0];
    const double k2 = geometry.inertia_per_mass();
    if (const auto* rock = std::get_if<RockMode>(&today.mode)) {
      ASSERT_EQ(state, ContactState::stick) << trial;
      EXPECT_EQ(rock->pivot, pivot);
      const CornerContact k = sticking_corner(r, omega, lambda, kGravity, k2);
      EXPECT_NEAR(here.acceleration.theta_dd, k.theta_dd, 1e-9 * (1 + std::abs(k.theta_dd)));
      EXPECT_NEAR(here.normal[0], k.normal, 1e-9 * kGravity);
      EXPECT_NEAR(here.tangent[0], k.friction, 1e-9 * kGravity);
      ++stick;
    } else if (const auto* slide_rock = std::get_if<SlideRockMode>(&today.mode)) {
      ASSERT_EQ(state, slide_rock->slip_sign > 0 ? ContactState::slip_positive
                                                 : ContactState::slip_negative)
          << trial;
      const CornerContact k =
          slipping_corner(r, omega, slide_rock->slip_sign, lambda, kGravity, mu, k2);
      EXPECT_NEAR(here.acceleration.theta_dd, k.theta_dd, 1e-8 * (1 + std::abs(k.theta_dd)));
      EXPECT_NEAR(here.acceleration.x_dd, k.x_dd, 1e-8 * (kGravity + std::abs(k.x_dd)));
      EXPECT_NEAR(here.normal[0], k.normal, 1e-8 * kGravity);
      ++slip;
    } else {
      ASSERT_TRUE(std::holds_alternative<FlightMode>(today.mode));
      ASSERT_EQ(state, ContactState::off) << trial;
      EXPECT_DOUBLE_EQ(here.acceleration.x_dd, lambda * kGravity);
      EXPECT_DOUBLE_EQ(here.acceleration.y_dd, -kGravity);
      EXPECT_DOUBLE_EQ(here.acceleration.theta_dd, 0.0);
      ++off;
    }
  }
  // Every mode is met often; few cases are set aside.
  EXPECT_GT(compared, 19000);
  EXPECT_GT(stick, 2000);
  EXPECT_GT(slip, 2000);
  EXPECT_GT(off, 1000);
  RecordProperty("compared", compared);
  RecordProperty("painleve_today", painleve);
  RecordProperty("not_unique_here", not_unique);
  RecordProperty("stick_slip_off",
                 std::to_string(stick) + " " + std::to_string(slip) + " " + std::to_string(off));
}

// Random rectangles flat on the ground (both base corners touching), at rest or sliding, random
// lambda and mu: the states chosen for the two corners are the mode today's resolver picks (rest:
// both stick; slide: both slip; rock: one sticks, the other is off; slide-rock: one slips, the
// other is off), with the same accelerations.
TEST(PlanarContactForces, FlatBlockAgreesWithTodaysResolver) {
  std::mt19937_64 random(20261125);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int compared = 0, rest = 0, slide = 0, rock = 0, slide_rock = 0, painleve = 0, not_unique = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const double a = 0.1 + unit(random), b = 0.1 + 2 * unit(random);
    const double mu = 1.5 * unit(random), lambda = 4 * unit(random) - 2;
    const double vx = unit(random) < 0.5 ? 0.0 : 2 * unit(random) - 1;
    BlockGeometry geometry(RectangularBlock{a, b, 1.0});
    BlockState s{0.0, b, 0.0, vx, 0.0, 0.0};
    const ContactOutcome today =
        ContactResolver(geometry, Contact{mu, 0.5}, kGravity).resolve(s, lambda);
    // Today's resolver ends a flat block's slip slower than the settling speed (lay_flat): the
    // forces are compared at the velocity it keeps.
    const double settle = kSettleVelocity * std::sqrt(kGravity * geometry.size());
    const double kept_vx = std::abs(vx) <= settle ? 0.0 : vx;
    PlanarForcesInput in = one_contact({-a, -b}, {kept_vx, 0, 0}, geometry.inertia_per_mass(),
                                       lambda, mu, geometry.size());
    in.contacts.push_back({{a, -b}, {0.0, 1.0}, ContactKind::block_vertex});
    const PlanarForces here = resolve_contact_forces(in);
    // The cases set aside: a flat block sliding with mu above its flat-sliding limit whose leading
    // corner's slide-rock is past the Painleve boundary. No state is consistent (this resolver
    // says so); today's keeps it sliding flat.
    if (here.determinacy != Determinacy::unique) {
      EXPECT_EQ(here.determinacy, Determinacy::inconsistent) << trial;
      EXPECT_TRUE(std::holds_alternative<SlideMode>(today.mode)) << trial;
      EXPECT_GT(mu, geometry.flat_slide_friction_limit(vx > 0 ? 1 : -1)) << trial;
    }
    painleve += today.painleve;
    not_unique += here.determinacy != Determinacy::unique;
    if (today.painleve || here.determinacy != Determinacy::unique) continue;
    ++compared;
    const auto slip_of = [](int sign) {
      return sign > 0 ? ContactState::slip_positive : ContactState::slip_negative;
    };
    const auto& st = here.states;
    if (std::holds_alternative<RestMode>(today.mode)) {
      EXPECT_EQ(st[0], ContactState::stick) << trial;
      EXPECT_EQ(st[1], ContactState::stick) << trial;
      EXPECT_NEAR(here.acceleration.x_dd, 0.0, 1e-9 * kGravity) << trial;
      ++rest;
    } else if (const auto* sliding = std::get_if<SlideMode>(&today.mode)) {
      EXPECT_EQ(st[0], slip_of(sliding->slip_sign)) << trial;
      EXPECT_EQ(st[1], slip_of(sliding->slip_sign)) << trial;
      EXPECT_NEAR(here.acceleration.x_dd, (lambda - sliding->slip_sign * mu) * kGravity,
                  1e-9 * kGravity)
          << trial;
      ++slide;
    } else if (const auto* rocking = std::get_if<RockMode>(&today.mode)) {
      const int k = rocking->pivot == Corner::left ? 0 : 1;
      EXPECT_EQ(st[k], ContactState::stick) << trial;
      EXPECT_EQ(st[1 - k], ContactState::off) << trial;
      const CornerContact c = sticking_corner(geometry.base_corner(rocking->pivot), 0.0, lambda,
                                              kGravity, geometry.inertia_per_mass());
      EXPECT_NEAR(here.acceleration.theta_dd, c.theta_dd, 1e-9 * (1 + std::abs(c.theta_dd)));
      ++rock;
    } else if (const auto* slide_rocking = std::get_if<SlideRockMode>(&today.mode)) {
      const int k = slide_rocking->pivot == Corner::left ? 0 : 1;
      EXPECT_EQ(st[k], slip_of(slide_rocking->slip_sign)) << trial;
      EXPECT_EQ(st[1 - k], ContactState::off) << trial;
      ++slide_rock;
    } else {
      ADD_FAILURE() << "flight from flat ground at trial " << trial;
    }
  }
  EXPECT_GT(compared, 19000);
  EXPECT_GT(rest, 1000);
  EXPECT_GT(slide, 1000);
  EXPECT_GT(rock, 1000);
  EXPECT_GT(slide_rock, 100);
  RecordProperty("flat_compared", compared);
  RecordProperty("flat_painleve_today", painleve);
  RecordProperty("flat_not_unique_here", not_unique);
  RecordProperty("rest_slide_rock_sliderock", std::to_string(rest) + " " + std::to_string(slide) +
                                                  " " + std::to_string(rock) + " " +
                                                  std::to_string(slide_rock));
}

// A seat point on a block edge: the gap's second derivative under a rigid motion with constant
// accelerations, by central differences of the distance from the seat point to the edge's line.
TEST(PlanarContactForces, NormalAccelerationIsTheGapsSecondDerivative) {
  const Vec2 seat_point{0.3, 0.0};
  // The block's edge through the seat point at time 0: body-frame point e0 and inward normal m0
  // (body frame), with the centre of mass at c and theta = 0.4.
  const double theta0 = 0.4, omega = 1.7, x_dd = 0.8, y_dd = -2.1, theta_dd = 3.3;
  const double vx = 0.9, vy = -0.4;
  const Vec2 c0{-0.2, 1.1};
  const Vec2 m_world{std::sin(0.25), std::cos(0.25)};  // the inward normal at time 0
  const auto body = [&](Vec2 w) {                      // world vector to body frame at theta0
    return Vec2{w.x * std::cos(theta0) + w.y * std::sin(theta0),
                -w.x * std::sin(theta0) + w.y * std::cos(theta0)};
  };
  const Vec2 e0 = body({seat_point.x - c0.x, seat_point.y - c0.y});
  const Vec2 m0 = body(m_world);
  const auto gap = [&](double t) {
    const double th = theta0 + omega * t + 0.5 * theta_dd * t * t;
    const Vec2 c{c0.x + vx * t + 0.5 * x_dd * t * t, c0.y + vy * t + 0.5 * y_dd * t * t};
    const Vec2 e = rotate(e0, std::cos(th), std::sin(th));
    const Vec2 m = rotate(m0, std::cos(th), std::sin(th));
    // The seat point's distance outside the edge: the inward normal points away from it.
    return m.x * (c.x + e.x - seat_point.x) + m.y * (c.y + e.y - seat_point.y);
  };
  const double h = 1e-4;
  const double fd = (gap(h) - 2 * gap(0) + gap(-h)) / (h * h);
  const PlanarContact contact{
      {seat_point.x - c0.x, seat_point.y - c0.y}, m_world, ContactKind::seat_point};
  const ContactAcceleration a =
      contact_acceleration(contact, {vx, vy, omega}, {x_dd, y_dd, theta_dd});
  EXPECT_NEAR(a.normal, fd, 1e-6);
  // Without the turning term it would be off by 2 omega u_t.
  const double u_t = contact_velocity(contact, {vx, vy, omega}).tangent;
  EXPECT_GT(std::abs(2 * omega * u_t), 0.5);
}

// The paper's type B block (docs/references.md) in its fold: heel and fold on the horizontal
// segment, the toe on the incline, all three touching at rest.
struct TypeB {
  double cx = 5.071424149494352, cy = 10.97679866760705;
  double k2 = 46.19106394722878, length = 12.091710048345288;
  std::vector<PlanarContact> contacts() const {
    return {{{0 - cx, 0 - cy}, {0, 1}},
            {{703.0 / 120 - cx, 0 - cy}, {0, 1}},
            {{12.525 - cx, 5 - cy}, {-0.6, 0.8}}};
  }
  PlanarForcesInput at_rest(double lambda, double mu) const {
    return {contacts(), {0, 0, 0},
            k2,         {lambda * kGravity, -kGravity},
            mu,         1e-9 * std::sqrt(kGravity * length),
            kGravity,   length};
  }
};

// The forces must balance the applied load and lie in their cones.
void expect_balanced(const PlanarForces& f, const PlanarForcesInput& in, double mu) {
  double fx = in.applied.x, fy = in.applied.y, moment = 0;
  for (std::size_t i = 0; i < in.contacts.size(); ++i) {
    const PlanarContact& c = in.contacts[i];
    const Vec2 t = contact_tangent(c);
    const double px = f.normal[i] * c.normal.x + f.tangent[i] * t.x;
    const double py = f.normal[i] * c.normal.y + f.tangent[i] * t.y;
    fx += px;
    fy += py;
    moment += c.r.x * py - c.r.y * px;
    EXPECT_GE(f.normal[i], -1e-12);
    EXPECT_LE(std::abs(f.tangent[i]), mu * f.normal[i] + 1e-12);
  }
  EXPECT_NEAR(fx, 0, 1e-9 * kGravity);
  EXPECT_NEAR(fy, 0, 1e-9 * kGravity);
  EXPECT_NEAR(moment, 0, 1e-9 * kGravity * in.length);
}

TEST(PlanarContactForces, TypeBBlockRestsInItsFold) {
  const TypeB block;
  // Under gravity alone, pushed downstream (held by the incline) and upstream within the heel's
  // tip threshold 0.4620 and friction 1.05: no acceleration, the forces balance the load.
  for (const double lambda : {0.0, 0.5, 1.0, -0.3, -0.45}) {
    const PlanarForcesInput in = block.at_rest(lambda, 1.05);
    const PlanarForces f = resolve_contact_forces(in);
    EXPECT_EQ(f.determinacy, Determinacy::unique) << lambda;
    EXPECT_NEAR(f.acceleration.x_dd, 0, 1e-9 * kGravity) << lambda;
    EXPECT_NEAR(f.acceleration.y_dd, 0, 1e-9 * kGravity) << lambda;
    EXPECT_NEAR(f.acceleration.theta_dd * block.length, 0, 1e-9 * kGravity) << lambda;
    expect_balanced(f, in, 1.05);
  }
  // Under gravity alone the heel and the fold carry it (its centre of mass is over the
  // horizontal part): the toe needs no push.
  const PlanarForces rest = resolve_contact_forces(block.at_rest(0.0, 1.05));
  EXPECT_NEAR(rest.normal[2], 0, 1e-9 * kGravity);
  EXPECT_NEAR(rest.normal[0] + rest.normal[1], kGravity, 1e-9 * kGravity);
}

TEST(PlanarContactForces, TypeBBlockRocksUpstreamAboutItsHeel) {
  // Past the heel's tip threshold (0.4620), the block turns about the heel as Housner's block does
  // (the paper's eq. 2.6 at the heel, engine/contact/contact_dynamics.hpp): fold and toe lift off.
  const TypeB block;
  const double lambda = -0.6;
  const PlanarForces f = resolve_contact_forces(block.at_rest(lambda, 1.05));
  ASSERT_EQ(f.determinacy, Determinacy::unique);
  EXPECT_EQ(f.states[0], ContactState::stick);
  EXPECT_EQ(f.states[1], ContactState::off);
  EXPECT_EQ(f.states[2], ContactState::off);
  const CornerContact k = sticking_corner({-block.cx, -block.cy}, 0.0, lambda, kGravity, block.k2);
  EXPECT_GT(k.theta_dd, 0.0);
  EXPECT_NEAR(f.acceleration.theta_dd, k.theta_dd, 1e-12 * kGravity);
  // Pushed upstream with friction 0.3 below the push: it slides towards the reservoir, on heel
  // and fold, away from the incline.
  const PlanarForces slide = resolve_contact_forces(block.at_rest(-0.4, 0.3));
  ASSERT_EQ(slide.determinacy, Determinacy::unique);
  EXPECT_EQ(slide.states[2], ContactState::off);
  EXPECT_NEAR(slide.acceleration.x_dd, (-0.4 + 0.3) * kGravity, 1e-9 * kGravity);
}

// A slender body slipping where the slip's normal force has no non-negative solution (Painleve,
// I/M + r_x^2 + s mu r_x r_y < 0): with the free contact falling there is no consistent state;
// with it rising fast enough (omega^2 > g / |r_y|) both slip and lift-off are consistent.
TEST(PlanarContactForces, PainleveCasesAreReported) {
  const double k2 = 0.01, mu = 1.0;
  const Vec2 r{0.3, -1.0};
  ASSERT_LT(k2 + r.x * r.x + mu * r.x * r.y, 0.0);
  const auto slipping = [&](double omega) {
    // u_t = vx - omega r_y = +1, u_n = vy + omega r_x = 0.
    return one_contact(r, {1.0 + omega * r.y, -omega * r.x, omega}, k2, 0.0, mu, 1.0);
  };
  const PlanarForces none = resolve_contact_forces(slipping(0.0));
  EXPECT_EQ(none.determinacy, Determinacy::inconsistent);
  EXPECT_EQ(none.consistent_choices, 0);
  const PlanarForces two = resolve_contact_forces(slipping(4.0));
  EXPECT_EQ(two.determinacy, Determinacy::indeterminate);
  EXPECT_EQ(two.consistent_choices, 2);
}

}  // namespace
}  // namespace blockfrag
