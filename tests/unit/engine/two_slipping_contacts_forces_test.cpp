// Two slipping contacts on a seat (engine/seat/fixed_state_forces.hpp): the fixed-size 2x2 solve
// against the general LU on random contacts, velocities and loads, with the block's own inertia
// and under a coupled mass matrix (the reservoir's added mass), and on the flat base of a block
// sliding on a flat seat, where it is met in a run.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <span>

#include <gtest/gtest.h>

#include "engine/seat/fixed_state_forces.hpp"
#include "tests/support/fixed_uniforms.hpp"

namespace blockfrag {
namespace {

using testing::FixedUniforms;

constexpr double kG = 9.81;

void expect_same(const FixedStateForces& fast, const FixedStateForces& general, double scale) {
  const auto close = [scale](double got, double expected) {
    EXPECT_NEAR(got, expected, 1e-12 * std::max(scale, std::abs(expected)));
  };
  close(fast.acceleration.x_dd, general.acceleration.x_dd);
  close(fast.acceleration.y_dd, general.acceleration.y_dd);
  close(fast.acceleration.theta_dd, general.acceleration.theta_dd);
  for (std::size_t i = 0; i < 2; ++i) {
    close(fast.normal[i], general.normal[i]);
    close(fast.tangent[i], general.tangent[i]);
  }
  close(fast.total.x, general.total.x);
  close(fast.total.y, general.total.y);
}

PlanarContact random_contact(FixedUniforms& u) {
  const double turn = u(-3.2, 3.2);
  return {{u(-10, 10), u(-10, 10)},
          {std::cos(turn), std::sin(turn)},
          u(0, 1) < 0.5 ? ContactKind::block_vertex : ContactKind::seat_point};
}

std::array<ContactState, 2> random_slips(FixedUniforms& u) {
  const auto one = [&u] {
    return u(0, 1) < 0.5 ? ContactState::slip_positive : ContactState::slip_negative;
  };
  return {one(), one()};
}

// Returns how many of the problems the fixed-size solve gave forces for.
int compare_on_random_problems(unsigned seed, bool coupled) {
  FixedUniforms u(seed);
  int compared = 0;
  for (int n = 0; n < 20000; ++n) {
    const std::array<PlanarContact, 2> c{random_contact(u), random_contact(u)};
    const std::array<ContactState, 2> states = random_slips(u);
    const BlockState s{0.0, 0.0, u(-1, 1), u(-3, 3), u(-3, 3), u(-1, 1)};
    const double k2 = u(1, 60), mu = u(0, 1.2);
    const double added = coupled ? u(0, 3) : 0.0, lever = u(-5, 5);
    const BodyLoad load{
        {u(-2, 2) * kG, -kG * (1 + u(-0.5, 0.5))},
        coupled ? u(-20, 20) * kG : 0.0,
        coupled ? BodyInertia{k2, added, -added * lever, added * lever * lever * u(1, 1.5)}
                : BodyInertia{k2}};
    const auto fast = two_slipping_contacts_forces(c, states, s, load, mu);
    if (!fast) continue;
    expect_same(*fast, general_fixed_state_forces(c, states, s, load, mu), 100 * kG);
    ++compared;
  }
  return compared;
}

TEST(TwoSlippingContactsForces, AgreeWithTheGeneralSolveOnRandomProblems) {
  EXPECT_GT(compare_on_random_problems(20261206, false), 19900);
}

TEST(TwoSlippingContactsForces, AgreeWithTheGeneralSolveUnderACoupledMassMatrix) {
  EXPECT_GT(compare_on_random_problems(20261208, true), 19900);
}

// A flat base 2b wide, its centre of mass h above it, sliding along a flat seat: both corners slip
// the same way, the system regular, and the fixed-size solve gives the general one's numbers to the
// bit. Sliding at an even tilt of 0 the base's normal forces share the weight: their sum is g.
TEST(TwoSlippingContactsForces, AreTheGeneralSolveForAFlatBaseSliding) {
  FixedUniforms u(33);
  for (int n = 0; n < 1000; ++n) {
    const double b = u(0.5, 3), h = u(1, 6), mu = u(0.2, 1.1), lambda = u(-1.5, 1.5);
    const std::array<PlanarContact, 2> c{
        PlanarContact{{-b, -h}, {0.0, 1.0}, ContactKind::block_vertex},
        PlanarContact{{b, -h}, {0.0, 1.0}, ContactKind::block_vertex}};
    const ContactState slip =
        n % 2 == 0 ? ContactState::slip_positive : ContactState::slip_negative;
    const std::array<ContactState, 2> states{slip, slip};
    const BlockState s{0.0, 0.0, 0.0, u(-2, 2), 0.0, 0.0};
    const BodyLoad load{{lambda * kG, -kG}, 0.0, BodyInertia{(b * b + h * h) / 3}};
    const auto fast = two_slipping_contacts_forces(c, states, s, load, mu);
    ASSERT_TRUE(fast.has_value());
    const FixedStateForces general = general_fixed_state_forces(c, states, s, load, mu);
    EXPECT_EQ(fast->normal[0], general.normal[0]);
    EXPECT_EQ(fast->normal[1], general.normal[1]);
    EXPECT_EQ(fast->acceleration.x_dd, general.acceleration.x_dd);
    EXPECT_EQ(fast->acceleration.theta_dd, general.acceleration.theta_dd);
    EXPECT_NEAR(fast->normal[0] + fast->normal[1], kG, 1e-12 * kG);
  }
}

// Nothing for other states: a sticking contact's friction is an unknown of its own.
TEST(TwoSlippingContactsForces, TakeOnlyTwoSlippingContacts) {
  const std::array<PlanarContact, 2> c{
      PlanarContact{{-1.0, -2.0}, {0.0, 1.0}, ContactKind::block_vertex},
      PlanarContact{{1.0, -2.0}, {0.0, 1.0}, ContactKind::block_vertex}};
  const std::array<ContactState, 2> states{ContactState::stick, ContactState::slip_positive};
  const BodyLoad load{{0.0, -kG}, 0.0, BodyInertia{2.0}};
  EXPECT_FALSE(two_slipping_contacts_forces(c, states, BlockState{}, load, 0.6).has_value());
  EXPECT_FALSE(two_slipping_contacts_forces(std::span(c).first(1), std::span(states).subspan(1),
                                            BlockState{}, load, 0.6)
                   .has_value());
}

}  // namespace
}  // namespace blockfrag
