// ContactResolver at impacts: a rocking block landing on its other corner against Housner's ratio,
// a flat block dropped on its base against Newton's restitution (docs/references.md, "Rocking
// without sliding"), and, over random impacts, that no resolution gains kinetic energy.
#include <cmath>
#include <cstdint>

#include <gtest/gtest.h>

#include "engine/contact/contact_resolution.hpp"
#include "engine/tolerances.hpp"
#include "tests/support/contact_states.hpp"
#include "tests/support/fixed_uniforms.hpp"
#include "tests/support/paper_block.hpp"

namespace blockfrag {
namespace {

using testing::flat_state;
using testing::rectangle_kinetic_energy;
using testing::turning_about;

using testing::kGravity;

TEST(ContactResolverImpact, ALandingCornerThatSticksWithoutBounceKeepsHousnersRatio) {
  // Rocking back about the right corner (omega = 1 rad/s counter-clockwise) to theta = 0, the
  // left corner lands at u_y = -2 a omega. With e = 0 and friction that holds (mu = 2 above
  // |a2/a1| = 3ab / (a^2 + 4b^2) for any a/b here), angular momentum about the left corner is
  // kept: omega+ = (1 - 1.5 sin^2 alpha) omega-, sin^2 alpha = a^2 / (a^2 + b^2)
  // (a/b = 0.5: 0.70, 0.25: 0.911765, 1: 0.25). The block goes on rocking about its left corner
  // at x - a, the centre moving at omega+ x (centre - corner) = (-omega+ b, omega+ a).
  const struct { double a, eta; } cases[] = {{0.5, 0.70}, {0.25, 0.911765}, {1.0, 0.25}};
  for (const auto& c : cases) {
    SCOPED_TRACE(c.a);
    const double a = c.a, b = 1.0, omega = 1.0, x = 3.0;
    BlockGeometry geometry(RectangularBlock{a, b, 1.0});
    const ContactResolver resolver(geometry, Contact{2.0, 0.0}, kGravity);
    const BlockState before = turning_about(a, b, 0.0, omega, x + a);
    const ContactOutcome out = resolver.resolve(before, 0.0);
    EXPECT_TRUE(out.impact);
    const double eta = 1.0 - 1.5 * a * a / (a * a + b * b);
    EXPECT_NEAR(eta, c.eta, 5e-7);  // docs/references.md prints 6 digits
    EXPECT_NEAR(out.state.omega, eta * omega, 1e-12);
    EXPECT_NEAR(out.state.vx, -eta * omega * b, 1e-12);
    EXPECT_NEAR(out.state.vy, eta * omega * a, 1e-12);
    // The kinetic energy ratio is eta^2 (not eta).
    EXPECT_NEAR(rectangle_kinetic_energy(a, b, out.state) / rectangle_kinetic_energy(a, b, before),
                eta * eta, 1e-12);
    const auto* rock = std::get_if<RockMode>(&out.mode);
    ASSERT_NE(rock, nullptr) << mode_name(mode_kind(out.mode));
    EXPECT_EQ(rock->pivot, Corner::left);
    EXPECT_NEAR(rock->pivot_x, x - a, 1e-15);
  }
}

TEST(ContactResolverImpact, AFlatBlockDroppedOnItsBaseBouncesStraightUpByNewtonsLaw) {
  // Both base corners land at u_y = vy = -1.5 m/s, symmetric about the centre: equal normal
  // impulses and no friction impulse, so omega and vx stay 0 and vy+ = e |vy-|. For e > 0 both
  // corners leave the ground (flight); for e = 0 the block lies still (rest).
  // Only e < 3/7 here: the resolver applies the first corner's impulse alone and takes both
  // corners together only if that drives the other one down. Alone (sticking, Table 2.1) the left
  // corner's impulse turns the block at Delta omega = -0.45 (1 + e) rad/s, leaving the right
  // corner at u_y = 1.5 e - 0.45 (1 + e), which is >= 0 from e = 3/7 on: there the block leaves
  // spinning and drifting to +x instead of straight up.
  const double a = 0.5, b = 1.0, vy = -1.5;
  BlockGeometry geometry(RectangularBlock{a, b, 1.0});
  for (const double e : {0.0, 0.3, 0.4}) {
    SCOPED_TRACE(e);
    const ContactResolver resolver(geometry, Contact{0.6, e}, kGravity);
    BlockState before = flat_state(b, 1.0);
    before.vy = vy;
    const ContactOutcome out = resolver.resolve(before, 0.0);
    EXPECT_TRUE(out.impact);
    EXPECT_NEAR(out.state.vy, e * -vy, 1e-12);
    EXPECT_NEAR(out.state.vx, 0.0, 1e-12);
    EXPECT_NEAR(out.state.omega, 0.0, 1e-12);
    EXPECT_EQ(out.state.theta, 0.0);
    EXPECT_EQ(mode_kind(out.mode), e > 0 ? ModeKind::flight : ModeKind::rest);
  }
}

TEST(ContactResolverImpact, ALandingWhoseReboundWouldBeSlowerThanTheSettlingSpeedIsPlastic) {
  // Rocking back about the right corner, the left corner lands at 3 times the settling speed
  // (kSettleVelocity sqrt(g R)). With e = 0.2 it would leave at 0.6 times that speed, a bounce
  // the model ends anyway: the landing is plastic and the block rocks on about its left corner,
  // at Housner's ratio (as with e = 0). With e = 0.5 it leaves at 1.5 times that speed: it bounces.
  const double a = 0.5, b = 1.0, x = 3.0;
  BlockGeometry geometry(RectangularBlock{a, b, 1.0});
  const double settle = kSettleVelocity * std::sqrt(kGravity * geometry.size());
  const double omega = 3.0 * settle / (2.0 * a);
  const BlockState before = turning_about(a, b, 0.0, omega, x + a);
  const double eta = 1.0 - 1.5 * a * a / (a * a + b * b);
  {
    const ContactOutcome out =
        ContactResolver(geometry, Contact{2.0, 0.2}, kGravity).resolve(before, 0.0);
    EXPECT_TRUE(out.impact);
    const auto* rock = std::get_if<RockMode>(&out.mode);
    ASSERT_NE(rock, nullptr) << mode_name(mode_kind(out.mode));
    EXPECT_EQ(rock->pivot, Corner::left);
    EXPECT_NEAR(out.state.omega, eta * omega, 1e-12 * omega);
  }
  {
    const ContactOutcome out =
        ContactResolver(geometry, Contact{2.0, 0.5}, kGravity).resolve(before, 0.0);
    EXPECT_TRUE(out.impact);
    EXPECT_EQ(mode_kind(out.mode), ModeKind::flight);
    const CornerKinematics left = corner_kinematics(geometry, out.state, Corner::left);
    EXPECT_NEAR(left.u_y, 0.5 * 3.0 * settle, 1e-9 * settle);
  }
}

TEST(ContactResolverImpact, AFlatLandingSlowerThanTheSettlingSpeedEndsASlipSlowerThanItToo) {
  // A flat block landing on both corners at half the settling speed is laid flat. Slipping at
  // half that speed too, it is laid at rest, as a seat lays a block none of whose contacts moves
  // faster than the settling speed; slipping at twice that speed, it goes on sliding.
  const double a = 0.5, b = 1.0;
  BlockGeometry geometry(RectangularBlock{a, b, 1.0});
  const ContactResolver resolver(geometry, Contact{0.4, 0.7}, kGravity);  // mu < a/b: slides flat
  const double settle = kSettleVelocity * std::sqrt(kGravity * geometry.size());
  for (const double slip : {0.5, 2.0}) {
    SCOPED_TRACE(slip);
    BlockState before = flat_state(b, 1.0);
    before.vy = -0.5 * settle;
    before.vx = slip * settle;
    const ContactOutcome out = resolver.resolve(before, 0.0);
    EXPECT_TRUE(out.impact);
    EXPECT_EQ(out.state.vy, 0.0);
    EXPECT_EQ(out.state.omega, 0.0);
    EXPECT_EQ(mode_kind(out.mode), slip < 1.0 ? ModeKind::rest : ModeKind::slide);
    EXPECT_EQ(out.state.vx, slip < 1.0 ? 0.0 : slip * settle);
  }
}

TEST(ContactResolverImpact, NoImpactGainsKineticEnergy) {
  // Random rectangles, friction, restitution and lambda; the block tilted (or, one time in four,
  // flat) with its lowest base corner on the ground and moving into it. Newton's law with friction
  // can create energy where a slip stops or reverses; the engine caps it (docs/physics.md, "Where
  // the model needs repairs"), so across resolve() T+ <= T- up to rounding.
  testing::FixedUniforms u(20240612);
  int impacts = 0, flat = 0;
  const int count = 4000;
  for (int i = 0; i < count; ++i) {
    const double b = std::exp(u(std::log(0.1), std::log(10.0)));
    const double a = b * std::exp(u(std::log(0.1), std::log(2.0)));
    const double mu = u(0.0, 2.0), e = u(0.0, 1.0), lambda = u(-2.0, 2.0);
    const double theta = u(0.0, 1.0) < 0.25 ? 0.0 : u(-1.4, 1.4);
    const double v = std::sqrt(kGravity * std::hypot(a, b));  // velocity scale sqrt(g R)
    // The lowest base corner: the right one when turned clockwise (theta < 0).
    const double corner_x = theta < 0 || (theta == 0 && u(0.0, 1.0) < 0.5) ? a : -a;
    BlockState s = turning_about(corner_x, b, theta, u(-3.0, 3.0) * v / b, u(-1.0, 1.0));
    s.vx += u(-1.0, 1.0) * v;
    s.vy -= u(0.01, 1.0) * v;  // the corner moves into the ground
    BlockGeometry geometry(RectangularBlock{a, b, 1.0});
    const ContactResolver resolver(geometry, Contact{mu, e}, kGravity);
    const ContactOutcome out = resolver.resolve(s, lambda);
    const double before = rectangle_kinetic_energy(a, b, s);
    const double after = rectangle_kinetic_energy(a, b, out.state);
    impacts += out.impact;
    flat += theta == 0.0;
    EXPECT_LE(after, before * (1 + 1e-12))
        << "a = " << a << " b = " << b << " mu = " << mu << " e = " << e << " theta = " << theta
        << " vx = " << s.vx << " vy = " << s.vy << " omega = " << s.omega;
  }
  EXPECT_EQ(impacts, count);  // every drawn state hits the ground
  EXPECT_GT(flat, count / 5);
}

}  // namespace
}  // namespace blockfrag
