// Where a block touches its seat (engine/seat/seat_contacts.hpp): which contact a seat point that
// reaches the block at one of its corners is taken as, and how a pair is posed.
#include "engine/seat/seat_contacts.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <vector>

#include <gtest/gtest.h>

#include "tests/support/fixed_uniforms.hpp"
#include "tests/support/same_bits.hpp"
#include "tests/support/type_b_block.hpp"

namespace blockfrag {
namespace {

using testing::kFoldX;
using testing::kTypeB;
using testing::kTypeBSeat;
using testing::same_bits;

bool found(const std::vector<SeatPair>& pairs, const SeatPair& pair) {
  return std::find(pairs.begin(), pairs.end(), pair) != pairs.end();
}

// The type B block's heel has slid 8e-8 m past the seat's upstream end, and the block turns
// upstream about its fold, so the heel comes down: the seat's end reaches the block 8e-8 m from the
// heel, within the contact tolerance of it. The heel, on the seat's first segment within that
// tolerance, carries the block there; the seat's end is taken on neither of the heel's edges. Taken
// on the upstream face, its horizontal normal carried the block, and the storm of record suite
// samples 116 and 127 followed; taken on the base too, it duplicated the heel's own contact.
TEST(SeatContacts, AHeelJustPastTheSeatsEndCarriesTheBlockThereNotTheSeatsEnd) {
  const SeatContacts contacts(kTypeB, kTypeBSeat);
  const Vec2 centre = contacts.rest_centre();
  const double omega = 1e-4;  // rad/s, upstream (counter-clockwise) about the fold
  BlockState s;
  s.x = centre.x - 8e-8;
  s.y = centre.y;
  s.vx = -omega * centre.y;
  s.vy = omega * (centre.x - kFoldX);
  s.omega = omega;
  const double R = 12.1;
  const int seat_end = 0;  // the seat's upstream end
  const std::vector<SeatPair> pairs = contacts.touching(s, 1e-6 * R, std::nullopt, seat_end);
  const int base = 0, upstream_face = 5;  // block edges from vertex 0 (the heel) and to it
  const int heel = 0;
  EXPECT_TRUE(found(pairs, {ContactKind::block_vertex, heel, seat_end}));
  EXPECT_FALSE(found(pairs, {ContactKind::seat_point, base, seat_end}));
  EXPECT_FALSE(found(pairs, {ContactKind::seat_point, upstream_face, seat_end}));
}

// With the heel exactly at the seat's end, the heel's own contact carries the block there whichever
// way it moves (sliding upstream over the end, or coming down on it): the seat's end is taken on
// neither the base nor the upstream face.
TEST(SeatContacts, AtTheSeatsEndTheHeelCarriesTheBlockWhicheverWayItMoves) {
  const SeatContacts contacts(kTypeB, kTypeBSeat);
  const Vec2 centre = contacts.rest_centre();
  for (const double omega : {0.0, 1e-4, -1e-4}) {
    BlockState s;
    s.x = centre.x;
    s.y = centre.y;
    s.vx = -0.1 - omega * centre.y;
    s.vy = omega * (centre.x - kFoldX);
    s.omega = omega;
    const std::vector<SeatPair> pairs = contacts.touching(s, 1e-6 * 12.1, std::nullopt, 0);
    EXPECT_TRUE(found(pairs, {ContactKind::block_vertex, 0, 0})) << omega;
    EXPECT_FALSE(found(pairs, {ContactKind::seat_point, 0, 0})) << omega;
    EXPECT_FALSE(found(pairs, {ContactKind::seat_point, 5, 0})) << omega;
  }
}

// The type B block moved 1e-5 m right and 1e-4 m down from rest: its toe is past the seat's end
// in x, but under the incline's line with its projection on the incline, where its contact with
// the incline touches. Its clearance is its height over the incline's line (vertical: 1.25 times
// its gap), not its distance from the incline's top point P: taken as that, the toe went on into
// the incline (reservoir study sample 342). Moved 1e-4 m right instead, the toe is beyond the
// incline's normal at P, past the end: its clearance is its distance from P.
TEST(SeatContacts, AToePastTheInclinesTopButUnderItIsInTheSeat) {
  const SeatContacts contacts(kTypeB, kTypeBSeat);
  const Vec2 centre = contacts.rest_centre();
  constexpr int kToe = 2;
  BlockState under;
  under.x = centre.x + 1e-5;
  under.y = centre.y - 1e-4;
  const Vec2 toe = contacts.vertex_at(kToe, under);
  ASSERT_GT(toe.x, kTypeBSeat.back()[0]);
  const PairPose on_incline = contacts.pose({ContactKind::block_vertex, kToe, 1}, under);
  ASSERT_LT(on_incline.along, on_incline.length);
  EXPECT_NEAR(contacts.vertex_clearance(kToe, under), 1.25 * on_incline.gap, 1e-12);
  EXPECT_LT(contacts.vertex_clearance(kToe, under), -7e-5);
  EXPECT_GT(contacts.penetration(under), 7e-5);

  BlockState beyond = under;
  beyond.x = centre.x + 1e-4;
  const Vec2 past = contacts.vertex_at(kToe, beyond);
  const PairPose off_incline = contacts.pose({ContactKind::block_vertex, kToe, 1}, beyond);
  ASSERT_GT(off_incline.along, off_incline.length);
  EXPECT_DOUBLE_EQ(contacts.vertex_clearance(kToe, beyond),
                   std::hypot(past.x - kTypeBSeat.back()[0], past.y - kTypeBSeat.back()[1]));
}

// A system takes a block vertex's contact normal from its segment without posing the vertex: the
// same to the bit as pose() gives, for every vertex and segment, at any pose.
TEST(SeatContacts, ASegmentsNormalIsItsBlockVertexContactsNormalAtAnyPose) {
  const std::vector<std::array<double, 2>> valley = {{-3.0, 1.2}, {-1.1, 0.3}, {0.0, 0.0},
                                                     {2.7, 0.4},  {4.4, 2.9},  {6.0, 2.95}};
  testing::FixedUniforms u(7);
  for (const auto& seat : {kTypeBSeat, valley}) {
    const SeatContacts contacts(kTypeB, seat);
    for (int trial = 0; trial < 50; ++trial) {
      BlockState s;
      s.x = u(-5.0, 5.0);
      s.y = u(-5.0, 5.0);
      s.theta = u(-1.6, 1.6);
      for (int i = 0; i < contacts.vertex_count(); ++i) {
        for (int k = 0; k + 1 < contacts.point_count(); ++k) {
          const Vec2 posed = contacts.pose({ContactKind::block_vertex, i, k}, s).contact.normal;
          EXPECT_EQ(contacts.segment_normal(k).x, posed.x) << i << " " << k;
          EXPECT_EQ(contacts.segment_normal(k).y, posed.y) << i << " " << k;
        }
      }
    }
  }
}

// The guards pose a seat point's contact from the world vertices they have turned: every pair's
// pose from them is pose()'s to the bit (gap, place, length and contact), on every block edge and
// seat segment, at any pose.
TEST(SeatContacts, APoseFromTheWorldVerticesIsPosesToTheBit) {
  const std::vector<std::array<double, 2>> valley = {{-3.0, 1.2}, {-1.1, 0.3}, {0.0, 0.0},
                                                     {2.7, 0.4},  {4.4, 2.9},  {6.0, 2.95}};
  testing::FixedUniforms u(11);
  int compared = 0;
  for (const auto& seat : {kTypeBSeat, valley}) {
    const SeatContacts contacts(kTypeB, seat);
    for (int trial = 0; trial < 50; ++trial) {
      const BlockState s{u(-5.0, 5.0), u(-5.0, 5.0), u(-1.6, 1.6), 0.0, 0.0, 0.0};
      std::array<Vec2, kMaxSeatClearances> world;
      contacts.world_vertices(s, world);
      for (int i = 0; i < contacts.vertex_count(); ++i) {
        for (int k = 0; k < contacts.point_count(); ++k) {
          for (const ContactKind kind : {ContactKind::block_vertex, ContactKind::seat_point}) {
            if (kind == ContactKind::block_vertex && k + 1 == contacts.point_count()) continue;
            const SeatPair pair{kind, i, k};
            const PairPose posed = contacts.pose(pair, s);
            const PairPose from_world = contacts.pose(pair, s, world);
            EXPECT_TRUE(same_bits(from_world.gap, posed.gap)) << i << " " << k;
            EXPECT_TRUE(same_bits(from_world.along, posed.along)) << i << " " << k;
            EXPECT_TRUE(same_bits(from_world.length, posed.length)) << i << " " << k;
            EXPECT_TRUE(same_bits(from_world.contact.r.x, posed.contact.r.x)) << i << " " << k;
            EXPECT_TRUE(same_bits(from_world.contact.r.y, posed.contact.r.y)) << i << " " << k;
            EXPECT_TRUE(same_bits(from_world.contact.normal.x, posed.contact.normal.x)) << i;
            EXPECT_TRUE(same_bits(from_world.contact.normal.y, posed.contact.normal.y)) << i;
            EXPECT_EQ(from_world.contact.kind, posed.contact.kind);
            ++compared;
          }
        }
      }
    }
  }
  EXPECT_EQ(compared, 50 * 6 * (5 + 6 + 2 + 3));
}

// A segment's line is its unit direction from its first point to its next, the normal to its left
// and the normal's offset, as found from its points, to the bit.
TEST(SeatContacts, ASegmentsLineIsTheOneItsPointsMake) {
  const std::vector<std::array<double, 2>> valley = {{-3.0, 1.2}, {-1.1, 0.3}, {0.0, 0.0},
                                                     {2.7, 0.4},  {4.4, 2.9},  {6.0, 2.95}};
  for (const auto& seat : {kTypeBSeat, valley}) {
    const SeatContacts contacts(kTypeB, seat);
    for (int k = 0; k + 1 < contacts.point_count(); ++k) {
      const Vec2 a = contacts.seat_point(k), b = contacts.seat_point(k + 1);
      const Vec2 d{b.x - a.x, b.y - a.y};
      const double length = std::sqrt(d.x * d.x + d.y * d.y);
      const Vec2 u{d.x / length, d.y / length};
      const SeatLine line = contacts.segment_line(k);
      EXPECT_EQ(line.direction.x, u.x) << k;
      EXPECT_EQ(line.direction.y, u.y) << k;
      EXPECT_EQ(line.normal.x, -u.y) << k;
      EXPECT_EQ(line.normal.y, u.x) << k;
      EXPECT_EQ(line.offset, -u.y * a.x + u.x * a.y) << k;
    }
  }
}

}  // namespace
}  // namespace blockfrag
