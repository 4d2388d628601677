// The settling speed both grounds' contact resolution use: a corner leaving the ground at it rises
// v^2 / (2 g_v), within the contact height but not far below it (the rule ends only bounces no
// event could tell from touching), it scales as sqrt(g_v R), and nothing settles in free fall.
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

}  // namespace
}  // namespace blockfrag
