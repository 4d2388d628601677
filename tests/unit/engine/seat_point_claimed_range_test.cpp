// A pivot's claims of its watched seat points from the range of tilts the last worked-out claim
// found them to hold over (PivotSweep's claimed ranges): a sweep asked about a rocking block's
// steps one after the other claims what a sweep asked about each step alone claims (which works
// every claim out), to the bit, turning the type B block both ways about its heel, its toe and a
// point inside it, out from rest and back through it, with steps of many sizes.
#include <vector>

#include <gtest/gtest.h>

#include "engine/seat/seat_system.hpp"
#include "tests/support/fixed_uniforms.hpp"
#include "tests/support/type_b_seat_system.hpp"

namespace blockfrag {
namespace {

using testing::FixedUniforms;
using testing::kEveryGuard;
using testing::TypeBSeat;

struct RangePivot {
  ActiveContact contact;
  Vec2 point, body;
  WatchedList vertices, points;
  double spread;  // the swings start within this of rest
};

TEST(SeatPointClaimedRange, ARockingSweepClaimsWhatEachStepAloneClaims) {
  const TypeBSeat seat;
  const SeatContacts& c = seat.contacts;
  // About the heel, the toe, and the seat's fold 0.3 m inside the block (its base turning across
  // the heel's seat point 0.01 rad before the heel's corner passes it closest).
  const Vec2 inside{c.body_vertex(1).x - 1.0, c.body_vertex(1).y + 0.3};
  const std::vector<RangePivot> pivots = {{{{ContactKind::block_vertex, 0, 0}, ContactState::stick},
                                           c.seat_point(0),
                                           c.body_vertex(0),
                                           {1, 2, 3, 4, 5},
                                           {1, 2},
                                           0.02},
                                          {{{ContactKind::block_vertex, 2, 1}, ContactState::stick},
                                           c.seat_point(2),
                                           c.body_vertex(2),
                                           {0, 1, 3, 4, 5},
                                           {0, 1},
                                           0.02},
                                          {{{ContactKind::seat_point, 0, 1}, ContactState::stick},
                                           c.seat_point(1),
                                           inside,
                                           {0, 1, 2, 3, 4, 5},
                                           {0, 2},
                                           0.1}};
  FixedUniforms u(52);
  for (const RangePivot& p : pivots) {
    SeatSystem system = seat.system({p.contact}, p.vertices, p.points);
    const PivotChart chart{p.point, p.body};
    PivotSweep rocking(system, chart);
    const auto first_point = static_cast<std::size_t>(kFirstClearanceGuard) + p.vertices.size();
    int claimed = 0, unclaimed = 0;
    for (int swing = 0; swing < 40; ++swing) {
      // Out from near rest and back through it, in steps of one size a swing.
      const double step = u(1e-6, 2e-3) * (swing % 2 == 0 ? 1.0 : -1.0);
      double theta = u(-p.spread, p.spread);
      for (int n = 0; n < 100; ++n) {
        const double next = theta + step * (n < 50 ? 1.0 : -1.0) * u(0.5, 1.5);
        PivotSweep alone(system, chart);
        const GuardClaims claims = rocking.claims(theta, next, kEveryGuard);
        ASSERT_EQ(claims, alone.claims(theta, next, kEveryGuard))
            << "pivot " << p.body.x << " swing " << swing << " step " << n << " " << theta;
        for (std::size_t g = first_point; g < first_point + p.points.size(); ++g) {
          claimed += claims[g];
          unclaimed += !claims[g];
        }
        theta = next;
      }
    }
    // Most steps are claimed, not all: the ranges are met at their edges.
    EXPECT_GT(claimed, 4000) << p.body.x;
    EXPECT_GT(unclaimed, 100) << p.body.x;
  }
}

}  // namespace
}  // namespace blockfrag
