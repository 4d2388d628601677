// A block leaving its seat past the seat's upstream end. A block vertex on a seat point (the type B
// block's heel on the seat's end) that slips off the seat: the corner's two pairs (the vertex on
// the seat's first segment, the seat's end point on the block's upstream face) must not take turns
// leaving their ends. A block falling upstream of the seat whose corner comes under the seat's end
// from beside it has gone down past that end: it has not touched the seat. A block whose base
// bounces off the seat's upstream corner, its heel just upstream of it, lands on that corner again.
#include <cmath>

#include <gtest/gtest.h>

#include "engine/simulate.hpp"
#include "tests/support/type_b_rk4_scene.hpp"

namespace blockfrag {
namespace {

// The randomized dam-block scene that failed on the event budget: the type B block, dry, turned
// about its heel on the seat's upstream end until its centre of mass is 11 m upstream of it, where
// the heel's friction reaches its limit and the heel slips upstream, off the seat.
Scene heel_slipping_off_the_seat(double duration) {
  // The swapping took a million events; a few thousand fail it at once.
  return testing::type_b_rk4_scene(1.191383085497047, 0.15497948891468735,
                                   SinePulse{-1.8205088204121125, 2.9330372085683694, 1.0},
                                   duration, 10'000);
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

// The randomized wet scene that failed on the event budget: the type B block under its reservoir
// (5 m below the crest, full head in the open crack) slides upstream off its seat, flies, and its
// downstream base corner swings under the seat's upstream end, 0.59 m below it.
Scene falling_upstream_under_the_reservoir() {
  Scene scene = testing::type_b_rk4_scene(0.8601308400138321, 0.35850795285028264,
                                          SinePulse{-1.6874201701881233, 2.821448446752989, 1.0},
                                          4.0, 10'000);
  scene.reservoir =
      Reservoir{16.781358466199976,           100.0, 1000.0, Hydrodynamic::westergaard,
                UpliftRule::full_head_in_gap, 1.0};
  return scene;
}

TEST(SeatCornerLeaves, CornerComingUnderTheSeatsEndFromBesideItFalls) {
  const Summary s = simulate(falling_upstream_under_the_reservoir());
  ASSERT_EQ(s.status, Status::ok) << s.status_reason;
  EXPECT_LT(s.events, 100);
  EXPECT_TRUE(s.fell);
  EXPECT_FALSE(s.overturned);
  EXPECT_TRUE(s.settled);
  ASSERT_TRUE(s.fell_time.has_value());
  ASSERT_FALSE(s.modes.empty());
  // In flight since it left the seat, upstream of it and turned upstream.
  EXPECT_EQ(s.modes.back().mode, ModeKind::flight);
  EXPECT_GT(*s.fell_time, s.modes.back().time);
  EXPECT_LT(s.final_slide, -10.0);
  EXPECT_GT(s.final_theta, 0.5);
}

// The randomized dry scene that failed on no progress: the type B block rocking about its fold
// lands its base on the seat's upstream corner, its heel 8e-5 m upstream of it, and bounces off it
// at e = 0.039. The bounce lands within a millisecond, far inside one sample spacing of the flight.
Scene base_bouncing_off_the_seats_corner() {
  return testing::type_b_rk4_scene(0.957, 0.039, SinePulse{-0.546, 2.01, 1.0}, 4.0, 10'000);
}

TEST(SeatCornerLeaves, BaseBouncingOffTheSeatsCornerLandsOnItAgainAndComesToRest) {
  const Summary s = simulate(base_bouncing_off_the_seats_corner());
  ASSERT_EQ(s.status, Status::ok) << s.status_reason;
  EXPECT_LT(s.events, 100);
  EXPECT_FALSE(s.fell);
  EXPECT_FALSE(s.overturned);
  // The corner never goes into the block: missed, the bounce's landing left it 5e-5 m inside.
  EXPECT_LT(s.max_penetration, 1e-12);
  // It rocks between the corner and the fold, and comes to rest on its seat within 0.2 s.
  EXPECT_TRUE(s.settled);
  ASSERT_TRUE(s.settle_time.has_value());
  EXPECT_GT(*s.settle_time, 1.3);
  EXPECT_LT(*s.settle_time, 1.5);
  EXPECT_LT(std::abs(s.final_theta), 1e-4);
  EXPECT_LT(std::abs(s.final_slide), 1e-3);
}

}  // namespace
}  // namespace blockfrag
