// What a record's motion pieces reuse from the piece before (engine/seat/watched_list.hpp,
// engine/seat/seat_ends.cpp, SeatSystem::start_piece): each is checked against what building it
// anew gives.
#include <array>
#include <cstddef>
#include <vector>

#include <gtest/gtest.h>

#include "engine/scene/block_geometry.hpp"
#include "engine/seat/seat_system.hpp"
#include "engine/seat/watched_list.hpp"
#include "tests/support/fixed_uniforms.hpp"
#include "tests/support/same_bits.hpp"
#include "tests/support/type_b_seat_system.hpp"

namespace blockfrag {
namespace {

using testing::FixedUniforms;

const std::vector<std::array<double, 2>> kPieceTypeA = {
    {0, 0}, {12.55, 0}, {10, 3.4}, {10, 16.7}, {0, 16.7}};

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
// chains of steps, whichever pivots, watched lists (longer or shorter), blocks and steps came
// before.
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
  // Another block, of five vertices, on the same seat: its own edges.
  const SeatContacts other{kPieceTypeA, testing::kTypeBSeat};
  const BlockGeometry other_geometry{PolygonBlock{kPieceTypeA, 1.0}};
  SeatSystemContext other_context = seat.context;
  other_context.contacts = &other;
  other_context.geometry = &other_geometry;
  const SeatPair other_heel{ContactKind::block_vertex, 0, 0};
  systems.emplace_back(other_context, std::vector<ActiveContact>{{other_heel, ContactState::stick}},
                       WatchedList{1, 2, 3, 4}, WatchedList{1, 2});
  const PivotChart other_chart{other.seat_point(0), other.body_vertex(0)};
  FixedUniforms u(66);
  PivotSweep reused(systems[0], pivots[0].chart);
  int claimed = 0;
  for (int n = 0; n < 400; ++n) {
    const auto at = static_cast<std::size_t>(u(0.0, 5.0));
    const PivotChart& chart = at < pivots.size() ? pivots[at].chart : other_chart;
    reused.reset(systems[at], chart);
    PivotSweep fresh(systems[at], chart);
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

// The guards, the forces, whether the contacts hold, a pivot's turning and the penetration of a
// system started on a new piece are a new system's there, to the bit: at the time and state the
// last piece's system was last asked about too, where the pieces' ground motions differ.
TEST(SeatPieceReuse, ASystemStartedOnANewPieceIsTheOneBuiltThere) {
  const testing::TypeBSeat seat;
  MotionPiece ending{{MotionPiece::Shape::cosine, 0.4, 1.7}, 0.0, 1e3};
  MotionPiece starting{{MotionPiece::Shape::cosine, -0.3, 0.9}, 0.0, 1e3};
  SeatSystemContext before = seat.context, after = seat.context;
  before.piece = &ending;
  after.piece = &starting;
  std::vector<std::vector<ActiveContact>> sets = testing::type_b_contact_sets();
  sets.push_back({});
  const WatchedList vertices{3, 4, 5}, points{0, 2};
  FixedUniforms u(4734);
  int compared = 0;
  for (int n = 0; n < 300; ++n) {
    const std::vector<ActiveContact>& active = sets[static_cast<std::size_t>(n) % sets.size()];
    const BlockState s{u(-2.0, 14.0), u(7.0, 13.0), u(-0.8, 0.8), u(-1, 1), u(-1, 1), u(-1, 1)};
    const double t = u(0.0, 5.0);
    const Vec2 arm{u(-5, 5), u(-10, 10)};
    SeatSystem reused(before, active, vertices, points);
    reused.guards(t, s);
    reused.pivot_turning(t, s, arm);
    ASSERT_TRUE(reused.lays_out(after, active, vertices, points));
    reused.start_piece(after);
    SeatSystem fresh(after, active, vertices, points);
    const auto guards = reused.guards(t, s), fresh_guards = fresh.guards(t, s);
    for (std::size_t i = 0; i < guards.size(); ++i) {
      if (fresh.live_guards()[i]) {
        EXPECT_TRUE(testing::same_bits(guards[i], fresh_guards[i])) << n << " " << i;
      }
    }
    EXPECT_TRUE(testing::same_bits(reused.forces(t, s).friction, fresh.forces(t, s).friction)) << n;
    EXPECT_TRUE(testing::same_bits(reused.forces(t, s).normal, fresh.forces(t, s).normal)) << n;
    EXPECT_EQ(reused.contacts_hold(t, s), fresh.contacts_hold(t, s)) << n;
    EXPECT_EQ(reused.pivot_turning(t, s, arm).has_value(),
              fresh.pivot_turning(t, s, arm).has_value());
    if (fresh.pivot_turning(t, s, arm)) {
      EXPECT_TRUE(
          testing::same_bits(*reused.pivot_turning(t, s, arm), *fresh.pivot_turning(t, s, arm)))
          << n;
    }
    EXPECT_TRUE(testing::same_bits(reused.penetration(s), fresh.penetration(s))) << n;
    ++compared;
  }
  EXPECT_EQ(compared, 300);
}

// A system lays its guards out as another only with the same active contacts, in the same states
// and order, and the same watched vertices and points.
TEST(SeatPieceReuse, ASystemLaysItsGuardsOutAsAnotherOnlyWithTheSameContactsAndWatches) {
  const testing::TypeBSeat seat;
  const std::vector<std::vector<ActiveContact>> sets = testing::type_b_contact_sets();
  const WatchedList vertices{3, 4, 5}, points{0, 2};
  for (std::size_t i = 0; i < sets.size(); ++i) {
    const SeatSystem system = seat.system(sets[i], vertices, points);
    EXPECT_FALSE(system.lays_out(seat.context, sets[i], vertices, WatchedList{0})) << i;
    EXPECT_FALSE(system.lays_out(seat.context, sets[i], WatchedList{3, 4}, points)) << i;
    for (std::size_t j = 0; j < sets.size(); ++j) {
      EXPECT_EQ(system.lays_out(seat.context, sets[j], vertices, points), i == j) << i << " " << j;
    }
    std::vector<ActiveContact> reversed(sets[i].rbegin(), sets[i].rend());
    EXPECT_EQ(system.lays_out(seat.context, reversed, vertices, points), sets[i].size() < 2) << i;
  }
}

}  // namespace
}  // namespace blockfrag
