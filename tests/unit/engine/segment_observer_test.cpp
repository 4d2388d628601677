// The summary's extremes as the observer records them: the deepest corner below the ground.
#include "engine/segment_observer.hpp"

#include <cmath>

#include <gtest/gtest.h>

namespace blockfrag {
namespace {

TEST(SegmentObserver, PenetrationIsTheDeepestCornerBelowTheGroundOverR) {
  BlockGeometry block(RectangularBlock{0.5, 1.0, 1.0});
  Summary summary;
  SegmentObserver observer(summary, block, 0.0, 9.81);
  BlockState resting;
  resting.y = 1.0;
  observer.start(resting);
  EXPECT_EQ(summary.max_penetration, 0.0);

  // Tilted by 0.1 rad about its centre, 0.9 m up: the lower base corner is at
  // 0.9 - 0.5 sin 0.1 - cos 0.1, under the ground.
  BlockState sunk;
  sunk.y = 0.9;
  sunk.theta = 0.1;
  observer.observe_state(sunk);
  const double depth = -(0.9 - 0.5 * std::sin(0.1) - std::cos(0.1));
  EXPECT_NEAR(summary.max_penetration, depth / std::hypot(0.5, 1.0), 1e-15);

  observer.observe_state(resting);  // the deepest stays
  EXPECT_NEAR(summary.max_penetration, depth / std::hypot(0.5, 1.0), 1e-15);
}

// A ground that measures its own depth (a seat) leaves the flat ground's alone: the extremes of
// the pose are still recorded.
TEST(SegmentObserver, LeavesTheDepthToTheGroundWhenAsked) {
  BlockGeometry block(RectangularBlock{0.5, 1.0, 1.0});
  Summary summary;
  SegmentObserver observer(summary, block, 0.0, 9.81);
  observer.leave_depth_to_ground();
  BlockState sunk;
  sunk.y = 0.9;
  sunk.theta = 0.1;
  sunk.x = 0.25;
  observer.start(BlockState{});
  observer.observe_state(sunk);
  EXPECT_EQ(summary.max_penetration, 0.0);
  EXPECT_EQ(summary.max_abs_theta, 0.1);
  EXPECT_EQ(summary.max_abs_slide, 0.25);
}

}  // namespace
}  // namespace blockfrag
