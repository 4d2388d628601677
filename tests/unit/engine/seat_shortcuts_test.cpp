// The seat's geometric shortcuts (engine/seat/seat_contacts.hpp): a pivot far inside the seat's
// ends keeps every vertex over the seat at every tilt, and the penetration that skips the vertices
// over the seat's top finds what a pass over every vertex finds.
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "engine/seat/seat_contacts.hpp"
#include "tests/support/type_b_block.hpp"

namespace blockfrag {
namespace {

using testing::kTypeB;
using testing::kTypeBSeat;

const std::vector<std::array<double, 2>> kTypeA = {
    {0, 0}, {12.55, 0}, {10, 3.4}, {10, 16.7}, {0, 16.7}};

// The centre of mass of the block turned by theta with its vertex i at p.
BlockState turned_about(const SeatContacts& contacts, int i, Vec2 p, double theta) {
  const Vec2 r = rotate(contacts.body_vertex(i), std::cos(theta), std::sin(theta));
  BlockState s;
  s.x = p.x - r.x;
  s.y = p.y - r.y;
  s.theta = theta;
  return s;
}

TEST(SeatShortcuts, APivotFarInsideTheEndsKeepsTheBlockWithinThemAtEveryTilt) {
  const SeatContacts contacts(kTypeA, {{-100, 0}, {100, 0}});
  const Vec2 toe{12.55, 0.0};
  ASSERT_TRUE(contacts.within_ends_turning_about(toe));
  for (double theta = -3.1; theta <= 3.1; theta += 0.05) {
    EXPECT_TRUE(contacts.within_ends(turned_about(contacts, 1, toe, theta))) << theta;
  }
}

TEST(SeatShortcuts, APivotWithinTheBlocksDiameterOfAnEndIsNotWithinTheEnds) {
  // The type A block's diameter is 2 x 11.0 m: its toe 20 m from the seat's right end can reach
  // past it, and the type B block's fold on its short seat can too.
  const SeatContacts flat(kTypeA, {{-100, 0}, {32.55, 0}});
  EXPECT_FALSE(flat.within_ends_turning_about({12.55, 0.0}));
  EXPECT_TRUE(flat.within_ends_turning_about({0.0, 0.0}));
  const SeatContacts folded(kTypeB, kTypeBSeat);
  EXPECT_FALSE(folded.within_ends_turning_about(folded.seat_point(1)));
}

// Over a range of tilts, sunk into the seat and lifted from it, on the flat seat and the type B
// seat: the penetration is the largest of 0, every vertex's -clearance and every seat point's.
TEST(SeatShortcuts, ThePenetrationIsTheDeepestVertexsAsAPassOverEveryVertexFindsIt) {
  const SeatContacts flat(kTypeA, {{-100, 0}, {100, 0}});
  const SeatContacts folded(kTypeB, kTypeBSeat);
  for (const SeatContacts* contacts : {&flat, &folded}) {
    const Vec2 heel = contacts->seat_point(0);
    const Vec2 pivot = contacts == &flat ? Vec2{0.0, 0.0} : heel;
    for (double theta = -0.3; theta <= 0.3; theta += 0.01) {
      for (const double depth : {-1e-3, 0.0, 1e-3}) {
        const BlockState s = turned_about(*contacts, 0, {pivot.x, pivot.y - depth}, theta);
        double deepest = 0.0;
        for (int i = 0; i < contacts->vertex_count(); ++i) {
          deepest = std::max(deepest, -contacts->vertex_clearance(i, s));
        }
        for (int k = 0; k < contacts->point_count(); ++k) {
          deepest = std::max(deepest, -contacts->point_clearance(k, s));
        }
        EXPECT_EQ(contacts->penetration(s), deepest) << theta << " " << depth;
      }
    }
  }
}

}  // namespace
}  // namespace blockfrag
