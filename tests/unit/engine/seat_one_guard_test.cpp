// One guard of a block on its seat computed alone (SeatSystem::guard: root finding and the dip
// search ask for one), and the guards a sample inside a step still follows computed without the
// others (guards(t, s, wanted)), are those guards() computes with all of them, to the bit: over
// random states of the paper's type B block, with each contact set's watched vertices and
// points, in every guard slot.
#include <cstddef>
#include <vector>

#include <gtest/gtest.h>

#include "engine/seat/seat_system.hpp"
#include "tests/support/fixed_uniforms.hpp"
#include "tests/support/type_b_block.hpp"

namespace blockfrag {
namespace {

struct ContactSet {
  std::vector<ActiveContact> active;
  WatchedList vertices, points;
};

TEST(SeatOneGuard, IsTheGuardComputedWithTheOthersToTheBit) {
  const SeatContacts contacts{testing::kTypeB, testing::kTypeBSeat};
  const BlockGeometry geometry{PolygonBlock{testing::kTypeB, 1.0}};
  MotionPiece push{{MotionPiece::Shape::constant, 0.3}, 0.0, 1e3};
  const SeatSystemContext context{
      &contacts, &geometry, &push, &push, 9.81, 0.8, 0.5 * geometry.size()};
  const std::vector<ContactSet> sets = {
      {{}, {0, 1, 2, 3, 4, 5}, {0, 1, 2}},
      {{{{ContactKind::block_vertex, 0, 0}, ContactState::stick}}, {1, 2, 3, 4, 5}, {1, 2}},
      {{{{ContactKind::seat_point, 0, 1}, ContactState::slip_positive}}, {0, 2, 3, 4, 5}, {0, 2}}};
  testing::FixedUniforms u(71);
  int clearances = 0;
  for (int n = 0; n < 600; ++n) {
    const ContactSet& set = sets[static_cast<std::size_t>(n) % sets.size()];
    SeatSystem system(context, set.active, set.vertices, set.points);
    // Near the seat (the clearances near zero, points inside and outside) and far from it.
    const double far = n % 5 == 0 ? u(20.0, 200.0) : 0.0;
    const BlockState s{u(4.0, 8.0) + far, u(9.5, 11.5), u(-0.3, 0.3), u(-1, 1), u(-1, 1), u(-1, 1)};
    const double t = u(0.0, 5.0);
    const auto all = system.guards(t, s);
    for (int i = 0; i < SeatSystem::kGuards; ++i) {
      EXPECT_EQ(system.guard(i, t, s), all[static_cast<std::size_t>(i)]) << n << " " << i;
      clearances += system.event(i) == SeatEvent::touches;
    }
  }
  EXPECT_EQ(clearances, 200 * (9 + 7 + 7));
}

TEST(SeatOneGuard, TheGuardsWantedAreThoseComputedWithTheOthersToTheBit) {
  const SeatContacts contacts{testing::kTypeB, testing::kTypeBSeat};
  const BlockGeometry geometry{PolygonBlock{testing::kTypeB, 1.0}};
  MotionPiece push{{MotionPiece::Shape::constant, -0.4}, 0.0, 1e3};
  const SeatSystemContext context{
      &contacts, &geometry, &push, &push, 9.81, 0.6, 0.5 * geometry.size()};
  const std::vector<ContactSet> sets = {
      {{}, {0, 1, 2, 3, 4, 5}, {0, 1, 2}},
      {{{{ContactKind::block_vertex, 2, 1}, ContactState::stick}}, {0, 1, 3, 4, 5}, {0, 1}}};
  testing::FixedUniforms u(73);
  int compared = 0;
  for (int n = 0; n < 400; ++n) {
    const ContactSet& set = sets[static_cast<std::size_t>(n) % sets.size()];
    SeatSystem system(context, set.active, set.vertices, set.points);
    const BlockState s{u(4.0, 8.0), u(9.5, 11.5), u(-0.3, 0.3), u(-1, 1), u(-1, 1), u(-1, 1)};
    const double t = u(0.0, 5.0);
    GuardClaims wanted;
    for (bool& w : wanted) w = u(0.0, 1.0) < 0.3;
    const auto some = system.guards(t, s, wanted);
    const auto all = system.guards(t, s);
    for (std::size_t i = 0; i < wanted.size(); ++i) {
      if (!wanted[i]) continue;
      EXPECT_EQ(some[i], all[i]) << n << " " << i;
      ++compared;
    }
  }
  EXPECT_GT(compared, 5000);
}

}  // namespace
}  // namespace blockfrag
