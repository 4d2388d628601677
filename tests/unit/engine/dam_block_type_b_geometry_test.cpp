// The paper's type B dam block (docs/references.md, "The paper's type B dam block"): the closed
// forms derived there against an independent construction of the dam's faces and crack lines, and
// the mass properties against a decomposition into a rectangle and two triangles.
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "engine/scene/block_geometry.hpp"
#include "engine/scene/polygon_properties.hpp"
#include "tests/support/type_b_block.hpp"

namespace blockfrag {
namespace {

// The derivation's results, heel at the origin, upstream on the left.
using testing::kBreakY;
using testing::kFoldX;
using testing::kToeX;
using testing::kToeY;
using testing::kTypeB;

struct Line {
  Vec2 point, direction;
};

Vec2 intersect(const Line& a, const Line& b) {
  const double cross = a.direction.x * b.direction.y - a.direction.y * b.direction.x;
  const double dx = b.point.x - a.point.x, dy = b.point.y - a.point.y;
  const double t = (dx * b.direction.y - dy * b.direction.x) / cross;
  return {a.point.x + t * a.direction.x, a.point.y + t * a.direction.y};
}

// The dam in the crest's frame (upstream corner of the crest at the origin, y up), built from the
// paper's words alone: 10 m crest, vertical upstream face, downstream face vertical until the 0.75
// slope meets the crest's width, crack points 16.7 m (downstream) and 21.7 m (upstream) deep.
struct Dam {
  double slope = 0.75, crest = 10.0;
  double slope_start = -crest / slope;  // where the sloping face would cross x = crest
  Line upstream_face{{0, 0}, {0, -1}};
  Line downstream_slope{{crest, slope_start}, {slope, -1}};
  Line horizontal_crack{{0, -21.7}, {1, 0}};
  Line downstream_depth{{0, -16.7}, {1, 0}};
};

TEST(DamBlockTypeB, CoordinatesFollowFromTheFaces) {
  const Dam dam;
  const Vec2 heel = intersect(dam.upstream_face, dam.horizontal_crack);
  const Vec2 toe = intersect(dam.downstream_slope, dam.downstream_depth);
  // Perpendicular to the downstream face: its direction (0.75, -1) turned by a right angle.
  const Line normal_crack{toe, {1.0, dam.slope}};
  const Vec2 fold = intersect(normal_crack, dam.horizontal_crack);
  const Vec2 slope_break = intersect(dam.downstream_slope, Line{{dam.crest, 0}, {0, -1}});

  EXPECT_NEAR(heel.x, 0.0, 1e-14);
  // In the heel's frame.
  EXPECT_NEAR(fold.x - heel.x, kFoldX, 1e-12);
  EXPECT_NEAR(fold.x - heel.x, 5.858333, 5e-7);  // the "about x = 5.86"
  EXPECT_NEAR(toe.x - heel.x, kToeX, 1e-12);
  EXPECT_NEAR(toe.y - heel.y, kToeY, 1e-12);
  EXPECT_NEAR(slope_break.y - heel.y, kBreakY, 1e-12);
  EXPECT_NEAR(-heel.y, 21.7, 1e-12);
  // The toe lies on the sloping part (below the break), so the crack meets the slope, not the
  // vertical part of the downstream face.
  EXPECT_LT(toe.y, slope_break.y);

  // The incline rises at atan(0.75) and is perpendicular to the downstream slope.
  const double incline = std::atan2(kToeY, kToeX - kFoldX);
  EXPECT_NEAR(incline, std::atan(0.75), 1e-14);
  EXPECT_NEAR(incline * 180.0 / std::numbers::pi, 36.869898, 1e-6);
  EXPECT_NEAR((kToeX - kFoldX) * dam.slope + kToeY * -1.0, 0.0, 1e-12);
}

// A triangle's area and polar second moment about its centroid over its area: the sum of the
// squared sides over 36 (independent of the shoelace sums the engine uses).
struct Part {
  double area, cx, cy, polar_per_area;
};

Part triangle(Vec2 a, Vec2 b, Vec2 c) {
  const double area = std::abs((b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y)) / 2;
  const auto sq = [](Vec2 p, Vec2 q) {
    return (p.x - q.x) * (p.x - q.x) + (p.y - q.y) * (p.y - q.y);
  };
  return {area, (a.x + b.x + c.x) / 3, (a.y + b.y + c.y) / 3,
          (sq(a, b) + sq(b, c) + sq(c, a)) / 36};
}

TEST(DamBlockTypeB, MassPropertiesFromADecomposition) {
  // The 10 x 21.7 rectangle, less the triangle under the incline inside x <= 10, plus the toe's
  // triangle outside x = 10.
  const double under = 0.75 * (10 - kFoldX);
  const Part rect{10 * 21.7, 5, 10.85, (100 + 21.7 * 21.7) / 12};
  const Part cut = triangle({kFoldX, 0}, {10, 0}, {10, under});
  const Part toe = triangle({10, under}, {kToeX, kToeY}, {10, kBreakY});
  const double area = rect.area - cut.area + toe.area;
  const double cx = (rect.area * rect.cx - cut.area * cut.cx + toe.area * toe.cx) / area;
  const double cy = (rect.area * rect.cy - cut.area * cut.cy + toe.area * toe.cy) / area;
  const auto moment = [&](const Part& p) {
    return p.area * (p.polar_per_area + (p.cx - cx) * (p.cx - cx) + (p.cy - cy) * (p.cy - cy));
  };
  const double inertia_per_mass = (moment(rect) - moment(cut) + moment(toe)) / area;

  // The decomposition against the documented values.
  EXPECT_NEAR(area, 217.20875, 1e-9);
  EXPECT_NEAR(cx, 5.071424, 5e-7);
  EXPECT_NEAR(cy, 10.976799, 5e-7);
  EXPECT_NEAR(inertia_per_mass, 46.19106, 5e-6);
  EXPECT_NEAR(2400 * area, 521301.0, 1e-6);

  // The engine's shoelace formulas on the vertex list.
  ASSERT_FALSE(polygon_defect(kTypeB).has_value());
  const PolygonProperties p = polygon_properties(kTypeB);
  EXPECT_NEAR(p.area, area, 1e-11);
  EXPECT_NEAR(p.centroid[0], cx, 1e-12);
  EXPECT_NEAR(p.centroid[1], cy, 1e-12);
  EXPECT_NEAR(p.inertia_per_mass, inertia_per_mass, 1e-10);

  // The centre of mass lies over the horizontal part of the seat, so the heel and the fold carry
  // the block at rest; the heel tips at x_G / y_G.
  EXPECT_LT(cx, kFoldX);
  const BlockGeometry block(PolygonBlock{kTypeB, 2400 * area});
  EXPECT_NEAR(block.tip_threshold(Corner::left), 0.4620, 5e-5);
  EXPECT_NEAR(block.size(), std::hypot(cx, cy), 1e-12);  // the heel is the farthest corner
  EXPECT_NEAR(block.size(), 12.0917, 5e-5);
}

}  // namespace
}  // namespace blockfrag
