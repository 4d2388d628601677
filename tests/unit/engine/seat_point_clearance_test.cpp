// A seat point's clearance from the block and whether it is inside (engine/seat/seat_contacts.hpp):
// the shortcuts that skip the divisions where their quotients are known (a point beside an edge's
// level crossing, a point off an edge's ends, where 0 or 1 times the edge is not taken off) give
// the plain crossing test's and the plain clamped projection's values to the bit, for points on
// the block's corners and edges, near it and far.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <span>
#include <vector>

#include <gtest/gtest.h>

#include "engine/seat/seat_contacts.hpp"
#include "tests/support/fixed_uniforms.hpp"
#include "tests/support/type_b_block.hpp"

namespace blockfrag {
namespace {

using testing::FixedUniforms;
using testing::kTypeB;

bool plain_inside(Vec2 p, std::span<const Vec2> world) {
  bool inside = false;
  for (std::size_t i = 0, j = world.size() - 1; i < world.size(); j = i++) {
    const Vec2 a = world[i], b = world[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y)) {
      inside = !inside;
    }
  }
  return inside;
}

double plain_clearance(Vec2 p, std::span<const Vec2> world) {
  double squared = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0, j = world.size() - 1; i < world.size(); j = i++) {
    const Vec2 a = world[i], b = world[j];
    const Vec2 d{b.x - a.x, b.y - a.y}, ap{p.x - a.x, p.y - a.y};
    const double t = std::clamp((d.x * ap.x + d.y * ap.y) / (d.x * d.x + d.y * d.y), 0.0, 1.0);
    const Vec2 off{ap.x - t * d.x, ap.y - t * d.y};
    squared = std::min(squared, off.x * off.x + off.y * off.y);
  }
  const double distance = std::sqrt(squared);
  return plain_inside(p, world) ? -distance : distance;
}

TEST(SeatPointClearance, IsThePlainTestsToTheBitOnAndOffTheBlock) {
  FixedUniforms u(4242);
  const SeatContacts posed(kTypeB, {{-1e5, 0.0}, {1e5, 0.0}});
  const std::size_t n = kTypeB.size();
  int inside = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const BlockState s{u(-5, 5), u(-5, 5), u(-1.6, 1.6), 0.0, 0.0, 0.0};
    std::vector<Vec2> world(n);
    posed.world_vertices(s, world);
    // On the corners, along the edges, near the block and far from it.
    std::vector<Vertex> seat;
    for (std::size_t i = 0; i < n; ++i) {
      const Vec2 a = world[i], b = world[(i + 1) % n];
      const double f = u(0, 1);
      seat.push_back({a.x, a.y});
      seat.push_back({a.x + f * (b.x - a.x), a.y + f * (b.y - a.y)});
      seat.push_back({s.x + u(-30, 30), s.y + u(-30, 30)});
    }
    seat.push_back({-1e5, u(-10, 10)});
    seat.push_back({1e5, u(-10, 10)});
    std::sort(seat.begin(), seat.end());
    const SeatContacts contacts(kTypeB, seat);
    for (int k = 0; k < contacts.point_count(); ++k) {
      const Vec2 p = contacts.seat_point(k);
      EXPECT_EQ(contacts.inside_block(k, world), plain_inside(p, world));
      EXPECT_EQ(contacts.point_clearance(k, world), plain_clearance(p, world));
      inside += plain_inside(p, world) ? 1 : 0;
    }
  }
  EXPECT_GT(inside, 300);  // the test tells inside from outside
}

// The edges pruned by their height over or under p (a point under the block's base, above its
// top, beside it): points straight under or over each vertex tie that vertex's two edges, whose
// rounded distances differ by an ulp where one of them is taken as ap - d, so a bound without its
// room for rounding would keep the larger.
TEST(SeatPointClearance, PrunedEdgesKeepTheLeastToTheBit) {
  FixedUniforms u(977);
  const SeatContacts posed(kTypeB, {{-1e5, 0.0}, {1e5, 0.0}});
  const std::size_t n = kTypeB.size();
  for (int trial = 0; trial < 3000; ++trial) {
    const BlockState s{u(-20, 20), u(-20, 20), u(-3.2, 3.2), 0.0, 0.0, 0.0};
    std::vector<Vec2> world(n);
    posed.world_vertices(s, world);
    std::vector<Vertex> seat;
    for (std::size_t i = 0; i < n; ++i) {
      const Vec2 v = world[i];
      seat.push_back({v.x, v.y - u(0, 1) * std::pow(10.0, u(-6, 1))});
      seat.push_back({v.x, v.y + u(0, 1) * std::pow(10.0, u(-6, 1))});
      seat.push_back({v.x + u(-1e-9, 1e-9), v.y - u(0, 3)});
      seat.push_back({s.x + u(-25, 25), s.y + u(-25, 25)});
    }
    std::sort(seat.begin(), seat.end());
    const SeatContacts contacts(kTypeB, seat);
    for (int k = 0; k < contacts.point_count(); ++k) {
      EXPECT_EQ(contacts.point_clearance(k, world), plain_clearance(contacts.seat_point(k), world));
    }
  }
}

}  // namespace
}  // namespace blockfrag
