// Laying a slow landing on its contacts (engine/contact/settling.hpp, keeps_slip): the block keeps
// its contacts' slip only where that adds no kinetic energy, otherwise its centre's horizontal
// velocity (the least change, in the kinetic metric, that zeroes both base corners' normal
// velocities), and the event's energy gain counts the laying. Worked by hand for a tall rectangle
// (a = 0.2, b = 2) flat on its base, its corners moving slower than the settling speed.
#include <cmath>

#include <gtest/gtest.h>

#include "engine/contact/contact_resolution.hpp"
#include "engine/contact/settling.hpp"
#include "tests/support/contact_states.hpp"

namespace blockfrag {
namespace {

constexpr double kLayingG = 9.81, kLayingA = 0.2, kLayingB = 2.0;

// mu = 0.05, below a / b: sliding flat, the block stays flat.
ContactOutcome lay_flat_block(double vx, double omega) {
  BlockGeometry geometry(RectangularBlock{kLayingA, kLayingB, 1.0});
  const ContactResolver resolver(geometry, Contact{0.05, 0.5}, kLayingG);
  BlockState s = testing::flat_state(kLayingB);
  s.vx = vx;
  s.omega = omega;
  return resolver.resolve(s, 0.0);
}

TEST(KeepsSlip, OnlyWhereTheSlipAddsNoKineticEnergy) {
  EXPECT_TRUE(keeps_slip(1.0, 0.5));
  EXPECT_TRUE(keeps_slip(1.0, 1.0));
  EXPECT_FALSE(keeps_slip(1.0, 1.0 + 1e-15));
}

// omega = 5e-4 rad/s: the base corners move at -+omega a = 1e-4 m/s vertically, below the settling
// speed 4.47e-5 sqrt(g R) = 1.98e-4 m/s, so the block is laid flat; its base slips at
// vx - omega r_y = vx + omega b = vx + 1e-3 m/s.
TEST(FlatGroundLaying, KeepsTheBaseSlipWhereThatAddsNoEnergy) {
  // omega < 0: the base slips at 0.01 - 0.001 = 0.009 m/s, slower than the centre.
  const ContactOutcome out = lay_flat_block(0.01, -5e-4);
  EXPECT_DOUBLE_EQ(out.state.vx, 0.009);
  EXPECT_EQ(out.state.omega, 0.0);
  EXPECT_EQ(out.state.vy, 0.0);
  EXPECT_EQ(mode_kind(out.mode), ModeKind::slide);
}

TEST(FlatGroundLaying, KeepsTheCentresVelocityWhereTheSlipWouldAddEnergy) {
  // omega > 0: the base slips at 0.011 m/s; kept, the block's kinetic energy per unit mass would
  // be 0.011^2 / 2 = 6.05e-5 J/kg against 0.01^2 / 2 + (I/M) omega^2 / 2 = 5.0168e-5 J/kg before.
  const ContactOutcome out = lay_flat_block(0.01, 5e-4);
  EXPECT_EQ(out.state.vx, 0.01);
  EXPECT_EQ(out.state.omega, 0.0);
  EXPECT_EQ(mode_kind(out.mode), ModeKind::slide);
  EXPECT_LE(out.impact_energy_gain, 0.0);
}

TEST(FlatGroundLaying, NeverAddsEnergyToASlowFlatLanding) {
  BlockGeometry geometry(RectangularBlock{kLayingA, kLayingB, 1.0});
  const double settle = settling_speed(kLayingG, geometry.size());
  // Corners landing or leaving slower than the settling speed, the centre sliding either way.
  for (int trial = 0; trial < 2000; ++trial) {
    const double omega = (trial % 40 - 19.5) / 20.0 * settle / kLayingA;
    const double vy = -((trial / 40) % 10) / 10.0 * (settle - std::abs(omega) * kLayingA);
    const double vx = ((trial / 400) - 2.0) * 10 * settle;
    const ContactResolver resolver(geometry, Contact{0.5, 0.5}, kLayingG);
    BlockState s = testing::flat_state(kLayingB);
    s.vx = vx;
    s.vy = vy;
    s.omega = omega;
    const ContactOutcome out = resolver.resolve(s, 0.0);
    const double before = testing::rectangle_kinetic_energy(kLayingA, kLayingB, s);
    const double after = testing::rectangle_kinetic_energy(kLayingA, kLayingB, out.state);
    EXPECT_LE(after, before) << "vx " << vx << " vy " << vy << " omega " << omega;
    EXPECT_LE(out.impact_energy_gain, 0.0);
  }
}

}  // namespace
}  // namespace blockfrag
