// A pivot's claims with the guards at the step's ends given (PivotSweep::claims with at0 and at1,
// the guard watch's): a watched seat point's guard's sign there says whether it is inside the
// block, and the claims are those that look at the block's edges at the step's lower tilt, to the
// bit, over random steps turning the type B block both ways about its heel and its toe (seat
// points inside the block and outside) and about a corner on a long flat seat (its ends far).
#include <cmath>
#include <cstddef>
#include <vector>

#include <gtest/gtest.h>

#include "engine/motion/ground_motion.hpp"
#include "engine/scene/block_geometry.hpp"
#include "engine/seat/seat_contacts.hpp"
#include "engine/seat/seat_system.hpp"
#include "tests/support/fixed_uniforms.hpp"
#include "tests/support/type_b_block.hpp"
#include "tests/support/type_b_seat_system.hpp"

namespace blockfrag {
namespace {

using testing::FixedUniforms;
using testing::kEveryGuard;
using testing::kTypeB;

struct SignedPivot {
  int vertex, segment;
  WatchedList vertices, points;
};

struct SignCounts {
  int claimed = 0, inside = 0;
};

// Random steps about `pivot`'s block vertex, at its seat point: the claims from the guards' signs
// are the claims from the block's edges.
SignCounts check_sign_claims(const testing::TypeBSeat& scene, const SignedPivot& pivot, Vec2 point,
                             FixedUniforms& u) {
  const SeatContacts& c = scene.contacts;
  SeatSystem system(
      scene.context,
      {{{ContactKind::block_vertex, pivot.vertex, pivot.segment}, ContactState::stick}},
      pivot.vertices, pivot.points);
  const PivotChart chart{point, c.body_vertex(pivot.vertex)};
  PivotSweep from_signs(system, chart), from_edges(system, chart);
  const auto first_point = static_cast<std::size_t>(kFirstClearanceGuard) + pivot.vertices.size();
  SignCounts counts;
  for (int n = 0; n < 2000; ++n) {
    const double theta0 = u(-0.05, 0.05);
    const double theta1 = theta0 + (n % 2 == 0 ? u(-1e-2, 1e-2) : u(-1e-5, 1e-5));
    const auto at0 = system.guards(0.0, chart.full(0.0, {theta0, 0.3}));
    const auto at1 = system.guards(0.0, chart.full(0.0, {theta1, 0.3}));
    const GuardClaims claims = from_signs.claims(theta0, theta1, kEveryGuard, at0, at1);
    EXPECT_EQ(claims, from_edges.claims(theta0, theta1, kEveryGuard)) << n << " " << theta0;
    const auto& at_lo = theta1 < theta0 ? at1 : at0;
    for (std::size_t g = first_point; g < first_point + pivot.points.size(); ++g) {
      counts.claimed += claims[g];
      counts.inside += std::signbit(at_lo[g]);
    }
  }
  return counts;
}

TEST(SeatPointSignClaims, AreTheEdgesClaimsOnTheNotchAndFarFromTheSeatsEnds) {
  FixedUniforms u(51);
  const testing::TypeBSeat notch({{0, 0}, {testing::kFoldX, 0}, {testing::kToeX, testing::kToeY}});
  const SignCounts heel =
      check_sign_claims(notch, {0, 0, {1, 2, 3, 4, 5}, {1, 2}}, notch.contacts.seat_point(0), u);
  const SignCounts toe =
      check_sign_claims(notch, {2, 1, {0, 1, 3, 4, 5}, {0, 1}}, notch.contacts.seat_point(2), u);
  // Both signs are met, and claims made either side of them.
  EXPECT_GT(heel.inside, 500);
  EXPECT_GT(toe.inside, 500);
  EXPECT_GT(heel.claimed, 1000);
  EXPECT_GT(toe.claimed, 1000);
  // A long flat seat's ends, 1e4 m away: their guards are a bound on their distance, positive.
  const testing::TypeBSeat flat({{-1e4, 0}, {1e4, 0}});
  const SignCounts corner = check_sign_claims(flat, {0, 0, {1, 2, 3, 4, 5}, {0, 1}}, {0.0, 0.0}, u);
  EXPECT_EQ(corner.inside, 0);
  EXPECT_GT(corner.claimed, 1000);
}

}  // namespace
}  // namespace blockfrag
