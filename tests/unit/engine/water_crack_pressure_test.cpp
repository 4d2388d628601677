// The water in a crack under each uplift rule (engine/water/crack_pressure.hpp) against hand
// integrals on a straight crack of length B from its mouth at x = 0, head h at the mouth, unit
// weight rho_w g and effective area c:
//   closed (rest, sliding): p(s) = c rho g h (1 - s/B): U = 1/2 c rho g h B at B/3, every rule
//     but "none";
//   opened whole (rocking about either end of the base, flight): "unchanged" the same,
//     "zero_in_gap" nothing, "full_head_in_gap" rho g h B at B/2 (the gap on the whole area);
//   opened over [0, 0.4 B] from the mouth: "zero_in_gap" keeps p(s) on [0.4 B, B]:
//     U = c rho g h B (1/2 - (0.4 - 0.08)) = 0.18 c rho g h B at 0.6 B; "full_head_in_gap" puts
//     rho g h on the gap and c rho g h falling linearly to zero on the rest (USACE's partial
//     crack): U = rho g h 0.4 B + 1/2 c rho g h 0.6 B;
//   opened over [0.5 B, B] from the end: "full_head_in_gap" rho g h there and p(s) before it;
//   a seated block's crack opened over l = 0.3 B from a lifting heel (CrackOpening::from_side),
//     "zero_in_gap": p(s) on [l, B], U = c rho g h (B - l)^2 / (2 B) = 0.245 c rho g h B at
//     l + (B - l) / 3 = 0.5333 B, its moment about the toe c rho g h (B - l)^3 / (3 B)
//     = 0.114333 c rho g h B^2; from a lifting toe, p(s) on [0, B - l]:
//     U = c rho g h (B - l) (1 + l / B) / 2 = 0.455 c rho g h B, its moment about the mouth
//     c rho g h ((B - l)^2 / 2 - (B - l)^3 / (3 B)) = 0.130667 c rho g h B^2.
// A folded crack's pieces press along each piece's normal.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "engine/errors.hpp"
#include "engine/water/crack_pressure.hpp"

namespace blockfrag {
namespace {

constexpr double kCrackB = 12.0, kCrackHead = 9.0, kCrackArea = 0.85;
constexpr double kCrackUnitWeight = 1000.0 * 9.81;

// The crack along the base of a block, its mouth at the origin: the pressure pushes up.
const std::vector<Vertex> kStraightCrack{{0.0, 0.0}, {kCrackB / 2, 0.0}, {kCrackB, 0.0}};

struct Resultant {
  double force, point;  // upward force and where it acts (x)
};

Resultant straight_resultant(UpliftRule rule, CrackOpening open) {
  const CrackPressure pressure =
      crack_pressure(rule, kCrackB, kCrackArea * kCrackUnitWeight * kCrackHead,
                     kCrackUnitWeight * kCrackHead, open);
  const WaterLoad load = crack_pressure_load(kStraightCrack, pressure, {0.0, 0.0});
  EXPECT_EQ(load.fx, 0.0);
  return {load.fy, load.fy == 0.0 ? 0.0 : load.moment / load.fy};
}

void expect_resultant(UpliftRule rule, CrackOpening open, double force, double point) {
  const Resultant r = straight_resultant(rule, open);
  EXPECT_NEAR(r.force, force, 1e-12 * kCrackUnitWeight * kCrackHead * kCrackB)
      << static_cast<int>(rule) << " [" << open.from << ", " << open.to << "]";
  if (force != 0.0) {
    EXPECT_NEAR(r.point, point, 1e-12 * kCrackB);
  }
}

TEST(CrackPressure, ClosedCrackTakesTheStaticUpliftUnderEveryRuleButNone) {
  const double u = 0.5 * kCrackArea * kCrackUnitWeight * kCrackHead * kCrackB;
  for (const UpliftRule rule :
       {UpliftRule::unchanged, UpliftRule::zero_in_gap, UpliftRule::full_head_in_gap}) {
    expect_resultant(rule, CrackOpening::closed(), u, kCrackB / 3);
  }
  expect_resultant(UpliftRule::none, CrackOpening::closed(), 0.0, 0.0);
}

TEST(CrackPressure, WholeOpeningKeepsZeroesOrFillsTheCrack) {
  const double still = 0.5 * kCrackArea * kCrackUnitWeight * kCrackHead * kCrackB;
  expect_resultant(UpliftRule::unchanged, CrackOpening::whole(), still, kCrackB / 3);
  expect_resultant(UpliftRule::zero_in_gap, CrackOpening::whole(), 0.0, 0.0);
  expect_resultant(UpliftRule::full_head_in_gap, CrackOpening::whole(),
                   kCrackUnitWeight * kCrackHead * kCrackB, kCrackB / 2);
  expect_resultant(UpliftRule::none, CrackOpening::whole(), 0.0, 0.0);
}

TEST(CrackPressure, OpeningFromTheMouthFollowsEachRule) {
  const CrackOpening open{0.0, 0.4};
  const double p = kCrackUnitWeight * kCrackHead;
  expect_resultant(UpliftRule::zero_in_gap, open, 0.18 * kCrackArea * p * kCrackB, 0.6 * kCrackB);
  // The gap's rho g h on [0, 0.4 B] at 0.2 B; c rho g h falling to zero on [0.4 B, B], a
  // triangle at 0.4 B + 0.6 B / 3 = 0.6 B.
  const double gap = p * 0.4 * kCrackB, rest = 0.5 * kCrackArea * p * 0.6 * kCrackB;
  expect_resultant(UpliftRule::full_head_in_gap, open, gap + rest,
                   (gap * 0.2 * kCrackB + rest * 0.6 * kCrackB) / (gap + rest));
}

TEST(CrackPressure, OpeningFromTheEndFillsOnlyTheGap) {
  const CrackOpening open{0.5, 1.0};
  const double p = kCrackUnitWeight * kCrackHead;
  // p(s) on [0, B/2]: a trapezoid from c p to c p / 2, 3/8 c p B at (B/2) (c p + 2 c p/2) /
  // (3 (c p + c p/2)) = 2/9 B from the mouth; the gap p B/2 at 3/4 B.
  const double closed = 0.375 * kCrackArea * p * kCrackB, gap = 0.5 * p * kCrackB;
  expect_resultant(UpliftRule::full_head_in_gap, open, closed + gap,
                   (closed * 2.0 / 9.0 * kCrackB + gap * 0.75 * kCrackB) / (closed + gap));
  expect_resultant(UpliftRule::zero_in_gap, open, closed, 2.0 / 9.0 * kCrackB);
}

// A crack folded at its middle, its second half rising at slope (0.8, 0.6): the closed pressure
// falls linearly with the length along it, and the second half presses along (-0.6, 0.8).
TEST(CrackPressure, FoldedCrackPressesAlongEachPiecesNormal) {
  const double half = 5.0, length = 2 * half;
  const std::vector<Vertex> folded{{0.0, 0.0}, {half, 0.0}, {half + 0.8 * half, 0.6 * half}};
  const double p0 = kCrackUnitWeight * kCrackHead;
  const CrackPressure pressure =
      crack_pressure(UpliftRule::unchanged, length, p0, p0, CrackOpening::closed());
  const WaterLoad load = crack_pressure_load(folded, pressure, {0.0, 0.0});
  const double first = 0.75 * p0 * half, second = 0.25 * p0 * half;  // p0 .. p0/2, p0/2 .. 0
  EXPECT_NEAR(load.fx, -0.6 * second, 1e-9 * p0);
  EXPECT_NEAR(load.fy, first + 0.8 * second, 1e-9 * p0);
}

TEST(CrackPressure, RefusesAnOpeningOutsideTheCrackOrBackwards) {
  for (const CrackOpening open :
       {CrackOpening{-0.1, 0.5}, CrackOpening{0.2, 1.5}, CrackOpening{0.6, 0.4}}) {
    EXPECT_THROW(crack_pressure(UpliftRule::zero_in_gap, 1.0, 1.0, 1.0, open), ContractViolation);
  }
}

TEST(CrackPressure, ASeatedCrackOpenedFromItsLiftingSideKeepsTheLinearHeadOnTheClosedRest) {
  const double p0 = kCrackArea * kCrackUnitWeight * kCrackHead;
  const Resultant heel = straight_resultant(UpliftRule::zero_in_gap,
                                            CrackOpening::from_side(LiftingSide::upstream, 0.3));
  EXPECT_NEAR(heel.force, 0.245 * p0 * kCrackB, 1e-12 * p0 * kCrackB);
  EXPECT_NEAR(heel.force * (kCrackB - heel.point), 0.343 / 3.0 * p0 * kCrackB * kCrackB,
              1e-12 * p0 * kCrackB * kCrackB);
  const Resultant toe = straight_resultant(UpliftRule::zero_in_gap,
                                           CrackOpening::from_side(LiftingSide::downstream, 0.3));
  EXPECT_NEAR(toe.force, 0.455 * p0 * kCrackB, 1e-12 * p0 * kCrackB);
  EXPECT_NEAR(toe.force * toe.point, (0.245 - 0.343 / 3.0) * p0 * kCrackB * kCrackB,
              1e-12 * p0 * kCrackB * kCrackB);
  // Not opened: the closed crack's uplift, from either side.
  for (const LiftingSide side : {LiftingSide::upstream, LiftingSide::downstream}) {
    const Resultant closed =
        straight_resultant(UpliftRule::zero_in_gap, CrackOpening::from_side(side, 0.0));
    EXPECT_NEAR(closed.force, 0.5 * p0 * kCrackB, 1e-12 * p0 * kCrackB);
  }
}

}  // namespace
}  // namespace blockfrag
