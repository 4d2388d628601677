// What a record's motion pieces reuse from the piece before (engine/seat/watched_list.hpp,
// engine/seat/seat_ends.cpp): each is checked against what building it anew gives.
#include <array>
#include <cstddef>
#include <vector>

#include <gtest/gtest.h>

#include "engine/seat/seat_system.hpp"
#include "engine/seat/watched_list.hpp"
#include "tests/support/fixed_uniforms.hpp"
#include "tests/support/type_b_seat_system.hpp"

namespace blockfrag {
namespace {

using testing::FixedUniforms;

WatchedList piece_list_of(int size, int first) {
  WatchedList list;
  for (int i = 0; i < size; ++i) list.push_back(first + 3 * i);
  return list;
}

std::vector<int> piece_items(const WatchedList& list) { return {list.begin(), list.end()}; }

// A list copied or assigned holds its source's indices, whatever the list it replaces held: every
// size over every size, the longer ones' indices beyond the source's left behind unread.
TEST(SeatPieceReuse, AWatchedListCopiedOrAssignedHoldsItsSourcesIndices) {
  for (int from = 0; from <= kMaxSeatClearances; ++from) {
    const WatchedList source = piece_list_of(from, 1);
    const WatchedList copied(source);
    EXPECT_EQ(piece_items(copied), piece_items(source)) << from;
    for (int over = 0; over <= kMaxSeatClearances; ++over) {
      WatchedList assigned = piece_list_of(over, 2);
      assigned = source;
      EXPECT_EQ(assigned.size(), source.size()) << from << " over " << over;
      EXPECT_EQ(piece_items(assigned), piece_items(source)) << from << " over " << over;
      EXPECT_TRUE(assigned == source);
      if (from < kMaxSeatClearances) {
        assigned.push_back(100);
        EXPECT_EQ(assigned[static_cast<std::size_t>(from)], 100);
      }
    }
  }
}

// A sweep set up again for another system and pivot claims what a sweep built for them claims, on
// chains of steps, whichever pivots, watched lists (longer or shorter) and steps came before.
TEST(SeatPieceReuse, ASweepSetUpAgainClaimsWhatANewOneClaims) {
  const testing::TypeBSeat seat;
  const SeatContacts& c = seat.contacts;
  struct Pivot {
    SeatPair pair;
    PivotChart chart;
    WatchedList vertices, points;
  };
  const std::vector<Pivot> pivots = {
      {{ContactKind::block_vertex, 0, 0},
       {c.seat_point(0), c.body_vertex(0)},
       {1, 2, 3, 4, 5},
       {1, 2}},
      {{ContactKind::block_vertex, 2, 1}, {c.seat_point(2), c.body_vertex(2)}, {0, 3}, {0}},
      {{ContactKind::seat_point, 0, 1},
       {c.seat_point(1), {c.body_vertex(1).x - 1.0, c.body_vertex(1).y}},
       {0, 1, 2, 3, 4, 5},
       {0, 2}},
      {{ContactKind::block_vertex, 0, 0},
       {c.seat_point(0), {c.body_vertex(0).x, c.body_vertex(0).y + 1e-9}},
       {1, 2, 3, 4, 5},
       {1, 2}}};
  std::vector<SeatSystem> systems;
  for (const Pivot& pivot : pivots) {
    systems.push_back(
        seat.system({{pivot.pair, ContactState::stick}}, pivot.vertices, pivot.points));
  }
  FixedUniforms u(66);
  PivotSweep reused(systems[0], pivots[0].chart);
  int claimed = 0;
  for (int n = 0; n < 400; ++n) {
    const auto at = static_cast<std::size_t>(u(0.0, 4.0));
    reused.reset(systems[at], pivots[at].chart);
    PivotSweep fresh(systems[at], pivots[at].chart);
    double theta = u(-1.0, 1.0);
    for (int step = 0; step < 6; ++step) {
      const double next = theta + u(-0.05, 0.05);
      const GuardClaims claims = reused.claims(theta, next, testing::kEveryGuard);
      ASSERT_EQ(claims, fresh.claims(theta, next, testing::kEveryGuard)) << n << " " << step;
      for (const bool claim : claims) claimed += claim;
      theta = next;
    }
  }
  EXPECT_GT(claimed, 400 * 6 * kSeatGuards / 2);
}

}  // namespace
}  // namespace blockfrag
