// The uplift in a crack (engine/water/uplift.hpp) against its closed form: the head h = y_w - y_c
// at the mouth falling linearly to zero at the crack's end, p(x) = c rho g h (1 - (x - x_u) / B),
// gives U = 1/2 c rho g h B upward at B/3 from the mouth (USACE EM 1110-2-2200, 1995, and FERC's
// guidelines chapter III: full head at the upstream end of a crack through the section, linear
// to zero at its downstream end without drains); its moment about any point is that force at
// that arm; no head, no uplift.
#include <gtest/gtest.h>

#include "engine/errors.hpp"
#include "engine/water/uplift.hpp"
#include "tests/support/paper_block.hpp"
#include "tests/support/water_outlines.hpp"

namespace blockfrag {
namespace {

using testing::kGravity;
using testing::kWaterDensity;

TEST(CrackUplift, FullCrackTakesHalfRhoGHBAtAThirdFromTheMouth) {
  const Crack crack{2.0, 14.0, 1.0};  // B = 12 m at y = 1 m
  const double head = 7.5, length = 12.0;
  for (const double factor : {1.0, 0.85}) {
    for (const Vertex& reference : {Vertex{6.0, 5.0}, Vertex{-3.0, 0.0}}) {
      const UpliftLoad uplift =
          crack_uplift(crack, {crack.y + head, kWaterDensity, kGravity}, factor, reference);
      const double expected = 0.5 * factor * kWaterDensity * kGravity * head * length;
      EXPECT_NEAR(uplift.force, expected, 1e-12 * expected);
      EXPECT_DOUBLE_EQ(uplift.point_x, 2.0 + length / 3);
      // Upward at x: a counter-clockwise moment (x - c_x) U about c.
      EXPECT_NEAR(uplift.moment, (2.0 + length / 3 - reference[0]) * expected, 1e-9 * expected);
    }
  }
}

TEST(CrackUplift, NoHeadIsExactlyZero) {
  const Crack crack{0.0, 10.0, 3.0};
  for (const double surface : {3.0, 1.0}) {
    const UpliftLoad uplift =
        crack_uplift(crack, {surface, kWaterDensity, kGravity}, 1.0, {5.0, 8.0});
    EXPECT_EQ(uplift.force, 0.0);
    EXPECT_EQ(uplift.moment, 0.0);
  }
}

TEST(CrackUplift, RefusesABackwardCrackOrAFactorOutsideZeroToOne) {
  const StillWater water{10.0, kWaterDensity, kGravity};
  EXPECT_THROW(crack_uplift({5.0, 5.0, 0.0}, water, 1.0, {0, 0}), ContractViolation);
  EXPECT_THROW(crack_uplift({0.0, 5.0, 0.0}, water, 1.5, {0, 0}), ContractViolation);
  EXPECT_THROW(crack_uplift({0.0, 5.0, 0.0}, water, -0.1, {0, 0}), ContractViolation);
}

}  // namespace
}  // namespace blockfrag
