// At a piece's end the seat's run asks whether the mode holds under the next piece, and where it
// does, the system that answered integrates that piece: its forces solved at the piece's start are
// kept for the guards and the right-hand sides asked there. So a system that has checked its
// contacts at (t, s) must give the guards, the forces and the one-contact turning that a system
// that has solved nothing gives there, to the bit, over random states of the paper's type B block
// with one or two contacts, sticking or slipping, under a moving ground.
#include <cstddef>
#include <optional>
#include <vector>

#include <gtest/gtest.h>

#include "engine/seat/seat_system.hpp"
#include "tests/support/fixed_uniforms.hpp"
#include "tests/support/same_bits.hpp"
#include "tests/support/type_b_seat_system.hpp"

namespace blockfrag {
namespace {

using testing::same_bits;

TEST(SeatHeldSystem, GivesAfterItsContactCheckWhatAFreshSystemGives) {
  const SeatContacts contacts{testing::kTypeB, testing::kTypeBSeat};
  const BlockGeometry geometry{PolygonBlock{testing::kTypeB, 1.0}};
  MotionPiece ground{{MotionPiece::Shape::cosine, 0.4, 1.7}, 0.0, 1e3};
  MotionPiece still{MotionPiece::Formula{}, 0.0, 1e3};
  const SeatSystemContext context{
      &contacts, &geometry, &ground, &still, 9.81, 0.7, 0.5 * geometry.size()};
  const std::vector<std::vector<ActiveContact>> sets = testing::type_b_contact_sets();
  const WatchedList vertices{3, 4, 5}, points{0};
  testing::FixedUniforms u(4721);
  int compared = 0;
  for (int n = 0; n < 600; ++n) {
    const std::vector<ActiveContact>& active = sets[static_cast<std::size_t>(n) % sets.size()];
    const BlockState s{u(4.0, 8.0), u(9.5, 11.5), u(-0.3, 0.3), u(-1, 1), u(-1, 1), u(-1, 1)};
    const double t = u(0.0, 5.0);
    SeatSystem held(context, active, vertices, points);
    SeatSystem fresh(context, active, vertices, points);
    SeatSystem fresh_for_forces(context, active, vertices, points);
    held.contacts_hold(t, s);
    const FixedStateForces& kept = held.solve(t, s);
    const FixedStateForces& solved = fresh_for_forces.solve(t, s);
    for (std::size_t i = 0; i < active.size(); ++i) {
      EXPECT_TRUE(same_bits(kept.normal[i], solved.normal[i])) << n << " " << i;
      EXPECT_TRUE(same_bits(kept.tangent[i], solved.tangent[i])) << n << " " << i;
    }
    EXPECT_TRUE(same_bits(kept.acceleration.x_dd, solved.acceleration.x_dd)) << n;
    EXPECT_TRUE(same_bits(kept.acceleration.y_dd, solved.acceleration.y_dd)) << n;
    EXPECT_TRUE(same_bits(kept.acceleration.theta_dd, solved.acceleration.theta_dd)) << n;
    const auto held_guards = held.guards(t, s), fresh_guards = fresh.guards(t, s);
    for (int i = 0; i < kSeatGuards; ++i) {
      const auto at = static_cast<std::size_t>(i);
      EXPECT_TRUE(same_bits(held_guards[at], fresh_guards[at])) << n << " " << i;
    }
    const Vec2 r{u(-3.0, 3.0), u(-12.0, -8.0)};
    const std::optional<double> held_turning = held.pivot_turning(t, s, r);
    const std::optional<double> fresh_turning = fresh.pivot_turning(t, s, r);
    ASSERT_EQ(held_turning.has_value(), fresh_turning.has_value()) << n;
    if (held_turning) {
      EXPECT_TRUE(same_bits(*held_turning, *fresh_turning)) << n;
    }
    ++compared;
  }
  EXPECT_EQ(compared, 600);
}

}  // namespace
}  // namespace blockfrag
