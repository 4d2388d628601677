// Polygon blocks: mass properties against hand computations, the geometry the engine sees, and the
// rules a vertex list must keep.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "engine/scene/block_geometry.hpp"
#include "engine/scene/polygon_properties.hpp"

namespace blockfrag {
namespace {

constexpr double kPi = std::numbers::pi;

// A w x h rectangle, lower left corner at (3, -1), listed from its top right corner: area w h,
// centroid in the middle, I/M = (w^2 + h^2) / 12.
TEST(PolygonProperties, RectangleFromAnyStartingVertex) {
  const std::vector<Vertex> rectangle = {{5, 0}, {3, 0}, {3, -1}, {5, -1}};  // w = 2, h = 1
  const PolygonProperties p = polygon_properties(rectangle);
  EXPECT_DOUBLE_EQ(p.area, 2.0);
  EXPECT_DOUBLE_EQ(p.centroid[0], 4.0);
  EXPECT_DOUBLE_EQ(p.centroid[1], -0.5);
  EXPECT_DOUBLE_EQ(p.inertia_per_mass, (4.0 + 1.0) / 12.0);
  // The hull (here all vertices) starts at the base's left end, relative to the centroid.
  ASSERT_EQ(p.hull.size(), 4u);
  EXPECT_DOUBLE_EQ(p.hull[0][0], -1.0);
  EXPECT_DOUBLE_EQ(p.hull[0][1], -0.5);
  EXPECT_DOUBLE_EQ(p.hull[1][0], 1.0);
  EXPECT_DOUBLE_EQ(p.hull[1][1], -0.5);
  EXPECT_DOUBLE_EQ(p.hull[2][0], 1.0);
  EXPECT_DOUBLE_EQ(p.hull[2][1], 0.5);
}

// Right triangle with legs b = 3 along x and h = 4 along y: area b h / 2 = 6, centroid (b/3, h/3),
// centroidal second moments b h^3 / 36 = 16/3 and h b^3 / 36 = 3, so I/M = (16/3 + 3) / 6 = 25/18
// (= (b^2 + h^2) / 18).
TEST(PolygonProperties, RightTriangle) {
  const PolygonProperties p = polygon_properties({{0, 0}, {3, 0}, {0, 4}});
  EXPECT_DOUBLE_EQ(p.area, 6.0);
  EXPECT_DOUBLE_EQ(p.centroid[0], 1.0);
  EXPECT_DOUBLE_EQ(p.centroid[1], 4.0 / 3.0);
  EXPECT_NEAR(p.inertia_per_mass, 25.0 / 18.0, 1e-15);

  const BlockGeometry block(PolygonBlock{{{0, 0}, {3, 0}, {0, 4}}, 6.0});
  ASSERT_EQ(block.corner_count(), 3);
  EXPECT_NEAR(block.rest_height(), 4.0 / 3.0, 1e-15);
  // Corner arms (-1, -4/3) and (2, -4/3): tip thresholds 1 / (4/3) and 2 / (4/3).
  EXPECT_NEAR(block.tip_threshold(Corner::left), 0.75, 1e-15);
  EXPECT_NEAR(block.tip_threshold(Corner::right), 1.5, 1e-15);
  EXPECT_NEAR(block.flat_slide_friction_limit(+1), 1.5,
              1e-15);  // sliding right: leads on the right
  EXPECT_NEAR(block.flat_slide_friction_limit(-1), 0.75, 1e-15);
  // The vertical leg lands after pi/2 about the left corner; the hypotenuse, rising at
  // atan2(4, -3) from the right corner, after pi - atan(4/3) clockwise.
  EXPECT_NEAR(block.overturn_angle(Corner::left), kPi / 2, 1e-15);
  EXPECT_NEAR(block.overturn_angle(Corner::right), kPi - std::atan(4.0 / 3.0), 1e-15);
  // R: the farthest corner, (-1, 8/3) from the centroid.
  EXPECT_NEAR(block.size(), std::hypot(1.0, 8.0 / 3.0), 1e-15);
  EXPECT_NEAR(block.inertia_per_mass(), 25.0 / 18.0, 1e-14);
}

// The paper's type A dam block (section 4): a gravity dam 100 m high, 10 m wide at the crest, with
// a 0.75 downstream slope; crack A is horizontal, 16.7 m below the crest. Our reading (the paper's
// Fig. 5 is not in the text): the upstream face is vertical (only a downstream slope is given), and
// the downstream face is vertical from the crest to 13.3 m below it, where the 0.75 slope starts
// (10 m / 0.75 = 13.33 m: the basic triangle's apex is at crest level, as in the usual profile; the
// issue rounds it to 13.3 m and so do we). Upstream on the left, the crack at y = 0:
// (0, 0), (12.55, 0), (10, 3.4), (10, 16.7), (0, 16.7); 12.55 = 10 + 0.75 * (16.7 - 13.3).
TEST(PolygonProperties, TypeADamBlockMatchesTheHandComputation) {
  const std::vector<Vertex> dam = {{0, 0}, {12.55, 0}, {10, 3.4}, {10, 16.7}, {0, 16.7}};
  // Hand computation: a 10 x 16.7 rectangle and the toe, a right triangle with legs 2.55 (x) and
  // 3.4 (y) at (10, 0).
  const double a_rect = 10 * 16.7, a_toe = 0.5 * 2.55 * 3.4;  // 167, 4.335 m^2
  const double x_rect = 5, y_rect = 8.35, x_toe = 10 + 2.55 / 3, y_toe = 3.4 / 3;
  const double area = a_rect + a_toe;                          // 171.335 m^2
  const double cx = (a_rect * x_rect + a_toe * x_toe) / area;  // 5.14801 m
  const double cy = (a_rect * y_rect + a_toe * y_toe) / area;  // 8.16741 m
  // Polar moments about each part's own centroid (rectangle (w^2 + h^2)/12, right triangle
  // (b^2 + h^2)/18 per area), moved to the block's centroid (parallel axes).
  const double j = a_rect * (10 * 10 + 16.7 * 16.7) / 12 + a_toe * (2.55 * 2.55 + 3.4 * 3.4) / 18 +
                   a_rect * (std::pow(x_rect - cx, 2) + std::pow(y_rect - cy, 2)) +
                   a_toe * (std::pow(x_toe - cx, 2) + std::pow(y_toe - cy, 2));
  const double k2 = j / area;  // I/M = 32.929 m^2

  const PolygonProperties p = polygon_properties(dam);
  EXPECT_NEAR(p.area, 171.335, 1e-12);
  EXPECT_NEAR(p.area, area, 1e-12);
  EXPECT_NEAR(p.centroid[0], cx, 1e-12);
  EXPECT_NEAR(p.centroid[1], cy, 1e-12);
  EXPECT_NEAR(cx, 5.148013, 1e-6);
  EXPECT_NEAR(cy, 8.167409, 1e-6);
  EXPECT_NEAR(p.inertia_per_mass, k2, 1e-11);
  EXPECT_NEAR(k2, 32.92901, 1e-5);

  // Per metre of dam, concrete at 2400 kg/m^3: M = 2400 * 171.335 = 411204 kg.
  const double mass = 2400 * area;
  const BlockGeometry block(PolygonBlock{dam, mass});
  EXPECT_NEAR(block.inertia_per_mass(), k2, 1e-11);
  EXPECT_NEAR(block.rest_height(), cy, 1e-12);
  // Upstream heel (left) at cx from the centroid, downstream toe (right) at 12.55 - cx.
  EXPECT_NEAR(block.tip_threshold(Corner::left), cx / cy, 1e-12);             // 0.6303: 32.2 deg
  EXPECT_NEAR(block.tip_threshold(Corner::right), (12.55 - cx) / cy, 1e-12);  // 0.9063: 42.2 deg
  Scene scene;
  scene.polygon = PolygonBlock{dam, mass};
  EXPECT_NEAR(block_alpha(scene), std::atan(cx / cy), 1e-12);    // the heel tips first
  EXPECT_NEAR(block.size(), std::hypot(12.55 - cx, cy), 1e-12);  // the toe is the farthest corner
}

// The slope break (10, 3.4) is a reflex corner (the face turns outwards going down): it never
// touches a flat ground. The corners are the convex hull's, and rocking about the toe lays the
// block on the hull's face from the toe to the crest's downstream corner (10, 16.7), after
// pi - atan(16.7 / 2.55) = 98.7 deg, before the slope could land.
TEST(PolygonBlockGeometry, TypeADamBlockTouchesTheGroundWithItsConvexHull) {
  const BlockGeometry block(
      PolygonBlock{{{0, 16.7}, {0, 0}, {12.55, 0}, {10, 3.4}, {10, 16.7}}, 1.0});
  ASSERT_EQ(block.corner_count(), 4);
  const double cx = block.corner(0).x, cy = block.corner(0).y;  // heel minus centroid
  EXPECT_NEAR(block.corner(1).x - cx, 12.55, 1e-12);
  EXPECT_NEAR(block.corner(1).y - cy, 0.0, 1e-12);
  EXPECT_NEAR(block.corner(2).x - cx, 10.0, 1e-12);
  EXPECT_NEAR(block.corner(2).y - cy, 16.7, 1e-12);
  EXPECT_NEAR(block.corner(3).x - cx, 0.0, 1e-12);
  EXPECT_NEAR(block.corner(3).y - cy, 16.7, 1e-12);
  EXPECT_NEAR(block.overturn_angle(Corner::right), kPi - std::atan(16.7 / 2.55), 1e-12);
  EXPECT_NEAR(block.overturn_angle(Corner::left), kPi / 2, 1e-12);
}

TEST(PolygonBlockGeometry, RectangleVerticesGiveTheRectanglesGeometry) {
  const double a = 0.3, b = 1.7;
  const BlockGeometry rectangle(RectangularBlock{a, b, 2.0});
  // Listed from the top left, in a frame where the base is at y = 0.
  const BlockGeometry polygon(PolygonBlock{{{-a, 2 * b}, {-a, 0}, {a, 0}, {a, 2 * b}}, 2.0});
  ASSERT_EQ(polygon.corner_count(), rectangle.corner_count());
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(polygon.corner(i).x, rectangle.corner(i).x, 1e-15) << i;
    EXPECT_NEAR(polygon.corner(i).y, rectangle.corner(i).y, 1e-15) << i;
  }
  EXPECT_NEAR(polygon.inertia_per_mass(), rectangle.inertia_per_mass(), 1e-15);
  EXPECT_NEAR(polygon.size(), rectangle.size(), 1e-15);
  EXPECT_NEAR(polygon.rest_height(), rectangle.rest_height(), 1e-15);
  EXPECT_EQ(polygon.overturn_angle(Corner::left), kPi / 2);
  EXPECT_EQ(polygon.overturn_angle(Corner::right), kPi / 2);
  EXPECT_NEAR(polygon.tip_threshold(Corner::right), a / b, 1e-15);
}

std::string defect_of(const std::vector<Vertex>& vertices) {
  const auto defect = polygon_defect(vertices);
  return defect ? std::to_string(defect->vertex) + ": " + defect->rule : "none";
}

TEST(PolygonDefect, AcceptsBlocksOnTheirBase) {
  EXPECT_EQ(defect_of({{0, 0}, {3, 0}, {0, 4}}), "none");
  EXPECT_EQ(defect_of({{0, 0}, {12.55, 0}, {10, 3.4}, {10, 16.7}, {0, 16.7}}), "none");
  EXPECT_EQ(defect_of({{0, 1}, {0, 0}, {1, 0}, {1, 1}}), "none");
  EXPECT_EQ(defect_of({{0, 0}, {2, 0}, {2, 2}, {1, 0.5}, {0, 2}}), "none");  // a reflex corner
}

TEST(PolygonDefect, NamesTheRuleAndTheVertex) {
  EXPECT_EQ(defect_of({{0, 0}, {1, 0}}).substr(0, 26), "-1: needs at least 3 verti");
  EXPECT_EQ(defect_of({{0, 0}, {1, 0}, {0, NAN}}), "2: coordinates must be finite");
  EXPECT_EQ(defect_of({{0, 0}, {0, 1}, {1, 0}}).substr(0, 16), "-1: is clockwise");
  // (1, 0) is a straight corner (three vertices on the base); (1, 0) again repeats a vertex.
  EXPECT_EQ(defect_of({{0, 0}, {1, 0}, {2, 0}, {2, 1}, {0, 1}}).substr(0, 25),
            "1: makes a straight corne");
  EXPECT_EQ(defect_of({{0, 0}, {1, 0}, {1, 0}, {1, 1}}).substr(0, 10), "1: makes a");
  // A bow tie, and a pentagram (it turns left at every vertex but winds twice).
  EXPECT_EQ(defect_of({{0, 0}, {1, 0}, {0, 1}, {1, 1}}).substr(0, 19), "-1: crosses itself ");
  std::vector<Vertex> star;
  for (int k = 0; k < 5; ++k) {
    const double angle = -kPi / 2 + 4 * kPi * k / 5;
    star.push_back({std::cos(angle), std::sin(angle)});
  }
  EXPECT_EQ(defect_of(star).substr(0, 19), "-1: crosses itself ");
  // A diamond stands on a vertex, not an edge; a U stands on two feet.
  EXPECT_EQ(defect_of({{0, -1}, {1, 0}, {0, 1}, {-1, 0}}).substr(0, 37),
            "0: is at the lowest y with 0 other ve");
  EXPECT_EQ(
      defect_of({{0, 0}, {1, 0}, {1, 1}, {2, 1}, {2, 0}, {3, 0}, {3, 2}, {0, 2}}).substr(0, 37),
      "0: is at the lowest y with 3 other ve");
  // Overhanging so far that the centre of mass is beyond the base's right end.
  EXPECT_EQ(defect_of({{0, 0}, {1, 0}, {5, 1}, {4, 1}}).substr(0, 36),
            "-1: has its centre of mass (x = 2.5)");
}

}  // namespace
}  // namespace blockfrag
