// The dynamics with the reservoir agree with its statics (engine/water/block_statics.hpp, closed
// forms over the block's supports): a constant ground acceleration 1e-6 g below a yield
// acceleration leaves the paper's dam blocks, water at the crest, at rest; 1e-6 g above it starts
// that motion, that way. Each case's friction makes the motion tested the first to start in its
// direction. The type B block's three contacts at rest (heel, fold, toe) carry forces that are not
// unique: under "zero_in_gap" its crack opens where the loads turn it about the other outermost
// contact, as in the statics. Under "full_head_in_gap" a block at rest has its crack closed: it
// lifts a corner where the closed crack's loads lift it, and the full head fills the crack after.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "engine/simulate.hpp"
#include "engine/water/block_statics.hpp"
#include "tests/support/wet_dam_blocks.hpp"

namespace blockfrag {
namespace {

struct OnsetCase {
  std::string name;
  double mu;
  int direction;  // +1: downstream (the ground accelerating upstream, lambda > 0)
  ModeKind motion;
};

double yield_of(const YieldAccelerations& y, const OnsetCase& c) {
  if (c.motion == ModeKind::slide) return c.direction > 0 ? y.slide_downstream : y.slide_upstream;
  return c.direction > 0 ? y.rock_downstream : y.rock_upstream;
}

using WetScene = Scene (*)(double mu, double lambda, UpliftRule rule);

void expect_onsets_at_yields(WetScene wet, UpliftRule rule, const std::vector<OnsetCase>& cases) {
  for (const OnsetCase& c : cases) {
    SCOPED_TRACE(c.name);
    const double yield = yield_of(block_statics(wet(c.mu, 0.0, rule)).yield, c);
    ASSERT_GT(yield, 0.0);
    const Summary below = simulate(wet(c.mu, c.direction * (yield - 1e-6), rule));
    const Summary above = simulate(wet(c.mu, c.direction * (yield + 1e-6), rule));
    ASSERT_EQ(below.status, Status::ok);
    ASSERT_EQ(above.status, Status::ok);
    ASSERT_EQ(below.modes.size(), 1u);
    EXPECT_EQ(below.modes.front().mode, ModeKind::rest);
    EXPECT_EQ(below.final_slide, 0.0);
    EXPECT_EQ(below.final_theta, 0.0);
    // The ground's acceleration is on from t = 0: the block moves from the start.
    ASSERT_FALSE(above.modes.empty());
    EXPECT_EQ(above.modes.front().mode, c.motion);
    if (c.motion == ModeKind::slide) {
      EXPECT_GT(c.direction * above.final_slide, 0.0);
    } else {
      EXPECT_LT(c.direction * above.final_theta, 0.0);  // downstream: about the toe, clockwise
    }
  }
}

TEST(ReservoirOnset, TheDynamicsStartEachMotionAtItsStaticYieldAcceleration) {
  const std::vector<OnsetCase> cases{
      {"slide downstream", 1.05, 1, ModeKind::slide},
      {"rock upstream", 1.05, -1, ModeKind::rock},
      {"rock downstream", 2.0, 1, ModeKind::rock},
      {"slide upstream", 0.5, -1, ModeKind::slide},
  };
  for (const UpliftRule rule : {UpliftRule::unchanged, UpliftRule::full_head_in_gap}) {
    SCOPED_TRACE(static_cast<int>(rule));
    expect_onsets_at_yields(testing::wet_type_a_step, rule, cases);
  }
}

TEST(ReservoirOnset, OnItsSeatTheTypeBBlockStartsEachMotionAtItsStaticYield) {
  const std::vector<OnsetCase> cases{
      {"rock downstream", 1.05, 1, ModeKind::rock},
      {"rock upstream", 1.05, -1, ModeKind::rock},
      {"slide upstream", 0.3, -1, ModeKind::slide},
  };
  for (const UpliftRule rule :
       {UpliftRule::unchanged, UpliftRule::zero_in_gap, UpliftRule::full_head_in_gap}) {
    SCOPED_TRACE(static_cast<int>(rule));
    expect_onsets_at_yields(testing::wet_type_b_step, rule, cases);
  }
}

}  // namespace
}  // namespace blockfrag
