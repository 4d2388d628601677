// How deep the block is in its seat at the pose its guards were last found at
// (SeatSystem::penetration): the watched seat points' clearances found there say which are inside
// and how deep, and the depth is the one found anew from the pose (each point's pass over the
// block's edges), to the bit, with all, some or none of the points' guards asked for, at poses of
// the type B block in its notch with its seat points inside it and outside.
#include <array>
#include <vector>

#include <gtest/gtest.h>

#include "engine/seat/seat_system.hpp"
#include "tests/support/fixed_uniforms.hpp"
#include "tests/support/same_bits.hpp"
#include "tests/support/type_b_seat_system.hpp"

namespace blockfrag {
namespace {

using testing::FixedUniforms;
using testing::kEveryGuard;
using testing::same_bits;
using testing::TypeBSeat;

TEST(SeatPointPenetration, IsTheDepthFoundAnewWithAllSomeOrNoPointsKnown) {
  const TypeBSeat seat;
  const SeatContacts& c = seat.contacts;
  SeatSystem system = seat.system({}, {0, 1, 2, 3, 4, 5}, {0, 1, 2});
  const auto first_point = static_cast<std::size_t>(kFirstClearanceGuard) + 6;
  GuardClaims none = kEveryGuard, first_only = kEveryGuard;
  for (std::size_t g = first_point; g < first_point + 3; ++g) {
    none[g] = false;
    first_only[g] = g == first_point;
  }
  FixedUniforms u(53);
  const Vec2 rest = c.rest_centre();
  int points_inside = 0, deep = 0;
  for (int n = 0; n < 3000; ++n) {
    const BlockState s{rest.x + u(-0.3, 0.3), rest.y + u(-0.3, 0.3), u(-0.08, 0.08), 0.0, 0.0, 0.0};
    const std::array<const GuardClaims*, 3> asked = {&kEveryGuard, &first_only, &none};
    system.guards(0.0, s, *asked[static_cast<std::size_t>(n % 3)]);
    const double anew = c.penetration(s);
    EXPECT_TRUE(same_bits(system.penetration(s), anew)) << n << " " << s.x << " " << s.theta;
    for (int k = 0; k < 3; ++k) points_inside += c.point_clearance(k, s) < 0;
    deep += anew > 0;
  }
  // Points inside, whose depth counts, and poses clear of the seat.
  EXPECT_GT(points_inside, 1000);
  EXPECT_GT(deep, 1000);
  EXPECT_LT(deep, 3000);
}

}  // namespace
}  // namespace blockfrag
