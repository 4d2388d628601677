// The reservoir's hydrostatic push (engine/water/hydrostatic.hpp) against closed forms: a vertical
// face wetted to depth d takes 1/2 rho g d^2 at d/3 above its foot (USACE EM 1110-2-2200, 1995,
// Gravity Dam Design: the hydrostatic pressure rho g y at depth y on the upstream face); a sloping
// face takes the same horizontal push (its projected height) plus the weight of the water above
// it; a tilted block's face against a brute-force quadrature of the pressure; no water below the
// block.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <utility>

#include <gtest/gtest.h>

#include "engine/water/hydrostatic.hpp"
#include "tests/support/paper_block.hpp"
#include "tests/support/water_outlines.hpp"

namespace blockfrag {
namespace {

using testing::kBaseEdge;
using testing::kGravity;
using testing::kWaterDensity;
using testing::rectangle_outline;

WorldPolygon rotated(const WorldPolygon& polygon, const Vertex& pivot, double theta) {
  WorldPolygon out;
  for (const Vertex& v : polygon) {
    const double x = v[0] - pivot[0], y = v[1] - pivot[1];
    out.push_back({pivot[0] + x * std::cos(theta) - y * std::sin(theta),
                   pivot[1] + x * std::sin(theta) + y * std::cos(theta)});
  }
  return out;
}

// The height of the push's line of action for a horizontal force: M = -(y - c_y) F_x.
double action_height(const WaterLoad& load, const Vertex& reference) {
  return reference[1] - load.moment / load.fx;
}

TEST(Hydrostatic, VerticalFaceTakesHalfRhoGDSquaredAtAThirdOfTheDepth) {
  for (const double d : {0.5, 3.0, 8.0}) {
    const Vertex centre{2.0, 4.0};
    const WaterLoad load = hydrostatic_load(rectangle_outline(4.0, 8.0),
                                            {d, kWaterDensity, kGravity}, kBaseEdge, centre);
    EXPECT_NEAR(load.fx, 0.5 * kWaterDensity * kGravity * d * d,
                1e-12 * kWaterDensity * kGravity * d * d)
        << d;
    EXPECT_EQ(load.fy, 0.0) << d;
    EXPECT_NEAR(action_height(load, centre), d / 3, 1e-12 * d) << d;
  }
}

// The upstream face leans back, its foot w upstream of its top: the wetted part (depth d of the
// face's height h) runs w d / h horizontally, and the water above it is a triangle of area
// 1/2 d (w d / h), whose weight presses the face down.
TEST(Hydrostatic, SlopingFaceAddsTheWeightOfTheWaterAboveIt) {
  const double w = 3.0, h = 10.0, d = 6.0;
  const WorldPolygon trapezoid{{-w, 0}, {5.0, 0}, {5.0, h}, {0, h}};
  const WaterLoad load =
      hydrostatic_load(trapezoid, {d, kWaterDensity, kGravity}, kBaseEdge, {1.0, 4.0});
  EXPECT_NEAR(load.fx, 0.5 * kWaterDensity * kGravity * d * d, 1e-9);
  EXPECT_NEAR(load.fy, -kWaterDensity * kGravity * 0.5 * d * (w * d / h), 1e-9);
}

// A face of two edges (a kink in the upstream face) against the same face as one edge: the push
// is additive over the pieces, and the kink above the water changes nothing.
TEST(Hydrostatic, SplitFaceAddsUp) {
  const WorldPolygon whole = rectangle_outline(4.0, 8.0);
  const WorldPolygon split{{0, 0}, {4.0, 0}, {4.0, 8.0}, {0, 8.0}, {0, 2.5}};
  for (const double surface : {2.0, 6.0}) {
    const WaterLoad a =
        hydrostatic_load(whole, {surface, kWaterDensity, kGravity}, kBaseEdge, {1.0, 3.0});
    const WaterLoad b =
        hydrostatic_load(split, {surface, kWaterDensity, kGravity}, kBaseEdge, {1.0, 3.0});
    EXPECT_NEAR(a.fx, b.fx, 1e-9 * a.fx);
    EXPECT_NEAR(a.moment, b.moment, 1e-9 * std::abs(a.moment));
  }
}

TEST(Hydrostatic, NoWaterAtOrBelowTheLowestPointIsExactlyZero) {
  const WorldPolygon tilted = rotated(rectangle_outline(4.0, 8.0), {4.0, 0.0}, 0.1);
  double lowest = tilted[0][1];
  for (const Vertex& v : tilted) lowest = std::min(lowest, v[1]);
  for (const double surface : {lowest, lowest - 1.0}) {
    const WaterLoad load =
        hydrostatic_load(tilted, {surface, kWaterDensity, kGravity}, kBaseEdge, {2.0, 4.0});
    EXPECT_EQ(load.fx, 0.0);
    EXPECT_EQ(load.fy, 0.0);
    EXPECT_EQ(load.moment, 0.0);
  }
}

// The pressure integrated by the midpoint rule over each edge turned upstream, n points an edge,
// clipped by max(0, depth) rather than at the surface: O(1/n^2) from the exact resultant, except
// at the surface crossing (O(1/n)).
WaterLoad quadrature(const WorldPolygon& polygon, double surface, const Vertex& c, int n) {
  WaterLoad sum;
  for (std::size_t i = 1; i < polygon.size(); ++i) {  // edge 0 is the base
    const Vertex& a = polygon[i];
    const Vertex& b = polygon[(i + 1) % polygon.size()];
    const double dx = b[0] - a[0], dy = b[1] - a[1], length = std::hypot(dx, dy);
    const double nx = dy / length, ny = -dx / length;
    if (nx >= 0) continue;
    for (int k = 0; k < n; ++k) {
      const double t = (k + 0.5) / n;
      const double x = a[0] + t * dx, y = a[1] + t * dy;
      const double force = kWaterDensity * kGravity * std::max(0.0, surface - y) * length / n;
      sum.fx -= nx * force;
      sum.fy -= ny * force;
      sum.moment += (x - c[0]) * (-ny * force) - (y - c[1]) * (-nx * force);
    }
  }
  return sum;
}

// The type A dam block's outline tilted both ways: toe lifted (counter-clockwise about the heel)
// its upstream face overhangs and the water pushes it up; heel lifted (clockwise about the toe) the
// face leans downstream and the water presses it down. Either way the horizontal push is
// 1/2 rho g D^2 with D the depth of the face's foot (the heel).
TEST(Hydrostatic, TiltedBlockMatchesAQuadratureOfItsRotatedFace) {
  const WorldPolygon upright{{0, 0}, {12.55, 0}, {10, 3.4}, {10, 16.7}, {0, 16.7}};
  const double surface = 14.0;
  for (const auto& [pivot, theta] :
       {std::pair<Vertex, double>{{12.55, 0}, -0.08}, std::pair<Vertex, double>{{0, 0}, 0.05}}) {
    const WorldPolygon tilted = rotated(upright, pivot, theta);
    const Vertex centre = rotated(WorldPolygon{Vertex{5.6, 7.9}}, pivot, theta)[0];
    const WaterLoad exact =
        hydrostatic_load(tilted, {surface, kWaterDensity, kGravity}, kBaseEdge, centre);
    const WaterLoad sum = quadrature(tilted, surface, centre, 400'000);
    const double scale = 0.5 * kWaterDensity * kGravity * surface * surface;
    EXPECT_NEAR(exact.fx, sum.fx, 1e-5 * scale) << theta;
    EXPECT_NEAR(exact.fy, sum.fy, 1e-5 * scale) << theta;
    EXPECT_NEAR(exact.moment, sum.moment, 1e-5 * scale * 16.7) << theta;
    const double heel_depth = surface - tilted[0][1];
    EXPECT_NEAR(exact.fx, 0.5 * kWaterDensity * kGravity * heel_depth * heel_depth, 1e-9 * scale)
        << theta;
    EXPECT_GT(std::abs(exact.fy), 1e-3 * scale) << theta;  // the face is no longer vertical
    EXPECT_EQ(exact.fy > 0, theta > 0) << "an overhanging face is pushed up";
  }
}

}  // namespace
}  // namespace blockfrag
