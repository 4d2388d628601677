// At a piece's start in a mode that held at the last piece's end, the seat's run takes the guards
// of the block's pose alone (overturning, falling, the watched clearances) from the last piece's
// end, where the pose is the same bit for bit, and finds only the contacts' guards. That is exact
// where those guards depend on the pose alone, not on the time, the velocities or the piece, and
// where asking for the contacts' guards alone gives what the full evaluation gives them: both are
// checked here to the bit over random states of the paper's type B block, one system per piece.
#include <algorithm>
#include <cstddef>
#include <vector>

#include <gtest/gtest.h>

#include "engine/seat/seat_system.hpp"
#include "tests/support/fixed_uniforms.hpp"
#include "tests/support/same_bits.hpp"
#include "tests/support/type_b_block.hpp"

namespace blockfrag {
namespace {

using testing::same_bits;

TEST(SeatPieceStartGuards, PoseGuardsAreTheLastPiecesEndAndContactGuardsAloneAreTheFullOnes) {
  const SeatContacts contacts{testing::kTypeB, testing::kTypeBSeat};
  const BlockGeometry geometry{PolygonBlock{testing::kTypeB, 1.0}};
  MotionPiece ending{{MotionPiece::Shape::cosine, 0.4, 1.7}, 0.0, 1e3};
  MotionPiece starting{{MotionPiece::Shape::cosine, -0.3, 0.9}, 0.0, 1e3};
  MotionPiece still{MotionPiece::Formula{}, 0.0, 1e3};
  const double g = 9.81, mu = 0.7, fall_depth = 0.5 * geometry.size();
  const SeatSystemContext before{&contacts, &geometry, &ending, &still, g, mu, fall_depth};
  const SeatSystemContext after{&contacts, &geometry, &starting, &still, g, mu, fall_depth};
  const SeatPair heel{ContactKind::block_vertex, 0, 0}, fold{ContactKind::block_vertex, 1, 0};
  const SeatPair toe{ContactKind::block_vertex, 2, 1}, point{ContactKind::seat_point, 1, 0};
  const std::vector<std::vector<ActiveContact>> sets = {
      {},
      {{toe, ContactState::stick}},
      {{heel, ContactState::slip_negative}},
      {{point, ContactState::slip_positive}},
      {{heel, ContactState::stick}, {fold, ContactState::stick}},
      {{heel, ContactState::stick}, {point, ContactState::slip_negative}}};
  const WatchedList vertices{3, 4, 5}, points{0, 2};
  const std::size_t first = kFirstClearanceGuard;
  testing::FixedUniforms u(4733);
  int compared = 0;
  for (int n = 0; n < 600; ++n) {
    const std::vector<ActiveContact>& active = sets[static_cast<std::size_t>(n) % sets.size()];
    const BlockState end{u(-2.0, 14.0), u(7.0, 13.0), u(-0.8, 0.8), u(-1, 1), u(-1, 1), u(-1, 1)};
    BlockState start = end;
    start.vx = u(-1, 1);
    start.vy = u(-1, 1);
    start.omega = u(-1, 1);
    const double t_end = u(0.0, 5.0), t_start = u(0.0, 5.0);
    SeatSystem ended(before, active, vertices, points);
    SeatSystem started(after, active, vertices, points);
    SeatSystem started_alone(after, active, vertices, points);
    const auto at_end = ended.guards(t_end, end);
    const auto full = started.guards(t_start, start);
    GuardClaims contact_slots{};
    std::fill_n(contact_slots.begin() + 2, kSeatContactGuards * active.size(), true);
    const auto alone = started_alone.guards(t_start, start, contact_slots);
    EXPECT_TRUE(same_bits(at_end[0], full[0])) << n;
    EXPECT_TRUE(same_bits(at_end[1], full[1])) << n;
    for (std::size_t k = 0; k < vertices.size() + points.size(); ++k) {
      EXPECT_TRUE(same_bits(at_end[first + k], full[first + k])) << n << " " << k;
    }
    for (std::size_t i = 2; i < 2 + kSeatContactGuards * active.size(); ++i) {
      EXPECT_TRUE(same_bits(alone[i], full[i])) << n << " " << i;
    }
    ++compared;
  }
  EXPECT_EQ(compared, 600);
}

}  // namespace
}  // namespace blockfrag
