// A place's height over a seat of several segments (SeatContacts::clearance_at): the two-segment
// seat's direct choice of segment and the scan that finds the segment under it on a seat of a few
// points find the one a binary search finds, and give the clearance to the bit, at the seat's
// points and between them, on seats of 3 to 10 points (3 chosen directly, scanned up to 6,
// searched above).
#include <algorithm>
#include <array>
#include <vector>

#include <gtest/gtest.h>

#include "engine/seat/seat_contacts.hpp"
#include "tests/support/fixed_uniforms.hpp"
#include "tests/support/same_bits.hpp"
#include "tests/support/type_b_block.hpp"

namespace blockfrag {
namespace {

using testing::FixedUniforms;
using testing::kTypeB;
using testing::same_bits;

double searched_clearance(Vec2 p, const std::vector<Vertex>& seat) {
  const auto right = std::upper_bound(seat.begin() + 1, seat.end() - 1, p.x,
                                      [](double x, const Vertex& v) { return x < v[0]; });
  const Vertex a = *(right - 1), b = *right;
  return p.y - (a[1] + (b[1] - a[1]) * ((p.x - a[0]) / (b[0] - a[0])));
}

TEST(SeatClearanceSearch, ScanFindsTheBinarySearchesSegmentToTheBit) {
  FixedUniforms u(4711);
  int checked = 0;
  for (int points = 3; points <= 10; ++points) {
    for (int trial = 0; trial < 200; ++trial) {
      std::vector<Vertex> seat;
      double x = u(-20, 0);
      for (int k = 0; k < points; ++k) {
        seat.push_back({x, u(-5, 5)});
        x += u(0.1, 8);
      }
      const SeatContacts contacts(kTypeB, seat);
      std::vector<Vec2> places;
      for (const Vertex& v : seat) places.push_back({v[0], u(-10, 10)});
      for (int i = 0; i < 40; ++i)
        places.push_back({u(seat.front()[0], seat.back()[0]), u(-10, 10)});
      for (const Vec2 p : places) {
        EXPECT_TRUE(same_bits(contacts.clearance_at(p), searched_clearance(p, seat)))
            << points << " points, x " << p.x;
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 70000);
}

}  // namespace
}  // namespace blockfrag
