// What a piece boundary asks of a moving block's mode on its seat (SeatSystem::contacts_hold):
// whether each active contact's lift-off guard and a sticking one's friction guard are positive,
// as guards() finds them. Over random states of the paper's type B block turning on its heel, its
// toe and its fold, sticking or slipping, under a range of constant ground accelerations, the two
// agree at every state, and both answers occur.
#include <array>
#include <cstddef>
#include <vector>

#include <gtest/gtest.h>

#include "engine/seat/seat_system.hpp"
#include "tests/support/fixed_uniforms.hpp"
#include "tests/support/type_b_block.hpp"

namespace blockfrag {
namespace {

bool guards_hold(SeatSystem& system, double t, const BlockState& s) {
  const auto guards = system.guards(t, s);
  for (int i = 0; i < SeatSystem::kGuards; ++i) {
    const SeatEvent e = system.event(i);
    if ((e == SeatEvent::lift_off || e == SeatEvent::friction_limit) &&
        !(guards[static_cast<std::size_t>(i)] > 0)) {
      return false;
    }
  }
  return true;
}

TEST(SeatContactsHold, AgreesWithTheGuardsOfEveryActiveContact) {
  const SeatContacts contacts{testing::kTypeB, testing::kTypeBSeat};
  const BlockGeometry geometry{PolygonBlock{testing::kTypeB, 1.0}};
  const std::vector<ActiveContact> cases = {
      {{ContactKind::block_vertex, 0, 0}, ContactState::stick},
      {{ContactKind::block_vertex, 2, 1}, ContactState::stick},
      {{ContactKind::seat_point, 0, 1}, ContactState::stick},
      {{ContactKind::block_vertex, 0, 0}, ContactState::slip_positive},
      {{ContactKind::block_vertex, 2, 1}, ContactState::slip_negative}};
  testing::FixedUniforms u(41);
  int held = 0, failed = 0;
  for (int n = 0; n < 4000; ++n) {
    MotionPiece push{{MotionPiece::Shape::constant, u(-1.5, 1.5)}, 0.0, 1e3};
    const SeatSystemContext context{
        &contacts, &geometry, &push, &push, 9.81, u(0.2, 1.2), 0.5 * geometry.size()};
    const ActiveContact& active = cases[static_cast<std::size_t>(n) % cases.size()];
    SeatSystem system(context, {active}, {1, 3, 4, 5}, {2});
    const BlockState s{u(4.0, 8.0), u(9.0, 12.0), u(-0.2, 0.2), u(-1, 1), u(-1, 1), u(-1, 1)};
    const double t = u(0.0, 10.0);
    const bool holds = system.contacts_hold(t, s);
    EXPECT_EQ(holds, guards_hold(system, t, s)) << n;
    (holds ? held : failed) += 1;
  }
  EXPECT_GT(held, 400);
  EXPECT_GT(failed, 400);
}

}  // namespace
}  // namespace blockfrag
