// The sweep-line test for edges that meet against the all-pairs test it replaces: the same verdict
// on thousands of random polygons (simple ones, tangled ones, and ones on an integer grid, where
// vertical edges, shared x coordinates and vertices touching other edges are common).
#include "engine/scene/polygon_simplicity.hpp"

#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

#include <gtest/gtest.h>

namespace blockfrag {
namespace {

bool any_meeting_by_all_pairs(const std::vector<Vertex>& v) {
  const std::size_t n = v.size();
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // neighbours share vertex 0
      if (segments_meet(v[i], v[(i + 1) % n], v[j], v[(j + 1) % n])) return true;
    }
  }
  return false;
}

// No straight or folded corner and no repeated vertex: what first_meeting_edges assumes.
bool corners_are_proper(const std::vector<Vertex>& v) {
  const std::size_t n = v.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vertex& a = v[(i + n - 1) % n];
    const Vertex& b = v[i];
    const Vertex& c = v[(i + 1) % n];
    if ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]) == 0) return false;
  }
  return true;
}

class Draw {
 public:
  explicit Draw(std::uint64_t seed) : engine_(seed) {}
  double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
  int integer(int below) { return static_cast<int>(engine_() % static_cast<std::uint64_t>(below)); }

 private:
  std::mt19937_64 engine_;
};

// A star-shaped polygon around the origin: simple by construction.
std::vector<Vertex> star(Draw& draw, int n) {
  std::vector<Vertex> v;
  for (int k = 0; k < n; ++k) {
    const double angle = 2 * std::numbers::pi * (k + 0.8 * draw.uniform()) / n;
    const double radius = 0.2 + draw.uniform();
    v.push_back({radius * std::cos(angle), radius * std::sin(angle)});
  }
  return v;
}

TEST(PolygonSimplicity, StarShapedPolygonsAreSimple) {
  Draw draw(1);
  for (int trial = 0; trial < 200; ++trial) {
    const auto v = star(draw, 3 + draw.integer(200));
    EXPECT_FALSE(first_meeting_edges(v).has_value()) << "trial " << trial;
  }
}

TEST(PolygonSimplicity, AgreesWithAllPairsOnTangledAndGridPolygons) {
  Draw draw(2);
  int tangled = 0, compared = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    std::vector<Vertex> v;
    if (trial % 2 == 0) {
      v = star(draw, 4 + draw.integer(40));
      // Swap one or two pairs of vertices: usually tangles it, sometimes not.
      for (int swaps = 1 + draw.integer(2); swaps > 0; --swaps) {
        std::swap(v[static_cast<std::size_t>(draw.integer(static_cast<int>(v.size())))],
                  v[static_cast<std::size_t>(draw.integer(static_cast<int>(v.size())))]);
      }
    } else {
      // Vertices on a 5 x 5 integer grid: vertical edges, equal x and touching are everywhere.
      const int n = 3 + draw.integer(8);
      for (int k = 0; k < n; ++k) v.push_back({double(draw.integer(5)), double(draw.integer(5))});
    }
    if (!corners_are_proper(v)) continue;
    ++compared;
    const bool expected = any_meeting_by_all_pairs(v);
    tangled += expected ? 1 : 0;
    const auto found = first_meeting_edges(v);
    ASSERT_EQ(found.has_value(), expected) << "trial " << trial;
    if (found) {
      const std::size_t n = v.size();
      const auto [i, j] = *found;
      EXPECT_TRUE(segments_meet(v[i], v[(i + 1) % n], v[j], v[(j + 1) % n]));
    }
  }
  // Both verdicts were exercised many times.
  EXPECT_GT(compared, 2000);
  EXPECT_GT(tangled, 500);
  EXPECT_GT(compared - tangled, 500);
}

TEST(PolygonSimplicity, TellsAReflexCornerFromAVertexTouchingAnotherEdge) {
  // An arrow: (1, 1) is a reflex corner, and the polygon is simple.
  EXPECT_FALSE(first_meeting_edges({{0, 0}, {2, 0}, {2, 2}, {1, 1}, {0, 2}}).has_value());
  // Pinched: vertex 3 at (1, 0) lies on edge 0, from (0, 0) to (2, 0), which is not one of its own.
  const std::vector<Vertex> pinched = {{0, 0}, {2, 0}, {1, 0.5}, {1, 0}, {0.5, 1}};
  ASSERT_TRUE(corners_are_proper(pinched));
  const auto found = first_meeting_edges(pinched);
  ASSERT_TRUE(found.has_value());
  EXPECT_EQ(found->first, 0u);
}

}  // namespace
}  // namespace blockfrag
