// A pivot's claims of its watched vertices from the range of tilts the last worked-out claim found
// them to hold over (PivotSweep's claimed ranges, on a one-segment seat the vertex stays over): a
// sweep asked about a rocking block's steps one after the other claims what a sweep asked about
// each step alone claims (which works every claim out), to the bit. The type B block turns both
// ways about its heel and its toe on a long flat seat, about the tilts where its other corners are
// lowest (so some steps hold a height's least value and are not claimed), and on a seat so short
// that its corners pass its ends (so no range is kept).
#include <cmath>
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

struct Counts {
  int claimed = 0, unclaimed = 0;
};

// Swings about block vertex `pivot` (at the seat's origin), watching the other vertices: the
// rocking sweep's claims against a fresh sweep's at every step.
Counts rock_about(const testing::TypeBSeat& seat, int pivot, FixedUniforms& u) {
  WatchedList watched;
  for (int i = 0; i < seat.contacts.vertex_count(); ++i) {
    if (i != pivot) watched.push_back(i);
  }
  const SeatSystem system(
      seat.context, {{{ContactKind::block_vertex, pivot, 0}, ContactState::stick}}, watched, {});
  const PivotChart chart{{0.0, 0.0}, seat.contacts.body_vertex(pivot)};
  PivotSweep rocking(system, chart);
  const auto first = static_cast<std::size_t>(kFirstClearanceGuard);
  Counts counts;
  for (int swing = 0; swing < 60; ++swing) {
    // Out and back, in steps of one size a swing, from near the tilt where a watched vertex is
    // lowest (its height c + a cos + b sin least, at atan2(-b, -a) with a = w.y and b = w.x).
    const Vec2 v =
        seat.contacts.body_vertex(watched[static_cast<std::size_t>(swing) % watched.size()]);
    const Vec2 w{v.x - chart.body.x, v.y - chart.body.y};
    const double step = u(1e-6, 2e-3) * (swing % 2 == 0 ? 1.0 : -1.0);
    double theta = std::atan2(-w.x, -w.y) + u(-0.05, 0.05);
    for (int n = 0; n < 100; ++n) {
      const double next = theta + step * (n < 50 ? 1.0 : -1.0) * u(0.5, 1.5);
      PivotSweep alone(system, chart);
      const GuardClaims claims = rocking.claims(theta, next, kEveryGuard);
      EXPECT_EQ(claims, alone.claims(theta, next, kEveryGuard))
          << "pivot " << pivot << " swing " << swing << " step " << n << " " << theta;
      if (claims != alone.claims(theta, next, kEveryGuard)) return counts;
      for (std::size_t g = first; g < first + watched.size(); ++g) {
        counts.claimed += claims[g];
        counts.unclaimed += !claims[g];
      }
      theta = next;
    }
  }
  return counts;
}

TEST(SeatVertexClaimedRange, ARockingSweepClaimsWhatEachStepAloneClaims) {
  const testing::TypeBSeat long_seat({{-1e4, 0.0}, {1e4, 0.0}});
  FixedUniforms u(53);
  for (const int pivot : {0, 2}) {
    const Counts counts = rock_about(long_seat, pivot, u);
    // Most steps are claimed, not all: a swing steps over a height's least value out and back.
    EXPECT_GT(counts.claimed, 20000) << pivot;
    EXPECT_GT(counts.unclaimed, 30) << pivot;
  }
}

TEST(SeatVertexClaimedRange, ASeatItsCornersPassClaimsWhatEachStepAloneClaims) {
  const testing::TypeBSeat short_seat({{-3.0, 0.0}, {5.0, 0.0}});
  FixedUniforms u(54);
  for (const int pivot : {0, 2}) {
    const Counts counts = rock_about(short_seat, pivot, u);
    EXPECT_GT(counts.claimed + counts.unclaimed, 20000) << pivot;
  }
}

}  // namespace
}  // namespace blockfrag
