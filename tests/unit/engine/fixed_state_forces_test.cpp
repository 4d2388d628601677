// The forces of no contact and of one contact on a seat (engine/seat/fixed_state_forces.hpp): the
// fixed-size solve against the general one on random poses and velocities, and against the flat
// ground's closed
// forms (engine/contact/contact_dynamics.hpp) for a contact whose normal is turned by any angle,
// with the whole scene turned with it.
#include "engine/seat/fixed_state_forces.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <span>

#include <gtest/gtest.h>

#include "engine/contact/contact_dynamics.hpp"
#include "engine/sine_cosine.hpp"
#include "tests/support/fixed_uniforms.hpp"
#include "tests/support/same_bits.hpp"

namespace blockfrag {
namespace {

using testing::FixedUniforms;
using testing::same_bits;

constexpr double kG = 9.81;
constexpr std::array<ContactState, 3> kStates = {ContactState::stick, ContactState::slip_positive,
                                                 ContactState::slip_negative};

void expect_close(double got, double expected, double scale) {
  EXPECT_NEAR(got, expected, 1e-12 * std::max(scale, std::abs(expected)));
}

TEST(OneContactForces, AgreeWithTheGeneralSolveOnRandomPosesAndVelocities) {
  FixedUniforms u(20261206);
  int compared = 0;
  for (int n = 0; n < 20000; ++n) {
    const double turn = u(-3.2, 3.2);
    const PlanarContact c{{u(-10, 10), u(-10, 10)},
                          {std::cos(turn), std::sin(turn)},
                          u(0, 1) < 0.5 ? ContactKind::block_vertex : ContactKind::seat_point};
    const ContactState state = kStates[static_cast<std::size_t>(n % 3)];
    const BlockState s{0.0, 0.0, u(-1, 1), u(-3, 3), u(-3, 3), u(-1, 1)};
    const Vec2 applied{u(-2, 2) * kG, -kG * (1 + u(-0.5, 0.5))};
    const double k2 = u(1, 60), mu = u(0, 1.2);
    const auto one = one_contact_forces(c, state, s, BodyLoad{applied, 0.0, k2}, mu);
    if (!one) continue;  // a slipping contact at its Painleve boundary exactly: not met at random
    const FixedStateForces general = general_fixed_state_forces(
        std::span(&c, 1), std::span(&state, 1), s, BodyLoad{applied, 0.0, k2}, mu);
    const double scale = 10 * kG;  // the accelerations' and forces' size here
    expect_close(one->acceleration.x_dd, general.acceleration.x_dd, scale);
    expect_close(one->acceleration.y_dd, general.acceleration.y_dd, scale);
    expect_close(one->acceleration.theta_dd, general.acceleration.theta_dd, scale);
    expect_close(one->normal[0], general.normal[0], scale);
    expect_close(one->tangent[0], general.tangent[0], scale);
    expect_close(one->total.x, general.total.x, scale);
    expect_close(one->total.y, general.total.y, scale);
    ++compared;
  }
  EXPECT_GT(compared, 19900);
}

// Without contacts (flight, the system's shortcut and the solves' answer for none): no forces,
// and the load's own accelerations M^-1 Q to the bit, under a diagonal and a coupled mass matrix.
TEST(NoContactForces, AreNoneAndTheLoadsOwnAccelerations) {
  FixedUniforms u(20261208);
  for (int n = 0; n < 2000; ++n) {
    const double k2 = u(1, 60), added = n % 2 == 0 ? 0.0 : u(0, 3), lever = u(-5, 5);
    const BodyLoad load{{u(-2, 2) * kG, -kG * (1 + u(-0.5, 0.5))},
                        u(-20, 20) * kG,
                        {k2, added, -added * lever, added * lever * lever * u(1, 1.5)}};
    const Eigen::Vector3d free = load.free_acceleration();
    const BlockState s{0.0, 0.0, u(-1, 1), u(-3, 3), u(-3, 3), u(-1, 1)};
    const FixedStateForces solved = fixed_state_forces({}, {}, s, load, u(0, 1.2));
    for (const FixedStateForces& f : {no_contact_forces(load), solved}) {
      EXPECT_TRUE(same_bits(f.acceleration.x_dd, free(0))) << n;
      EXPECT_TRUE(same_bits(f.acceleration.y_dd, free(1))) << n;
      EXPECT_TRUE(same_bits(f.acceleration.theta_dd, free(2))) << n;
      EXPECT_TRUE(same_bits(f.total.x, 0.0) && same_bits(f.total.y, 0.0)) << n;
      for (std::size_t i = 0; i < f.normal.size(); ++i) {
        EXPECT_TRUE(same_bits(f.normal[i], 0.0) && same_bits(f.tangent[i], 0.0)) << n;
      }
    }
  }
}

// Under a coupled mass matrix (an added mass with its lever arm, positive definite) and a moment.
TEST(OneContactForces, AgreeWithTheGeneralSolveUnderACoupledMassMatrix) {
  FixedUniforms u(20261207);
  int compared = 0;
  for (int n = 0; n < 20000; ++n) {
    const double turn = u(-3.2, 3.2);
    const PlanarContact c{{u(-10, 10), u(-10, 10)},
                          {std::cos(turn), std::sin(turn)},
                          u(0, 1) < 0.5 ? ContactKind::block_vertex : ContactKind::seat_point};
    const ContactState state = kStates[static_cast<std::size_t>(n % 3)];
    const BlockState s{0.0, 0.0, u(-1, 1), u(-3, 3), u(-3, 3), u(-1, 1)};
    const double k2 = u(1, 60), mu = u(0, 1.2);
    const double added = u(0, 3), lever = u(-5, 5);  // the added mass a and its height z
    const BodyLoad load{{u(-2, 2) * kG, -kG * (1 + u(-0.5, 0.5))},
                        u(-20, 20) * kG,
                        {k2, added, -added * lever, added * lever * lever * u(1, 1.5)}};
    const auto one = one_contact_forces(c, state, s, load, mu);
    if (!one) continue;
    const FixedStateForces general =
        general_fixed_state_forces(std::span(&c, 1), std::span(&state, 1), s, load, mu);
    const double scale = 100 * kG;
    expect_close(one->acceleration.x_dd, general.acceleration.x_dd, scale);
    expect_close(one->acceleration.y_dd, general.acceleration.y_dd, scale);
    expect_close(one->acceleration.theta_dd, general.acceleration.theta_dd, scale);
    expect_close(one->normal[0], general.normal[0], scale);
    expect_close(one->tangent[0], general.tangent[0], scale);
    ++compared;
  }
  EXPECT_GT(compared, 19900);
}

// The flat ground's sticking_corner and slipping_corner are the one-contact system for the normal
// (0, 1) under (lambda g, -g). Turning the normal, the corner's arm, the velocity and the applied
// force together by any angle turns the accelerations and leaves the forces' normal and tangential
// parts as they were.
TEST(OneContactForces, AreTheFlatGroundsClosedFormsTurnedWithTheNormal) {
  FixedUniforms u(7);
  int compared = 0;
  for (int n = 0; n < 3000; ++n) {
    const Vec2 r{u(-6, 6), u(-12, 0)};
    const double w = u(-1, 1), lambda = u(-1.5, 1.5), k2 = u(5, 60), mu = u(0.2, 1.1);
    const ContactState state = kStates[static_cast<std::size_t>(n % 3)];
    const int s = slip_sign(state);
    if (s != 0 && !slide_rock_well_posed(r, s, mu, k2)) continue;
    const CornerContact flat = s == 0 ? sticking_corner(r, w, lambda, kG, k2)
                                      : slipping_corner(r, w, s, lambda, kG, mu, k2);
    const SineCosine turn = sine_cosine(u(-3.2, 3.2));
    const auto turned = [&](Vec2 a) { return rotate(a, turn.cos, turn.sin); };
    const PlanarContact c{turned(r), turned({0.0, 1.0}), ContactKind::block_vertex};
    // The corner's velocity along the ground is zero (sticking) or anything (slipping): the
    // centre's velocity makes its normal part zero either way.
    const Vec2 corner_velocity{s == 0 ? 0.0 : u(-2, 2), 0.0};
    const Vec2 centre{corner_velocity.x + w * r.y, corner_velocity.y - w * r.x};
    const Vec2 v = turned(centre), applied = turned({lambda * kG, -kG});
    const auto one =
        one_contact_forces(c, state, {0.0, 0.0, 0.0, v.x, v.y, w}, BodyLoad{applied, 0.0, k2}, mu);
    ASSERT_TRUE(one.has_value());
    const double scale = 10 * kG;
    expect_close(one->normal[0], flat.normal, scale);
    expect_close(one->tangent[0], flat.friction, scale);
    expect_close(one->acceleration.theta_dd, flat.theta_dd, scale);
    // The centre's acceleration on flat ground: (x'', V - g).
    const Vec2 a = turned({flat.x_dd, flat.normal - kG});
    expect_close(one->acceleration.x_dd, a.x, scale);
    expect_close(one->acceleration.y_dd, a.y, scale);
    ++compared;
  }
  EXPECT_GT(compared, 2000);
}

}  // namespace
}  // namespace blockfrag
