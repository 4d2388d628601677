// The "full_head_in_gap" uplift on a sliding block (engine/seat/seated_load.hpp): the friction at
// the base of the paper's type A dam block sliding downstream fast tips it onto its toe, lifting
// its heel under the closed crack's uplift; the full head in the crack that lifting opens lightens
// the block's push on the ground and that friction, and sets the heel back down. With the crack
// either closed or full, the block rattled between slide and slide-rock every 2.8 microseconds
// (215,908 events in a 4 s run); the crack opened from the heel as far as the heel needs keeps it
// sliding on its base.
#include <gtest/gtest.h>

#include "engine/simulate.hpp"
#include "tests/support/wet_dam_blocks.hpp"

namespace blockfrag {
namespace {

Scene type_a_sliding_under_full_head() {
  Scene scene = testing::wet_type_a_step(1.1246, 0.0, UpliftRule::full_head_in_gap);
  scene.contact.restitution = 0.8764;
  scene.ground_motion = CosinePulse{2.0319, 1.7542, 1};
  scene.duration = 1.0;
  scene.solver.method = Method::rk4;
  scene.solver.dt = 0.00025;
  scene.solver.max_events = 1000;
  return scene;
}

TEST(FullHeadInGap, ABlockTippedOntoItsToeBySlidingOpensItsCrackWithoutRattling) {
  const Summary summary = simulate(type_a_sliding_under_full_head());
  ASSERT_EQ(summary.status, Status::ok);
  EXPECT_LT(summary.events, 20);
  ASSERT_GE(summary.modes.size(), 2u);
  EXPECT_EQ(summary.modes[0].mode, ModeKind::slide);
  EXPECT_GT(summary.max_abs_slide, 1.0);
}

}  // namespace
}  // namespace blockfrag
