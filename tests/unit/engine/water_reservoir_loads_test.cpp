// The reservoir's loads on a scene's block at any pose (engine/water/reservoir_loads.hpp) against
// hand integrals. The block: a rectangle 10 m wide and 16 m high about its centre (base at
// y = -8), the water at y = 4 (d = 12 m on the upstream face), H = 100 m, effective area c = 0.85.
//   At rest and sliding: the push 1/2 rho g d^2 at d/3 above the base, the uplift
//     1/2 c rho g d B at B/3 from the heel, Westergaard's M_a = (7/12) rho sqrt(H) d^(3/2) at 0.4 d
//     above the base.
//   Rocking about the toe (heel up by the tilt) or the heel, and in flight: the tilted face's push
//     1/2 rho g D L along its normal at L/3 from the heel (D the heel's depth, L = D / cos theta
//     the wetted length), and each uplift rule's crack: "unchanged" the rest uplift along the
//     base's normal at the same point of the base, "zero_in_gap" nothing, "full_head_in_gap"
//     rho g D B at the base's middle.
//   A type B block on its folded seat: the uplift over both pieces, with its upstream push on the
//     incline.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "engine/scene/scene_validation.hpp"
#include "engine/water/reservoir_loads.hpp"

namespace blockfrag {
namespace {

constexpr double kLoadsG = 9.81, kLoadsRho = 1000.0, kLoadsPool = 100.0;
constexpr double kLoadsA = 5.0, kLoadsB = 8.0, kLoadsLevel = 4.0, kLoadsArea = 0.85;
constexpr double kLoadsDepth = kLoadsLevel + kLoadsB;  // d = 12 m
constexpr double kLoadsBase = 2 * kLoadsA;             // B = 10 m

Scene wet_rectangle(UpliftRule rule) {
  Scene scene;
  scene.block = {kLoadsA, kLoadsB, 2400.0 * 4 * kLoadsA * kLoadsB};
  scene.reservoir =
      Reservoir{kLoadsLevel, kLoadsPool, kLoadsRho, Hydrodynamic::westergaard, rule, kLoadsArea};
  validate_scene(scene);
  return scene;
}

// The flat ground's BlockState with the block turned by theta about a base corner at rest (x = +-a,
// y = -b in the scene's frame), lifted by `lift`: its centre of mass is the corner minus the
// turned corner vector; BlockState's (0, 0) is (0, -b), the centre's x and the ground.
BlockState turned_about(double corner_x, double theta, double lift) {
  const double rx = corner_x, ry = -kLoadsB;
  const double cx = corner_x - (rx * std::cos(theta) - ry * std::sin(theta));
  const double cy = -kLoadsB + lift - (rx * std::sin(theta) + ry * std::cos(theta));
  BlockState s;
  s.x = cx;
  s.y = cy + kLoadsB;
  s.theta = theta;
  return s;
}

// Counter-clockwise moment about the centre c of a force f at p.
double moment_of(const Vertex& p, const Vertex& c, double fx, double fy) {
  return (p[0] - c[0]) * fy - (p[1] - c[1]) * fx;
}

Vertex turned(const Vertex& body, const Vertex& centre, double theta) {
  return {centre[0] + body[0] * std::cos(theta) - body[1] * std::sin(theta),
          centre[1] + body[0] * std::sin(theta) + body[1] * std::cos(theta)};
}

void expect_load(const WaterLoad& load, double fx, double fy, double moment, double scale) {
  EXPECT_NEAR(load.fx, fx, 1e-11 * scale);
  EXPECT_NEAR(load.fy, fy, 1e-11 * scale);
  EXPECT_NEAR(load.moment, moment, 1e-11 * scale * kLoadsB);
}

TEST(ReservoirLoads, AtRestTheyAreTheClosedForms) {
  const ReservoirLoads loads(wet_rectangle(UpliftRule::unchanged));
  EXPECT_TRUE(loads.wets());
  BlockState rest;
  rest.y = kLoadsB;
  for (const double slide : {0.0, 3.5}) {  // sliding moves nothing relative to the water
    rest.x = slide;
    const ReservoirLoadSet at = loads.at(rest, CrackOpening::closed());
    const double push = 0.5 * kLoadsRho * kLoadsG * kLoadsDepth * kLoadsDepth;
    const Vertex centre{slide, 0.0};
    expect_load(at.hydrostatic, push, 0.0,
                moment_of({slide - kLoadsA, -kLoadsB + kLoadsDepth / 3}, centre, push, 0.0), push);
    const double uplift = 0.5 * kLoadsArea * kLoadsRho * kLoadsG * kLoadsDepth * kLoadsBase;
    expect_load(at.uplift, 0.0, uplift,
                moment_of({slide - kLoadsA + kLoadsBase / 3, -kLoadsB}, centre, 0.0, uplift),
                uplift);
    const double added =
        7.0 / 12.0 * kLoadsRho * std::sqrt(kLoadsPool) * std::pow(kLoadsDepth, 1.5);
    EXPECT_NEAR(at.added_mass.mass, added, 1e-12 * added);
    // About the centre of mass, 0.4 d above the base is 0.4 d - b.
    EXPECT_NEAR(at.added_mass.first_moment, added * (0.4 * kLoadsDepth - kLoadsB), 1e-9 * added);
  }
}

// The pose's tilted upstream face and each rule's crack, against the hand integrals.
void expect_tilted_loads(UpliftRule rule, const BlockState& s, CrackOpening open) {
  const ReservoirLoads loads(wet_rectangle(rule));
  const ReservoirLoadSet at = loads.at(s, open);
  const double theta = s.theta;
  const Vertex centre{s.x, s.y - kLoadsB};
  const Vertex heel = turned({-kLoadsA, -kLoadsB}, centre, theta);
  const double depth = kLoadsLevel - heel[1];  // D, at the heel
  const double wetted = depth / std::cos(theta);
  const double push = 0.5 * kLoadsRho * kLoadsG * depth * wetted;
  // Against the face, whose outward normal is the turned (-1, 0), at L/3 up from the heel.
  const double fx = push * std::cos(theta), fy = push * std::sin(theta);
  const Vertex push_point = turned({-kLoadsA, -kLoadsB + wetted / 3}, centre, theta);
  const double scale = push;
  expect_load(at.hydrostatic, fx, fy, moment_of(push_point, centre, fx, fy), scale);
  // The base's inward normal is the turned (0, 1).
  const double nx = -std::sin(theta), ny = std::cos(theta);
  switch (rule) {
    case UpliftRule::unchanged: {
      const double u = 0.5 * kLoadsArea * kLoadsRho * kLoadsG * kLoadsDepth * kLoadsBase;
      const Vertex point = turned({-kLoadsA + kLoadsBase / 3, -kLoadsB}, centre, theta);
      expect_load(at.uplift, u * nx, u * ny, moment_of(point, centre, u * nx, u * ny), scale);
      break;
    }
    case UpliftRule::zero_in_gap: expect_load(at.uplift, 0.0, 0.0, 0.0, scale); break;
    case UpliftRule::full_head_in_gap: {
      const double u = kLoadsRho * kLoadsG * depth * kLoadsBase;
      const Vertex point = turned({0.0, -kLoadsB}, centre, theta);
      expect_load(at.uplift, u * nx, u * ny, moment_of(point, centre, u * nx, u * ny), scale);
      break;
    }
    case UpliftRule::none: expect_load(at.uplift, 0.0, 0.0, 0.0, scale); break;
  }
}

TEST(ReservoirLoads, RockingAboutTheToeLiftsTheHeelOutOfTheWater) {
  for (const UpliftRule rule : {UpliftRule::none, UpliftRule::unchanged, UpliftRule::zero_in_gap,
                                UpliftRule::full_head_in_gap}) {
    expect_tilted_loads(rule, turned_about(kLoadsA, -0.05, 0.0), CrackOpening::whole());
  }
}

TEST(ReservoirLoads, RockingAboutTheHeelKeepsItsHead) {
  for (const UpliftRule rule : {UpliftRule::none, UpliftRule::unchanged, UpliftRule::zero_in_gap,
                                UpliftRule::full_head_in_gap}) {
    expect_tilted_loads(rule, turned_about(-kLoadsA, 0.03, 0.0), CrackOpening::whole());
  }
}

TEST(ReservoirLoads, InFlightTheWholeCrackIsOpen) {
  for (const UpliftRule rule : {UpliftRule::none, UpliftRule::unchanged, UpliftRule::zero_in_gap,
                                UpliftRule::full_head_in_gap}) {
    expect_tilted_loads(rule, turned_about(kLoadsA, -0.02, 0.4), CrackOpening::whole());
  }
}

TEST(ReservoirLoads, NoWaterBelowTheBlock) {
  Scene scene = wet_rectangle(UpliftRule::full_head_in_gap);
  scene.reservoir->level = -kLoadsB;
  const ReservoirLoads loads(scene);
  EXPECT_FALSE(loads.wets());
  const ReservoirLoadSet at = loads.at(turned_about(kLoadsA, -0.05, 0.0), CrackOpening::whole());
  EXPECT_EQ(at.hydrostatic.fx, 0.0);
  EXPECT_EQ(at.uplift.fy, 0.0);
  EXPECT_EQ(at.uplift.moment, 0.0);
  EXPECT_EQ(at.added_mass.mass, 0.0);
}

// The paper's type B block on its seat (configs/dam_block_type_b.json), the water at its crest
// (h = 21.7 m at the heel): its crack runs from the heel along the base (L1 = 5.858 m) and up the
// incline (slope (0.8, 0.6), 8.333 m), S = L1 + 8.333 m. With p(s) = rho g h (1 - s / S), the base
// takes rho g h (L1 - L1^2 / (2 S)) up, the incline rho g h (S - L1)^2 / (2 S) along (-0.6, 0.8).
TEST(ReservoirLoads, TypeBBlocksFoldedCrackPushesItUpstream) {
  const double fold = 5.858333333333333;
  Scene scene;
  scene.polygon = PolygonBlock{
      {{0, 0}, {fold, 0}, {12.525, 5}, {10, 8.366666666666667}, {10, 21.7}, {0, 21.7}}, 521301};
  scene.seat = Seat{{{0, 0}, {fold, 0}, {12.525, 5}}};
  scene.reservoir =
      Reservoir{21.7, 100.0, kLoadsRho, Hydrodynamic::none, UpliftRule::unchanged, 1.0};
  validate_scene(scene);
  const ReservoirLoads loads(scene);
  ASSERT_EQ(loads.crack().points.size(), 3u);
  ASSERT_EQ(loads.crack().edges.size(), 2u);
  BlockState rest;
  const Vertex centre = BlockOutline(scene).rest_centre();
  rest.x = centre[0];
  rest.y = centre[1];
  const ReservoirLoadSet at = loads.at(rest, CrackOpening::closed());
  const double p = kLoadsRho * kLoadsG * 21.7;
  const double incline = std::hypot(12.525 - fold, 5.0), total = fold + incline;
  const double on_base = p * (fold - fold * fold / (2 * total));
  const double on_incline = p * incline * incline / (2 * total);
  EXPECT_NEAR(incline, 8.333333333333334, 1e-12);
  EXPECT_NEAR(at.uplift.fx, -0.6 * on_incline, 1e-9 * p);
  EXPECT_NEAR(at.uplift.fy, on_base + 0.8 * on_incline, 1e-9 * p);
  EXPECT_EQ(at.added_mass.mass, 0.0);  // "hydrodynamic": "none"
  // The upstream face is wetted to the heel, the whole 21.7 m.
  EXPECT_NEAR(at.hydrostatic.fx, 0.5 * p * 21.7, 1e-9 * p);
}

}  // namespace
}  // namespace blockfrag
