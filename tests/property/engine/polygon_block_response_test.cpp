// A polygon block responds as the physics says it must: given a rectangle's vertices it is that
// rectangle; mirrored (with the ground motion) it mirrors; it starts rocking about a corner exactly
// when lambda passes that corner's tip threshold.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "engine/simulate.hpp"
#include "tests/support/scene_builders.hpp"

namespace blockfrag {
namespace {

using testing::block_scene;
using testing::rk4;

PolygonBlock rectangle_polygon(const RectangularBlock& r, int first_vertex, double dx, double dy) {
  const std::vector<std::array<double, 2>> ccw = {{dx - r.half_width, dy},
                                                  {dx + r.half_width, dy},
                                                  {dx + r.half_width, dy + 2 * r.half_height},
                                                  {dx - r.half_width, dy + 2 * r.half_height}};
  PolygonBlock polygon{{}, r.mass};
  for (int i = 0; i < 4; ++i)
    polygon.vertices.push_back(ccw[static_cast<std::size_t>((first_vertex + i) % 4)]);
  return polygon;
}

bool visits(const Summary& s, ModeKind kind) {
  return std::any_of(s.modes.begin(), s.modes.end(),
                     [&](const ModeChange& m) { return m.mode == kind; });
}

void expect_same(const Summary& a, const Summary& b, double tolerance) {
  EXPECT_EQ(a.status, b.status);
  EXPECT_EQ(a.steps, b.steps);
  EXPECT_EQ(a.overturned, b.overturned);
  EXPECT_EQ(a.impacts, b.impacts);
  EXPECT_EQ(a.events, b.events);
  EXPECT_NEAR(a.max_abs_theta, b.max_abs_theta, tolerance);
  EXPECT_NEAR(a.final_theta, b.final_theta, tolerance);
  EXPECT_NEAR(a.final_slide, b.final_slide, tolerance);
  EXPECT_NEAR(a.max_abs_slide, b.max_abs_slide, tolerance);
  EXPECT_NEAR(a.end_time, b.end_time, tolerance);
  ASSERT_EQ(a.modes.size(), b.modes.size());
  for (std::size_t i = 0; i < a.modes.size(); ++i) {
    EXPECT_EQ(a.modes[i].mode, b.modes[i].mode) << "mode change " << i;
    EXPECT_NEAR(a.modes[i].time, b.modes[i].time, tolerance) << "mode change " << i;
  }
}

// Rock, slide, slide-rock, flight and impacts (the paper's example), sliding alone, rocking with
// e = 0, and overturning.
std::vector<Scene> rectangle_scenes() {
  return {block_scene(0.5, 1.0, 0.6, 0.6, CosinePulse{1.0, 2.0, 1.0}, 4.0, 1e-9),
          block_scene(0.3, 1.0, 0.8, 0.3, SinePulse{0.7, 1.0, 2.0}, 4.0, 1e-9),
          block_scene(0.5, 1.0, 0.35, 0.5, RectangularPulse{0.8, 0.4}, 2.0, 1e-9),
          block_scene(0.2, 1.5, 1.0, 0.0, CosinePulse{0.45, 0.8, 3.0}, 5.0, 1e-9),
          block_scene(0.2, 1.0, 0.8, 0.5, SinePulse{0.6, 1.5, 1.0}, 4.0, 1e-9)};
}

TEST(PolygonResponse, RectangleVerticesGiveTheRectanglesResults) {
  bool overturned = false, flew = false, slid = false, slide_rocked = false, impacted = false;
  for (const Scene& scene : rectangle_scenes()) {
    for (const Scene& base : {scene, rk4(scene, 2.5e-4)}) {
      const Summary expected = simulate(base);
      overturned |= expected.overturned;
      flew |= visits(expected, ModeKind::flight);
      slid |= visits(expected, ModeKind::slide);
      slide_rocked |= visits(expected, ModeKind::slide_rock);
      impacted |= expected.impacts > 0;
      // From any starting vertex, the base on y = 0 or anywhere else: the same numbers to the
      // last bit (the mass properties come out exactly as the rectangle's when the vertices are
      // exact about the centre).
      for (const int first : {0, 1, 2, 3}) {
        Scene polygon = base;
        polygon.polygon =
            rectangle_polygon(base.block, first, 0.0, first == 3 ? -base.block.half_height : 0.0);
        polygon.block = {};  // unused
        SCOPED_TRACE("first vertex " + std::to_string(first));
        expect_same(simulate(polygon), expected, 0.0);
      }
    }
  }
  EXPECT_TRUE(overturned && flew && slid && slide_rocked && impacted)
      << "the scenes must cover every mode";
}

PolygonBlock mirrored(const PolygonBlock& p) {
  PolygonBlock m{{}, p.mass};
  // x -> -x reverses the turning: list the mirrored vertices backwards to stay counter-clockwise.
  for (auto it = p.vertices.rbegin(); it != p.vertices.rend(); ++it)
    m.vertices.push_back({-(*it)[0], (*it)[1]});
  return m;
}

// The paper's type A dam block (tests/unit/engine/polygon_block_test.cpp explains the vertices),
// and a trapezoid, mirrored with the ground motion's sign: theta and x flip, nothing else changes.
TEST(PolygonResponse, MirroredBlockAndMotionMirrorTheResponse) {
  const PolygonBlock dam{{{0, 0}, {12.55, 0}, {10, 3.4}, {10, 16.7}, {0, 16.7}}, 411204.0};
  const PolygonBlock trapezoid{{{0, 0}, {1, 0}, {0.7, 1.6}, {0.1, 1.6}}, 1.0};
  std::vector<Scene> scenes;
  for (const auto& [block, motion, duration] :
       {std::tuple{dam, GroundMotion{CosinePulse{1.0, 2.0, 1.0}}, 4.0},
        std::tuple{trapezoid, GroundMotion{SinePulse{0.9, 0.8, 1.0}}, 3.0},
        std::tuple{trapezoid, GroundMotion{RectangularPulse{0.5, 0.3}}, 2.0}}) {
    for (const Method method : {Method::adaptive, Method::rk4}) {
      Scene scene = block_scene(0.5, 1.0, 1.05, 0.3, motion, duration, 1e-9);
      scene.solver.method = method;
      scene.polygon = block;
      scenes.push_back(scene);
    }
  }
  bool rocked_both_ways = false;
  for (const Scene& scene : scenes) {
    Scene mirror = scene;
    mirror.polygon = mirrored(*scene.polygon);
    std::visit(
        [](auto& m) {
          if constexpr (requires { m.amplitude_g; }) m.amplitude_g = -m.amplitude_g;
        },
        mirror.ground_motion);
    const auto a = simulate_with_history(scene, 0.01), b = simulate_with_history(mirror, 0.01);
    EXPECT_EQ(a.summary.overturned, b.summary.overturned);
    EXPECT_EQ(a.summary.impacts, b.summary.impacts);
    EXPECT_NEAR(a.summary.final_theta, -b.summary.final_theta, 1e-9);
    EXPECT_NEAR(a.summary.final_slide, -b.summary.final_slide, 1e-9);
    EXPECT_NEAR(a.summary.max_abs_theta, b.summary.max_abs_theta, 1e-9);
    ASSERT_EQ(a.history.size(), b.history.size());
    double most = 0, least = 0;
    for (std::size_t i = 0; i < a.history.size(); ++i) {
      EXPECT_NEAR(a.history[i].theta, -b.history[i].theta, 1e-9) << "row " << i;
      EXPECT_NEAR(a.history[i].x, -b.history[i].x, 1e-9) << "row " << i;
      most = std::max(most, a.history[i].theta);
      least = std::min(least, a.history[i].theta);
    }
    rocked_both_ways |= most > 1e-3 && least < -1e-3;
  }
  EXPECT_TRUE(rocked_both_ways) << "an asymmetric block must rock about both corners somewhere";
}

// Right triangle, legs 3 (base) and 4: corner arms (-1, -4/3) and (2, -4/3) from the centroid
// (1, 4/3), so rocking starts about the right corner for lambda > 2 / (4/3) = 1.5 and about the
// left one for -lambda > 1 / (4/3) = 0.75 (friction too large to slide).
TEST(PolygonResponse, RockingStartsAtEachCornersTipThreshold) {
  const PolygonBlock triangle{{{0, 0}, {3, 0}, {0, 4}}, 1.0};
  const auto run = [&](double lambda) {
    Scene scene = block_scene(0.5, 1.0, 10.0, 0.5, RectangularPulse{lambda, 0.3}, 0.3, 1e-9);
    scene.polygon = triangle;
    return simulate_with_history(scene, 0.01);
  };
  for (const double margin : {1.001, 0.999}) {
    SCOPED_TRACE("lambda over its threshold: " + std::to_string(margin));
    const auto right = run(1.5 * margin);
    const auto left = run(-0.75 * margin);
    const bool rocks = margin > 1;
    EXPECT_EQ(right.summary.rock_start_time.has_value(), rocks);
    EXPECT_EQ(left.summary.rock_start_time.has_value(), rocks);
    EXPECT_FALSE(right.summary.slide_start_time.has_value());
    // Clockwise about the right corner, counter-clockwise about the left.
    const auto [low, high] =
        std::minmax_element(right.history.begin(), right.history.end(),
                            [](const auto& p, const auto& q) { return p.theta < q.theta; });
    EXPECT_EQ(high->theta, 0.0);
    EXPECT_EQ(low->theta < 0, rocks);
    const auto [low_l, high_l] =
        std::minmax_element(left.history.begin(), left.history.end(),
                            [](const auto& p, const auto& q) { return p.theta < q.theta; });
    EXPECT_EQ(low_l->theta, 0.0);
    EXPECT_EQ(high_l->theta > 0, rocks);
  }
  // Between the thresholds the rectangle rule (one a/b for both sides) would be wrong either way.
  EXPECT_FALSE(run(1.2).summary.rock_start_time.has_value());
  EXPECT_TRUE(run(-1.2).summary.rock_start_time.has_value());
}

}  // namespace
}  // namespace blockfrag
