// A block vertex on a seat point (the type B block's heel on the seat's upstream end) that slips
// off the seat: the corner's two pairs (the vertex on the seat's first segment, the seat's end
// point on the block's upstream face) must not take turns leaving their ends.
#include <gtest/gtest.h>

#include "engine/simulate.hpp"
#include "tests/support/type_b_block.hpp"

namespace blockfrag {
namespace {

// The randomized dam-block scene that failed on the event budget: the type B block, dry, turned
// about its heel on the seat's upstream end until its centre of mass is 11 m upstream of it, where
// the heel's friction reaches its limit and the heel slips upstream, off the seat.
Scene heel_slipping_off_the_seat(double duration) {
  Scene scene;
  scene.polygon = PolygonBlock{testing::kTypeB, 521301.0};
  scene.seat = Seat{testing::kTypeBSeat};
  scene.contact = {1.191383085497047, 0.15497948891468735};
  scene.ground_motion = SinePulse{-1.8205088204121125, 2.9330372085683694, 1.0};
  scene.duration = duration;
  scene.solver.method = Method::rk4;
  scene.solver.dt = 0.00025;
  // The swapping took a million events; a few thousand fail it at once.
  scene.solver.max_events = 10'000;
  return scene;
}

TEST(SeatCornerLeaves, HeelSlippingOffTheSeatsEndFliesOffInsteadOfSwappingItsPairs) {
  const Summary s = simulate(heel_slipping_off_the_seat(4.0));
  ASSERT_EQ(s.status, Status::ok) << s.status_reason;
  EXPECT_LT(s.events, 100);
  ASSERT_FALSE(s.modes.empty());
  // It rocks about the heel, the heel slips, and leaves the seat within a millisecond of slipping.
  const ModeChange last = s.modes.back();
  EXPECT_EQ(last.mode, ModeKind::flight);
  ASSERT_TRUE(s.slide_start_time.has_value());
  EXPECT_GT(last.time, *s.slide_start_time);
  EXPECT_LT(last.time, *s.slide_start_time + 1e-3);
  EXPECT_GT(s.final_theta, 1.5);
  EXPECT_LT(s.final_slide, -15.0);
}

TEST(SeatCornerLeaves, HeelSlippingOffTheSeatsEndFallsBesideTheSeat) {
  const Summary s = simulate(heel_slipping_off_the_seat(4.5));
  ASSERT_EQ(s.status, Status::ok) << s.status_reason;
  EXPECT_LT(s.events, 100);
  EXPECT_TRUE(s.fell);
  EXPECT_FALSE(s.overturned);
  ASSERT_TRUE(s.fell_time.has_value());
  EXPECT_GT(*s.fell_time, 4.0);
  EXPECT_TRUE(s.settled);
}

}  // namespace
}  // namespace blockfrag
