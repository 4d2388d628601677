// The block at rest under its reservoir (engine/water/block_statics.hpp) against hand
// computations. A dry block: it slides at mu g either way and rocks at the tip thresholds
// (x_P - x_G) / (y_G - y_P) about its outermost supports (a/b for a rectangle); on the type B
// block's folded seat it slides downstream only up the incline, at tan(beta + phi) g
// (tan beta = 0.75, tan phi = mu). A wet rectangle (B = 10 m, h = 16 m, d = 12 m of water,
// c = 0.85, H = 100 m): with W the weight, P = 1/2 rho g d^2 the push at d/3, U = 1/2 c rho g d B
// the uplift at B/3 from the heel and Westergaard's M_a (7/12 rho sqrt(H) d^(3/2)) and S_base
// (7/30 rho sqrt(H) d^(5/2), about the base),
//   slide downstream (mu (W - U) - P) / ((M + M_a) g), upstream (mu (W - U) + P) / ((M + M_a) g),
//   rock downstream (W B/2 - P d/3 - U 2B/3) / ((M h_G + S_base) g),
//   rock upstream (W B/2 + P d/3 - U B/3) / ((M h_G + S_base) g),
// and at seismic coefficient K the factors of USACE EM 1110-2-2100 and FERC chapter III,
//   sliding mu (W - U) / (P + K W + K g M_a),
//   overturning W B/2 / (P d/3 + U 2B/3 + K W h_G + K g S_base);
// after the earthquake the same at K = 0 with c = 1. A face leaning upstream adds the weight V of
// the water above it to the base's push and its moment to the resisting ones.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "engine/scene/block_geometry.hpp"
#include "engine/scene/polygon_properties.hpp"
#include "engine/scene/scene_validation.hpp"
#include "engine/water/block_outline.hpp"
#include "engine/water/block_statics.hpp"

namespace blockfrag {
namespace {

constexpr double kStaticsG = 9.81, kStaticsRho = 1000.0, kStaticsPool = 100.0;
constexpr double kStaticsMu = 0.7, kStaticsArea = 0.85;
constexpr double kStaticsHalfWidth = 5.0, kStaticsHalfHeight = 8.0, kStaticsLevel = 4.0;

Scene statics_rectangle(bool wet, Hydrodynamic hydrodynamic = Hydrodynamic::westergaard) {
  Scene scene;
  scene.block = {kStaticsHalfWidth, kStaticsHalfHeight,
                 2400.0 * 4 * kStaticsHalfWidth * kStaticsHalfHeight};
  scene.contact.friction = kStaticsMu;
  if (wet) {
    scene.reservoir = Reservoir{kStaticsLevel, kStaticsPool,          kStaticsRho,
                                hydrodynamic,  UpliftRule::unchanged, kStaticsArea};
  }
  validate_scene(scene);
  return scene;
}

// The wet rectangle's hand values.
struct WetRectangle {
  double m = 2400.0 * 4 * kStaticsHalfWidth * kStaticsHalfHeight;
  double w = m * kStaticsG;
  double base = 2 * kStaticsHalfWidth, h_g = kStaticsHalfHeight;
  double d = kStaticsLevel + kStaticsHalfHeight;
  double push = 0.5 * kStaticsRho * kStaticsG * d * d;
  double uplift(double c) const { return 0.5 * c * kStaticsRho * kStaticsG * d * base; }
  double added = 7.0 / 12.0 * kStaticsRho * std::sqrt(kStaticsPool) * std::pow(d, 1.5);
  double s_base = 7.0 / 30.0 * kStaticsRho * std::sqrt(kStaticsPool) * std::pow(d, 2.5);
};

TEST(BlockStatics, DryRectangleSlidesAtMuAndRocksAtItsTipThreshold) {
  const BlockStatics statics = block_statics(statics_rectangle(false));
  EXPECT_EQ(statics.hydrostatic_x, 0.0);
  EXPECT_EQ(statics.uplift_y, 0.0);
  EXPECT_EQ(statics.added_mass, 0.0);
  EXPECT_NEAR(statics.yield.slide_downstream, kStaticsMu, 1e-14);
  EXPECT_NEAR(statics.yield.slide_upstream, kStaticsMu, 1e-14);
  EXPECT_NEAR(statics.yield.rock_downstream, kStaticsHalfWidth / kStaticsHalfHeight, 1e-14);
  EXPECT_NEAR(statics.yield.rock_upstream, kStaticsHalfWidth / kStaticsHalfHeight, 1e-14);
  // Nothing drives a dry block at rest; K = 0.2 gives mu / K and the overturning ratio
  // (B/2) / (K h_G).
  const SafetyFactors rest = pseudo_static_safety_factors(statics_rectangle(false), 0.0);
  EXPECT_EQ(rest.sliding, std::numeric_limits<double>::infinity());
  EXPECT_EQ(rest.overturning, std::numeric_limits<double>::infinity());
  const SafetyFactors shaken = pseudo_static_safety_factors(statics_rectangle(false), 0.2);
  EXPECT_NEAR(shaken.sliding, kStaticsMu / 0.2, 1e-13);
  EXPECT_NEAR(shaken.overturning, kStaticsHalfWidth / (0.2 * kStaticsHalfHeight), 1e-13);
}

TEST(BlockStatics, WetRectangleMatchesTheHandComputation) {
  const WetRectangle hand;
  const BlockStatics statics = block_statics(statics_rectangle(true));
  const double u = hand.uplift(kStaticsArea);
  EXPECT_NEAR(statics.weight, hand.w, 1e-9);
  EXPECT_NEAR(statics.hydrostatic_x, hand.push, 1e-12 * hand.push);
  EXPECT_EQ(statics.hydrostatic_y, 0.0);
  EXPECT_NEAR(statics.uplift_y, u, 1e-12 * u);
  EXPECT_NEAR(statics.added_mass, hand.added, 1e-12 * hand.added);
  const double inertia = (hand.m + hand.added) * kStaticsG;
  const double tipping = (hand.m * hand.h_g + hand.s_base) * kStaticsG;
  EXPECT_NEAR(statics.yield.slide_downstream, (kStaticsMu * (hand.w - u) - hand.push) / inertia,
              1e-12);
  EXPECT_NEAR(statics.yield.slide_upstream, (kStaticsMu * (hand.w - u) + hand.push) / inertia,
              1e-12);
  const double d = hand.d, b = hand.base;
  EXPECT_NEAR(statics.yield.rock_downstream,
              (hand.w * b / 2 - hand.push * d / 3 - u * 2 * b / 3) / tipping, 1e-12);
  EXPECT_NEAR(statics.yield.rock_upstream,
              (hand.w * b / 2 + hand.push * d / 3 - u * b / 3) / tipping, 1e-12);
  for (const double k : {0.0, 0.1, 0.25}) {
    const SafetyFactors f = pseudo_static_safety_factors(statics_rectangle(true), k);
    EXPECT_NEAR(f.sliding,
                kStaticsMu * (hand.w - u) / (hand.push + k * hand.w + k * kStaticsG * hand.added),
                1e-12)
        << k;
    EXPECT_NEAR(f.overturning,
                hand.w * b / 2 /
                    (hand.push * d / 3 + u * 2 * b / 3 + k * hand.w * hand.h_g +
                     k * kStaticsG * hand.s_base),
                1e-12)
        << k;
  }
}

// Under "zero_in_gap" K W downstream opens the crack from the heel by a, as far as the heel needs:
// the uplift left on the closed part, p0 (B - a)^2 / (2B) at 2 (B - a) / 3 from the toe, balances
// the moments about the toe, (B - a)^3 = 3B / p0 (W B/2 - P d/3 - K (W h_G + g S_base)), so the
// block stands on its toe (overturning factor 1) and slides at mu (W - U(a)) / (P + K W + K g M_a).
// Below the closed crack's rocking yield the crack stays closed, as under "unchanged".
TEST(BlockStatics, ZeroInGapOpensTheCrackUnderTheSeismicCoefficient) {
  const WetRectangle hand;
  Scene scene = statics_rectangle(true);
  scene.reservoir->uplift = UpliftRule::zero_in_gap;
  const double b = hand.base, d = hand.d;
  const double p0 = kStaticsArea * kStaticsRho * kStaticsG * d;
  const double closed_yield = block_statics(statics_rectangle(true)).yield.rock_downstream;
  const double k = 0.34;
  ASSERT_GT(k, closed_yield);
  ASSERT_LT(k, block_statics(scene).yield.rock_downstream);
  const double resisting =
      hand.w * b / 2 - hand.push * d / 3 - k * (hand.w * hand.h_g + kStaticsG * hand.s_base);
  const double closed_length = std::cbrt(3 * b / p0 * resisting);
  const double uplift = p0 * closed_length * closed_length / (2 * b);
  const SafetyFactors opened = pseudo_static_safety_factors(scene, k);
  EXPECT_NEAR(opened.overturning, 1.0, 1e-12);
  EXPECT_NEAR(
      opened.sliding,
      kStaticsMu * (hand.w - uplift) / (hand.push + k * hand.w + k * kStaticsG * hand.added), 1e-9);
  for (const double below : {0.0, 0.1, closed_yield * (1 - 1e-9)}) {
    const SafetyFactors zero = pseudo_static_safety_factors(scene, below);
    const SafetyFactors unchanged = pseudo_static_safety_factors(statics_rectangle(true), below);
    EXPECT_EQ(zero.sliding, unchanged.sliding) << below;
    EXPECT_EQ(zero.overturning, unchanged.overturning) << below;
  }
}

// At each rule's yield accelerations downstream the pseudo-static factors are 1: the statics'
// yields and safety factors describe one block.
TEST(BlockStatics, FactorsAreOneAtTheYieldsUnderEveryUpliftRule) {
  for (const UpliftRule rule : {UpliftRule::none, UpliftRule::unchanged, UpliftRule::zero_in_gap,
                                UpliftRule::full_head_in_gap}) {
    Scene scene = statics_rectangle(true);
    scene.reservoir->uplift = rule;
    const YieldAccelerations yield = block_statics(scene).yield;
    EXPECT_NEAR(pseudo_static_safety_factors(scene, yield.rock_downstream).overturning, 1.0, 1e-12)
        << static_cast<int>(rule);
    if (yield.slide_downstream < yield.rock_downstream) {
      EXPECT_NEAR(pseudo_static_safety_factors(scene, yield.slide_downstream).sliding, 1.0, 1e-12)
          << static_cast<int>(rule);
    }
  }
}

TEST(BlockStatics, WithoutWestergaardTheWaterAddsNoInertia) {
  const WetRectangle hand;
  const BlockStatics statics = block_statics(statics_rectangle(true, Hydrodynamic::none));
  EXPECT_EQ(statics.added_mass, 0.0);
  const double u = hand.uplift(kStaticsArea);
  EXPECT_NEAR(statics.yield.slide_downstream,
              (kStaticsMu * (hand.w - u) - hand.push) / (hand.m * kStaticsG), 1e-12);
}

TEST(BlockStatics, PostEarthquakeTakesFullUpliftWhereverTheBlockSettled) {
  const WetRectangle hand;
  const Scene scene = statics_rectangle(true);
  const double u = hand.uplift(1.0);
  for (const double slide : {0.0, -2.5, 40.0}) {
    BlockState settled;
    settled.x = slide;
    settled.y = kStaticsHalfHeight;
    const SafetyFactors f = post_earthquake_safety_factors(scene, settled);
    EXPECT_NEAR(f.sliding, kStaticsMu * (hand.w - u) / hand.push, 1e-12) << slide;
    EXPECT_NEAR(f.overturning,
                hand.w * hand.base / 2 / (hand.push * hand.d / 3 + u * 2 * hand.base / 3), 1e-12)
        << slide;
  }
  // A check the summary leaves out for a block that does not stand at rest.
  BlockState settled;
  settled.y = kStaticsHalfHeight;
  EXPECT_FALSE(post_earthquake_check(scene, settled, false).sliding_safety_factor.has_value());
  EXPECT_TRUE(post_earthquake_check(scene, settled, true).overturning_safety_factor.has_value());
}

// The face leans back upstream, its foot 3 m upstream of its top: the water above it (a triangle
// of 1.8 m by 6 m, V = 5.4 rho g at x = -2.4) presses the block down and resists overturning about
// the toe (x = 5) with the arm 7.4 m; the push P = 1/2 rho g 6^2 acts 2 m above the base, the
// uplift 1/2 rho g 6 B over B = 8 m at B/3 from the heel.
TEST(BlockStatics, WaterOnALeaningFaceResists) {
  Scene scene;
  const double mass = 2400.0 * 65.0;
  scene.polygon = PolygonBlock{{{-3, 0}, {5, 0}, {5, 10}, {0, 10}}, mass};
  scene.contact.friction = kStaticsMu;
  scene.reservoir =
      Reservoir{6.0, kStaticsPool, kStaticsRho, Hydrodynamic::none, UpliftRule::unchanged, 1.0};
  validate_scene(scene);
  const double rho_g = kStaticsRho * kStaticsG, w = mass * kStaticsG;
  const double v = 5.4 * rho_g, push = 18.0 * rho_g, u = 0.5 * rho_g * 6.0 * 8.0;
  const BlockStatics statics = block_statics(scene);
  EXPECT_NEAR(statics.hydrostatic_y, -v, 1e-9 * v);
  const SafetyFactors f = pseudo_static_safety_factors(scene, 0.0);
  EXPECT_NEAR(f.sliding, kStaticsMu * (w - u + v) / push, 1e-12);
  // x_G of the trapezoid: (50 * 2.5 + 15 * (-1)) / 65.
  const double x_g = 110.0 / 65.0;
  EXPECT_NEAR(f.overturning, (w * (5 - x_g) + v * 7.4) / (push * 2 + u * (8 - 8.0 / 3)), 1e-12);
}

// The paper's type B block on its seat, dry: downstream it can only slide up the incline
// (slope 0.75) and upstream only along the base; it rocks about the incline's top (its toe) and
// its heel.
TEST(BlockStatics, TypeBBlockSlidesUpItsInclineAtTanBetaPlusPhi) {
  const double fold = 5.858333333333333;
  Scene scene;
  scene.polygon = PolygonBlock{
      {{0, 0}, {fold, 0}, {12.525, 5}, {10, 8.366666666666667}, {10, 21.7}, {0, 21.7}}, 521301};
  scene.seat = Seat{{{0, 0}, {fold, 0}, {12.525, 5}}};
  scene.contact.friction = 1.05;
  validate_scene(scene);
  const BlockStatics statics = block_statics(scene);
  EXPECT_NEAR(statics.yield.slide_downstream, std::tan(std::atan(0.75) + std::atan(1.05)), 1e-12);
  EXPECT_NEAR(statics.yield.slide_upstream, 1.05, 1e-14);
  const Vertex centre = BlockOutline(scene).rest_centre();
  EXPECT_NEAR(statics.yield.rock_downstream, (12.525 - centre[0]) / (centre[1] - 5.0), 1e-12);
  EXPECT_NEAR(statics.yield.rock_upstream, centre[0] / centre[1], 1e-12);
}

}  // namespace
}  // namespace blockfrag
