// The corner impact law against closed forms (Housner, docs/references.md), the paper's Table 2.1
// re-derived independently, the energy identity of a corner impulse, and symmetries.
#include "engine/contact/impact.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

#include <gtest/gtest.h>

#include "engine/errors.hpp"

namespace blockfrag {
namespace {

struct Body {
  double mass, inertia, r_x, r_y;
};

CornerImpactInput input_for(const Body& body, const RigidVelocity& v, double mu, double e) {
  const CornerVelocity u = corner_velocity(v, body.r_x, body.r_y);
  return {body.mass, body.inertia, body.r_x, body.r_y, u.u_x, u.u_y, mu, e};
}

RigidVelocity after(const Body& body, const RigidVelocity& v, const CornerImpulse& p) {
  return apply_impulse(v, body.mass, body.inertia, body.r_x, body.r_y, p);
}

double sign(double x) { return x > 0.0 ? 1.0 : -1.0; }

// A rectangle flat on the ground (theta = 0) rocking back about its right bottom corner (a, -b)
// with omega > 0: the centre of mass moves as omega x (centre - pivot) = omega x (-a, b). Its
// left corner (-a, -b) is the one that lands.
RigidVelocity rocking_about_right_corner(double a, double b, double omega) {
  return {-omega * b, -omega * a, omega};
}

Body rectangle_left_corner(double a, double b, double mass) {
  return {mass, mass * (a * a + b * b) / 3.0, -a, -b};
}

TEST(CornerImpact, HousnerRatioWithoutBounceOrSlip) {
  struct Case {
    double a_over_b, eta_printed;
  };
  for (const Case c : {Case{0.5, 0.70}, Case{0.25, 0.911765}, Case{1.0, 0.25}}) {
    const double b = 1.3, a = c.a_over_b * b, omega = 0.8;
    const Body body = rectangle_left_corner(a, b, 2.5);
    const RigidVelocity before = rocking_about_right_corner(a, b, omega);
    const CornerVelocity pivot = corner_velocity(before, a, -b);
    EXPECT_NEAR(pivot.u_x, 0.0, 1e-15);
    EXPECT_NEAR(pivot.u_y, 0.0, 1e-15);
    const CornerVelocity landing = corner_velocity(before, -a, -b);
    EXPECT_NEAR(landing.u_x, 0.0, 1e-15);
    EXPECT_NEAR(landing.u_y, -2.0 * a * omega, 1e-15);

    const CornerImpulse p = corner_impact(input_for(body, before, 2.0, 0.0));
    const RigidVelocity v = after(body, before, p);
    const double alpha = std::atan(a / b);
    const double eta = 1.0 - 1.5 * std::pow(std::sin(alpha), 2);
    EXPECT_NEAR(v.omega / omega, eta, 1e-12) << "a/b = " << c.a_over_b;
    EXPECT_NEAR(v.omega / omega, c.eta_printed, 5e-7);  // docs/references.md prints 6 digits
    const CornerVelocity landed = corner_velocity(v, -a, -b);
    EXPECT_NEAR(landed.u_x, 0.0, 1e-12);
    EXPECT_NEAR(landed.u_y, 0.0, 1e-12);
    EXPECT_GE(corner_velocity(v, a, -b).u_y, -1e-12);  // the old pivot lifts or stays
    EXPECT_NEAR(kinetic_energy(v, body.mass, body.inertia) /
                    kinetic_energy(before, body.mass, body.inertia),
                eta * eta, 1e-12);
    EXPECT_EQ(p.regime, ImpactRegime::stick);
    EXPECT_FALSE(p.energy_capped);
    EXPECT_FALSE(p.painleve_stick);
  }
}

// docs/references.md: a/b = 0.5, b = 1, e = 0.6, sticking corner at a flat impact,
// theta'- = 1 rad/s.
TEST(CornerImpact, FlatImpactWithRestitutionMatchesReferences) {
  const double a = 0.5, b = 1.0;
  const Body body = rectangle_left_corner(a, b, 3.0);
  const RigidVelocity before = rocking_about_right_corner(a, b, 1.0);
  const CornerImpulse p = corner_impact(input_for(body, before, 1.0, 0.6));
  const RigidVelocity v = after(body, before, p);
  EXPECT_NEAR(v.omega, 0.52, 1e-12);
  EXPECT_NEAR(1.0 - 1.5 * 1.6 * 0.2, 0.52, 1e-15);  // 1 - 1.5 (1 + e) sin^2(alpha)
  EXPECT_NEAR(v.vx, -0.52, 1e-12);
  EXPECT_NEAR(v.vy, 0.86, 1e-12);
  EXPECT_NEAR(
      kinetic_energy(v, body.mass, body.inertia) / kinetic_energy(before, body.mass, body.inertia),
      0.6736, 1e-12);
  EXPECT_GT(corner_velocity(v, -a, -b).u_y, 0.0);  // both corners leave the ground
  EXPECT_GT(corner_velocity(v, a, -b).u_y, 0.0);
  EXPECT_EQ(p.regime, ImpactRegime::stick);
}

TEST(CornerImpact, StickNeedsMuAboveThreeAbOverASquaredPlusFourBSquared) {
  const double a = 0.5, b = 1.0;
  const double mu_stick = 3.0 * a * b / (a * a + 4.0 * b * b);
  EXPECT_NEAR(mu_stick, 0.352941, 5e-7);
  const Body body = rectangle_left_corner(a, b, 1.0);
  const RigidVelocity before = rocking_about_right_corner(a, b, 1.0);

  const CornerImpulse stick = corner_impact(input_for(body, before, mu_stick * (1 + 1e-9), 0.6));
  EXPECT_EQ(stick.regime, ImpactRegime::stick);
  EXPECT_NEAR(corner_velocity(after(body, before, stick), -a, -b).u_x, 0.0, 1e-12);

  // Just below, the corner slides outwards (to -x, as a2 = ab/I > 0) with the impulse on the
  // cone's edge; the result is continuous across the threshold.
  const double mu_slip = mu_stick * (1 - 1e-9);
  const CornerImpulse slip = corner_impact(input_for(body, before, mu_slip, 0.6));
  EXPECT_EQ(slip.regime, ImpactRegime::slip);
  EXPECT_NEAR(slip.p_x, mu_slip * slip.p_y, 1e-15);
  EXPECT_LT(corner_velocity(after(body, before, slip), -a, -b).u_x, 0.0);
  EXPECT_NEAR(slip.p_x, stick.p_x, 1e-8);
  EXPECT_NEAR(slip.p_y, stick.p_y, 1e-8);

  const CornerImpulse low = corner_impact(input_for(body, before, 0.2, 0.6));
  EXPECT_EQ(low.regime, ImpactRegime::slip);
  EXPECT_LT(corner_velocity(after(body, before, low), -a, -b).u_x, -0.05);
}

TEST(CornerImpact, ElasticStickConservesEnergy) {
  const double a = 0.3, b = 1.1;
  const Body body = rectangle_left_corner(a, b, 4.0);
  const RigidVelocity before = rocking_about_right_corner(a, b, 1.7);
  const CornerImpulse p = corner_impact(input_for(body, before, 2.0, 1.0));
  const RigidVelocity v = after(body, before, p);
  const double t_before = kinetic_energy(before, body.mass, body.inertia);
  EXPECT_NEAR(kinetic_energy(v, body.mass, body.inertia), t_before, 1e-12 * t_before);
  EXPECT_NEAR(corner_velocity(v, -a, -b).u_y, 2.0 * a * 1.7, 1e-12);
  EXPECT_EQ(p.regime, ImpactRegime::stick);
  EXPECT_FALSE(p.energy_capped);
}

// The paper's Table 2.1, re-derived (the printed table has sign and symbol typos): the impulse
// of Newton's law along the Darboux-Keller path, with no energy cap.
struct Impulse {
  double p_x, p_y;
};

Impulse table_2_1(const CornerImpactInput& in) {
  const double m = in.mass, i = in.inertia, rx = in.r_x, ry = in.r_y, mu = in.friction;
  const double e = in.restitution, ux = in.u_x, uy = in.u_y;
  const double a1 = 1 / m + ry * ry / i, a2 = rx * ry / i, a3 = 1 / m + rx * rx / i;
  const bool can_stick = mu >= std::abs(a2 / a1);
  if (ux == 0.0) {
    if (can_stick) {  // row 1
      const double d = i / m + rx * rx + ry * ry;
      return {-m * rx * ry / d * (1 + e) * uy, -(i + m * ry * ry) / d * (1 + e) * uy};
    }
    const double py = (1 + e) * uy / (a2 * sign(a2) * mu - a3);  // row 2
    return {sign(a2) * mu * py, py};
  }
  const double s = sign(ux);
  // Eq. 2.14: the slip stops at p1 if friction decelerates it (eq. 2.15) before u_y = -e u_y-.
  const bool decelerates = a1 * mu + s * a2 > 0.0;
  const double p1 = decelerates ? ux / (a1 * s * mu + a2) : 0.0;
  const double uy1 = uy + (a2 * s * mu + a3) * p1;
  if (!decelerates || uy1 >= -e * uy) {  // row 3: slips throughout
    const double py = -(1 + e) * uy / (a2 * s * mu + a3);
    return {-s * mu * py, py};
  }
  if (can_stick) {  // row 4
    const double p2 = (-e * uy - uy1) * a1 / (a1 * a3 - a2 * a2);
    return {-s * mu * p1 + a2 / a1 * p2, p1 + p2};
  }
  const double p2 = (-e * uy - uy1) / (a3 - mu * std::abs(a2));  // row 5
  return {-s * mu * p1 + sign(a2) * mu * p2, p1 + p2};
}

// With e = 1 and a slip that stops and sticks, u+ = (0, -u_y-) for any mu. The energy of a corner
// impulse is T+ - T- = (u+.W^-1.u+ - u-.W^-1.u-)/2, so the gain is
// (-a3 u_x^2 - 2 a2 u_x u_y) / (2 det W): positive for small u_x with u_x a2 > 0.
TEST(CornerImpact, EnergyGainOfNewtonsLawIsCapped) {
  const double a = 0.5, b = 1.0;
  const Body body = rectangle_left_corner(a, b, 1.0);
  const double a1 = 1 + b * b / body.inertia, a2 = a * b / body.inertia;
  const double a3 = 1 + a * a / body.inertia, det = a1 * a3 - a2 * a2;
  const double ux = 0.3, uy = -1.0;
  const double gain = (-a3 * ux * ux - 2 * a2 * ux * uy) / (2 * det);
  ASSERT_GT(gain, 0.0);

  // The corner (-a, -b) with u = (0.3, -1) and no rotation: the centre moves as the corner.
  const RigidVelocity before{ux, uy, 0.0};
  const CornerImpactInput in = input_for(body, before, 1.0, 1.0);
  const Impulse newton = table_2_1(in);
  const RigidVelocity uncapped = after(body, before, {newton.p_x, newton.p_y});
  const double t_before = kinetic_energy(before, body.mass, body.inertia);
  EXPECT_NEAR(kinetic_energy(uncapped, body.mass, body.inertia) - t_before, gain, 1e-12);
  EXPECT_NEAR(corner_velocity(uncapped, -a, -b).u_y, 1.0, 1e-12);

  const CornerImpulse p = corner_impact(in);
  EXPECT_TRUE(p.energy_capped);
  EXPECT_EQ(p.regime, ImpactRegime::slip_then_stick);
  const RigidVelocity v = after(body, before, p);
  EXPECT_NEAR(kinetic_energy(v, body.mass, body.inertia), t_before, 1e-12 * t_before);
  // The slip stops during compression, so the cap cuts the stick phase where u+ = (0, v) and
  // a1 v^2 = u-.(det W^-1).u- (no energy change).
  const CornerVelocity u = corner_velocity(v, -a, -b);
  EXPECT_NEAR(u.u_x, 0.0, 1e-12);
  EXPECT_NEAR(u.u_y, std::sqrt((a3 * ux * ux + 2 * a2 * ux * uy + a1 * uy * uy) / a1), 1e-12);
  EXPECT_LT(u.u_y, -in.restitution * uy);
}

double uniform(std::mt19937& gen, double lo, double hi) {
  return lo + (hi - lo) * ((gen() + 0.5) / 4294967296.0);
}

// The corner of a tilted rectangle that is lowest: the one that can touch the ground.
Body random_body(std::mt19937& gen) {
  const double a = std::exp(uniform(gen, std::log(0.05), std::log(2.0)));
  const double b = std::exp(uniform(gen, std::log(0.05), std::log(2.0)));
  const double mass = std::exp(uniform(gen, std::log(0.01), std::log(100.0)));
  const double theta = uniform(gen, -1.5, 1.5), c = std::cos(theta), s = std::sin(theta);
  Body body{mass, mass * (a * a + b * b) / 3.0, 0.0, 1e300};
  for (const double x : {-a, a}) {
    for (const double y : {-b, b}) {
      if (s * x + c * y < body.r_y) {
        body.r_x = c * x - s * y;
        body.r_y = s * x + c * y;
      }
    }
  }
  return body;
}

TEST(CornerImpact, RandomSweepKeepsTheLawsAndNeverGainsEnergy) {
  std::mt19937 gen(20240611);
  int painleve = 0, regimes[4] = {}, capped[4] = {};
  for (int n = 0; n < 100000; ++n) {
    const Body body = random_body(gen);
    const double mu = n % 10 == 0 ? 0.0 : uniform(gen, 0.0, 5.0);
    const double e = n % 10 == 1 ? 0.0 : n % 10 == 2 ? 1.0 : uniform(gen, 0.0, 1.0);
    const double ux = n % 4 == 0 ? 0.0 : uniform(gen, -2.0, 2.0);
    const double uy = uniform(gen, -2.0, -0.01), omega = uniform(gen, -3.0, 3.0);
    const RigidVelocity before{ux + omega * body.r_y, uy - omega * body.r_x, omega};
    const CornerImpactInput in{body.mass, body.inertia, body.r_x, body.r_y, ux, uy, mu, e};
    SCOPED_TRACE(::testing::Message() << "sample " << n << " mu " << mu << " e " << e);

    const CornerImpulse p = corner_impact(in);
    const RigidVelocity v = after(body, before, p);
    const CornerVelocity u = corner_velocity(v, body.r_x, body.r_y);
    const double t_before = kinetic_energy(before, body.mass, body.inertia);
    const double delta_t = kinetic_energy(v, body.mass, body.inertia) - t_before;
    ++regimes[static_cast<int>(p.regime)];
    capped[static_cast<int>(p.regime)] += p.energy_capped;
    painleve += p.painleve_stick;

    EXPECT_GE(p.p_y, 0.0);
    EXPECT_LE(std::abs(p.p_x), mu * p.p_y * (1 + 1e-12));
    EXPECT_LE(delta_t, 1e-12 * t_before);
    const double speed = std::abs(ux) + std::abs(uy);
    if (p.energy_capped) {
      EXPECT_NEAR(delta_t, 0.0, 1e-12 * t_before);
      EXPECT_GE(u.u_y, -1e-12 * speed);
      EXPECT_LT(u.u_y, -e * uy);
    } else {
      EXPECT_NEAR(u.u_y, -e * uy, 1e-12 * speed);
    }

    // The paper's closed forms: equal where no cap applies, and gaining energy exactly where
    // the cap was reported (up to rounding of the energy difference).
    const Impulse newton = table_2_1(in);
    const RigidVelocity v_newton = after(body, before, {newton.p_x, newton.p_y});
    const double gain = kinetic_energy(v_newton, body.mass, body.inertia) - t_before;
    if (gain > 1e-12 * t_before) {
      EXPECT_TRUE(p.energy_capped);
    } else if (gain < -1e-12 * t_before) {
      EXPECT_FALSE(p.energy_capped);
    }
    if (!p.energy_capped) {
      const double scale = std::abs(newton.p_x) + std::abs(newton.p_y);
      EXPECT_NEAR(p.p_x, newton.p_x, 1e-12 * scale);
      EXPECT_NEAR(p.p_y, newton.p_y, 1e-12 * scale);
    }

    // What each regime means for the corner's tangential velocity.
    const double s = ux == 0.0 ? 0.0 : sign(ux);
    switch (p.regime) {
      case ImpactRegime::stick: EXPECT_EQ(ux, 0.0); [[fallthrough]];
      case ImpactRegime::slip_then_stick: EXPECT_NEAR(u.u_x, 0.0, 1e-12 * speed); break;
      case ImpactRegime::slip:
        EXPECT_NEAR(std::abs(p.p_x), mu * p.p_y, 1e-12 * p.p_y);
        if (s != 0.0) {
          EXPECT_GE(s * u.u_x, -1e-12 * speed);
        }
        break;
      case ImpactRegime::slip_reversal: EXPECT_LT(s * u.u_x, 0.0); break;
    }
    const double painleve_condition =
        body.inertia / body.mass + body.r_x * body.r_x + s * mu * body.r_x * body.r_y;
    EXPECT_EQ(p.painleve_stick, ux != 0.0 && painleve_condition <= 0.0);

    // Mass scaling (M and I together) leaves the velocities; a mirror (x -> -x) mirrors P.
    const double k = 7.3;
    const Body heavy{k * body.mass, k * body.inertia, body.r_x, body.r_y};
    const CornerImpulse ph =
        corner_impact({heavy.mass, heavy.inertia, in.r_x, in.r_y, ux, uy, mu, e});
    const RigidVelocity vh = after(heavy, before, ph);
    const double v_scale = speed + std::abs(omega) * std::hypot(body.r_x, body.r_y);
    EXPECT_NEAR(vh.vx, v.vx, 1e-12 * v_scale);
    EXPECT_NEAR(vh.vy, v.vy, 1e-12 * v_scale);
    EXPECT_NEAR(vh.omega * std::hypot(body.r_x, body.r_y), v.omega * std::hypot(body.r_x, body.r_y),
                1e-12 * v_scale);
    EXPECT_EQ(ph.regime, p.regime);

    // Exact: every step is odd or even in x, and IEEE rounding commutes with negation.
    const CornerImpulse pm =
        corner_impact({body.mass, body.inertia, -body.r_x, body.r_y, -ux, uy, mu, e});
    EXPECT_EQ(pm.p_x, -p.p_x);
    EXPECT_EQ(pm.p_y, p.p_y);
    EXPECT_EQ(pm.regime, p.regime);
    EXPECT_EQ(pm.energy_capped, p.energy_capped);
    if (::testing::Test::HasFailure()) break;
  }
  // The sweep reaches every branch. Newton's law gains energy when the slip stops, then sticks or
  // reverses; one straight phase (stick or slip throughout) never gains: u_y runs linearly
  // from u_y- to -e u_y-, so the normal work is <= 0, and friction's is <= 0.
  EXPECT_GT(painleve, 100);
  for (const int count : regimes) EXPECT_GT(count, 100);
  EXPECT_GT(capped[static_cast<int>(ImpactRegime::slip_then_stick)], 100);
  EXPECT_GT(capped[static_cast<int>(ImpactRegime::slip_reversal)], 10);
  EXPECT_EQ(capped[static_cast<int>(ImpactRegime::stick)], 0);
}

// A slender rod-like block leaning at 0.5 rad on its lowest corner, which slides away from under
// the centre of mass (u_x > 0, r_x r_y < 0): the classic Painleve configuration.
struct LeaningRod {
  double a = 0.05, b = 1.0, theta = 0.5, mass = 2.0;
  Body body() const {
    const double c = std::cos(theta), s = std::sin(theta);
    return {mass, mass * (a * a + b * b) / 3.0, -a * c + b * s, -a * s - b * c};
  }
  // I/M + r_x^2 + mu r_x r_y = 0
  double mu_painleve() const {
    const Body r = body();
    return (r.inertia / r.mass + r.r_x * r.r_x) / -(r.r_x * r.r_y);
  }
};

TEST(PainleveStickImpulse, StopsTheSlipInsideTheConeAndDissipates) {
  const LeaningRod rod;
  const Body body = rod.body();
  ASSERT_LT(body.r_x * body.r_y, 0.0);
  ASSERT_GT(rod.mu_painleve(), 1.0);
  ASSERT_LT(rod.mu_painleve(), 2.0);
  const double mu = 2.0;
  ASSERT_LE(body.inertia / body.mass + body.r_x * body.r_x + mu * body.r_x * body.r_y, 0.0);

  const RigidVelocity before{1.5 + 0.4 * body.r_y, -0.4 * body.r_x, 0.4};  // u = (1.5, 0)
  const CornerImpactInput in = input_for(body, before, mu, 0.5);
  const std::optional<CornerImpulse> p = painleve_stick_impulse(in);
  ASSERT_TRUE(p.has_value());
  EXPECT_GT(p->p_y, 0.0);
  EXPECT_LE(std::abs(p->p_x), mu * p->p_y);
  EXPECT_LT(p->p_x, 0.0);  // opposes the slip
  EXPECT_TRUE(p->painleve_stick);
  const RigidVelocity v = after(body, before, *p);
  const CornerVelocity u = corner_velocity(v, body.r_x, body.r_y);
  EXPECT_NEAR(u.u_x, 0.0, 1e-12);
  EXPECT_NEAR(u.u_y, 0.0, 1e-12);
  // Delta T = P.(u- + u+)/2 = P_x u_x- / 2 < 0
  const double delta_t =
      kinetic_energy(v, body.mass, body.inertia) - kinetic_energy(before, body.mass, body.inertia);
  EXPECT_NEAR(delta_t, 0.5 * p->p_x * 1.5, 1e-12);
  EXPECT_LT(delta_t, 0.0);
}

TEST(PainleveStickImpulse, ExistsExactlyWhenTheSlipCannotContinue) {
  const LeaningRod rod;
  const Body body = rod.body();
  const double mu_p = rod.mu_painleve();
  const RigidVelocity sliding_out{1.5 + 0.4 * body.r_y, -0.4 * body.r_x, 0.4};

  // At the threshold the impulse's ratio |P_x|/P_y = a3/|a2| is mu_p: it touches the cone's edge.
  const auto edge = painleve_stick_impulse(input_for(body, sliding_out, mu_p * (1 + 1e-9), 0.0));
  ASSERT_TRUE(edge.has_value());
  EXPECT_NEAR(std::abs(edge->p_x) / edge->p_y, mu_p, 1e-12);
  EXPECT_FALSE(painleve_stick_impulse(input_for(body, sliding_out, mu_p * (1 - 1e-9), 0.0)));
  EXPECT_FALSE(painleve_stick_impulse(input_for(body, sliding_out, 1.0, 0.0)));

  const RigidVelocity sliding_in{-1.5 + 0.4 * body.r_y, -0.4 * body.r_x, 0.4};  // u_x < 0
  EXPECT_FALSE(painleve_stick_impulse(input_for(body, sliding_in, 2.0, 0.0)));
  const RigidVelocity not_sliding{0.4 * body.r_y, -0.4 * body.r_x, 0.4};
  EXPECT_FALSE(painleve_stick_impulse(input_for(body, not_sliding, 2.0, 0.0)));
}

// Impacting in the Painleve configuration: stopped by the jump, then stick; the end velocity
// (0, -e u_y-) is the one of the paper's slip-then-stick row, so the impulse is the same.
TEST(CornerImpact, PainleveConfigurationStopsTheSlipThenSticks) {
  const LeaningRod rod;
  const Body body = rod.body();
  const RigidVelocity before{1.5 + 0.4 * body.r_y, -0.8 - 0.4 * body.r_x, 0.4};  // u = (1.5, -0.8)
  const CornerImpactInput in = input_for(body, before, 2.0, 0.5);
  const CornerImpulse p = corner_impact(in);
  EXPECT_TRUE(p.painleve_stick);
  EXPECT_EQ(p.regime, ImpactRegime::slip_then_stick);
  EXPECT_FALSE(p.energy_capped);
  const RigidVelocity v = after(body, before, p);
  const CornerVelocity u = corner_velocity(v, body.r_x, body.r_y);
  EXPECT_NEAR(u.u_x, 0.0, 1e-12);
  EXPECT_NEAR(u.u_y, 0.4, 1e-12);
  const Impulse newton = table_2_1(in);
  EXPECT_NEAR(p.p_x, newton.p_x, 1e-12);
  EXPECT_NEAR(p.p_y, newton.p_y, 1e-12);
  EXPECT_LT(kinetic_energy(v, body.mass, body.inertia),
            kinetic_energy(before, body.mass, body.inertia));
}

TEST(CornerImpact, NoImpulseWithoutApproach) {
  for (const double uy : {0.0, 0.3}) {
    const CornerImpulse p = corner_impact({1.0, 0.5, -0.5, -1.0, 0.7, uy, 0.6, 0.6});
    EXPECT_EQ(p.p_x, 0.0);
    EXPECT_EQ(p.p_y, 0.0);
  }
}

TEST(CornerImpact, RefusesInvalidInputs) {
  const CornerImpactInput good{1.0, 0.5, -0.5, -1.0, 0.2, -1.0, 0.6, 0.6};
  EXPECT_NO_THROW(corner_impact(good));
  const auto with = [&](auto change) {
    CornerImpactInput in = good;
    change(in);
    return in;
  };
  for (const CornerImpactInput& bad :
       {with([](auto& in) { in.mass = 0.0; }), with([](auto& in) { in.inertia = -1.0; }),
        with([](auto& in) { in.friction = -0.1; }), with([](auto& in) { in.restitution = 1.1; }),
        with([](auto& in) { in.restitution = -0.1; }), with([](auto& in) { in.u_x = NAN; }),
        with([](auto& in) { in.r_y = INFINITY; }), with([](auto& in) { in.mass = NAN; })}) {
    EXPECT_THROW(corner_impact(bad), ContractViolation);
    EXPECT_THROW(painleve_stick_impulse(bad), ContractViolation);
  }
}

}  // namespace
}  // namespace blockfrag
