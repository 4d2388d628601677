// The rules by which both grounds' contacts rest and settle. A corner leaving the ground at the
// settling speed rises v^2 / (2 g_v), within the contact height but not far below it (the rule ends
// only bounces no event could tell from touching); it scales as sqrt(g_v R), and nothing settles in
// free fall. The resting speed lies far below it. A landing is plastic exactly where its rebound
// would be slower than the settling speed.
#include <cmath>

#include <gtest/gtest.h>

#include "engine/contact/settling.hpp"
#include "engine/tolerances.hpp"

namespace blockfrag {
namespace {

TEST(SettlingSpeed, ARiseAtItIsWithinTheContactHeightAndNotFarBelow) {
  for (const double g : {1.62, 9.81, 981.0}) {
    for (const double size : {1e-3, 1.118, 12.0}) {
      const double v = settling_speed(g, size);
      const double rise = v * v / (2.0 * g);
      EXPECT_LE(rise, kContactHeight * size) << "g " << g << ", R " << size;
      EXPECT_GE(rise, 0.99 * kContactHeight * size) << "g " << g << ", R " << size;
    }
  }
}

TEST(SettlingSpeed, ScalesAsTheSquareRootOfFeltGravityTimesSize) {
  const double base = settling_speed(9.81, 2.0);
  EXPECT_NEAR(settling_speed(4.0 * 9.81, 2.0), 2.0 * base, 1e-15 * base);
  EXPECT_NEAR(settling_speed(9.81, 18.0), 3.0 * base, 1e-15 * base);
}

TEST(SettlingSpeed, NothingSettlesWhereTheGroundFallsAtGOrFaster) {
  EXPECT_EQ(settling_speed(0.0, 1.0), 0.0);
  EXPECT_EQ(settling_speed(-3.0, 1.0), 0.0);
}

TEST(RestingSpeed, LiesFarBelowTheSettlingSpeedAndScalesAsTheSquareRootOfGTimesSize) {
  const double g = 9.81, size = 2.0;
  EXPECT_DOUBLE_EQ(resting_speed(g, size), kRestingVelocity * std::sqrt(g * size));
  EXPECT_LT(resting_speed(g, size), 1e-4 * settling_speed(g, size));
  EXPECT_NEAR(resting_speed(g, 4.0 * size), 2.0 * resting_speed(g, size),
              1e-15 * resting_speed(g, size));
}

TEST(PlasticLanding, ALandingIsPlasticWhereItsReboundWouldBeSlowerThanTheSettlingSpeed) {
  const double settle = settling_speed(9.81, 1.0);
  const double e = 0.5;
  // A rebound at e |u_n| just below and just above the settling speed.
  const double slow = -0.999 * settle / e, fast = -1.001 * settle / e;
  EXPECT_TRUE(lands_plastically(e, slow, settle));
  EXPECT_FALSE(lands_plastically(e, fast, settle));
  EXPECT_EQ(landing_restitution(e, slow, settle), 0.0);
  EXPECT_EQ(landing_restitution(e, fast, settle), e);
  // A fast landing keeps its restitution; in free fall (no settling speed) every landing does.
  EXPECT_EQ(landing_restitution(e, -1.0, settle), e);
  EXPECT_EQ(landing_restitution(e, slow, 0.0), e);
}

}  // namespace
}  // namespace blockfrag
