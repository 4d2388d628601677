// The "zero_in_gap" uplift on a seated block (engine/contact/crack_seating.hpp,
// engine/seat/seated_load.hpp): the crack opens from the lifting corner just far enough to seat
// it, so the paper's type A dam block, water at its crest, rocks only where even a fully open
// crack (no uplift) leaves its lifting corner in tension, and a ground step between the closed
// crack's threshold and that one leaves it at rest instead of rattling between a closed crack that
// lifts it and an open one that sets it down (thousands of rest-rock events in 0.02 s). The
// statics (engine/water/block_statics.hpp) use the same rule: the dynamics start each motion at
// their yield acceleration.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "engine/contact/crack_seating.hpp"
#include "engine/simulate.hpp"
#include "engine/water/block_statics.hpp"
#include "tests/support/wet_dam_blocks.hpp"

namespace blockfrag {
namespace {

Scene type_a_in_gap(double mu, double lambda, UpliftRule rule = UpliftRule::zero_in_gap) {
  Scene scene = testing::wet_type_a_step(mu, lambda, rule);
  // Ten times the events a step needs here: a rattle exhausts it within milliseconds.
  scene.solver.max_events = 10;
  return scene;
}

TEST(SeatingOpening, OpensJustFarEnoughToSeatTheCorner) {
  EXPECT_EQ(seating_opening([](double f) { return f + 0.5; }), 0.0);
  EXPECT_EQ(seating_opening([](double f) { return f - 2.0; }), 1.0);
  const double f = seating_opening([](double x) { return (x - 0.3) * (x - 0.3) * (x - 0.3); });
  EXPECT_GE(f, 0.3);
  EXPECT_LE(f - 0.3, 1e-15);
}

TEST(ZeroInGapStatics, TheBlockRocksWhereAFullyOpenCrackLeavesItsCornerInTension) {
  const YieldAccelerations gap = block_statics(type_a_in_gap(2.0, 0.0)).yield;
  const YieldAccelerations none = block_statics(type_a_in_gap(2.0, 0.0, UpliftRule::none)).yield;
  const YieldAccelerations full =
      block_statics(type_a_in_gap(2.0, 0.0, UpliftRule::unchanged)).yield;
  EXPECT_DOUBLE_EQ(gap.rock_downstream, none.rock_downstream);
  EXPECT_DOUBLE_EQ(gap.rock_upstream, none.rock_upstream);
  // The type A block's four thresholds, closed crack and none (docs/statics.md).
  EXPECT_NEAR(full.rock_downstream, 0.2311, 1e-4);
  EXPECT_NEAR(gap.rock_downstream, 0.3768, 1e-4);
  EXPECT_NEAR(full.rock_upstream, 0.4079, 1e-4);
  EXPECT_NEAR(gap.rock_upstream, 0.4808, 1e-4);
  // mu = 1.1: the closed crack's block slides downstream at 0.2442 g, above the 0.2311 g at
  // which its heel lifts; the crack opened that far presses it down: it slides between the
  // closed crack's threshold and the open one's.
  const YieldAccelerations gap_slide = block_statics(type_a_in_gap(1.1, 0.0)).yield;
  const YieldAccelerations full_slide =
      block_statics(type_a_in_gap(1.1, 0.0, UpliftRule::unchanged)).yield;
  const YieldAccelerations none_slide =
      block_statics(type_a_in_gap(1.1, 0.0, UpliftRule::none)).yield;
  EXPECT_GT(full_slide.slide_downstream, full.rock_downstream);
  EXPECT_GT(gap_slide.slide_downstream, full_slide.slide_downstream);
  EXPECT_LT(gap_slide.slide_downstream, none_slide.slide_downstream);
}

struct InGapOnset {
  std::string name;
  double mu;
  int direction;  // +1: downstream (the ground accelerating upstream, lambda > 0)
  ModeKind motion;
};

TEST(ZeroInGapOnset, TheDynamicsStartEachMotionAtItsStaticYieldWithoutRattling) {
  const std::vector<InGapOnset> cases{
      {"rock downstream", 2.0, 1, ModeKind::rock},
      {"rock upstream", 2.0, -1, ModeKind::rock},
      {"slide downstream, the crack part open", 1.1, 1, ModeKind::slide},
  };
  for (const InGapOnset& c : cases) {
    SCOPED_TRACE(c.name);
    const YieldAccelerations y = block_statics(type_a_in_gap(c.mu, 0.0)).yield;
    const double yield = c.motion == ModeKind::slide
                             ? y.slide_downstream
                             : (c.direction > 0 ? y.rock_downstream : y.rock_upstream);
    const Summary below = simulate(type_a_in_gap(c.mu, c.direction * (yield - 1e-6)));
    const Summary above = simulate(type_a_in_gap(c.mu, c.direction * (yield + 1e-6)));
    ASSERT_EQ(below.status, Status::ok);
    ASSERT_EQ(above.status, Status::ok);
    EXPECT_LE(below.events, 2);
    EXPECT_LE(above.events, 2);
    ASSERT_EQ(below.modes.size(), 1u);
    EXPECT_EQ(below.modes.front().mode, ModeKind::rest);
    EXPECT_EQ(below.final_theta, 0.0);
    EXPECT_EQ(below.final_slide, 0.0);
    ASSERT_FALSE(above.modes.empty());
    EXPECT_EQ(above.modes.front().mode, c.motion);
    if (c.motion == ModeKind::slide) {
      EXPECT_GT(c.direction * above.final_slide, 0.0);
    } else {
      EXPECT_LT(c.direction * above.final_theta, 0.0);
    }
  }
}

}  // namespace
}  // namespace blockfrag
