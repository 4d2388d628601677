// The dynamics with the reservoir agree with its statics (engine/water/block_statics.hpp, closed
// forms over the block's supports): a constant ground acceleration 1e-6 g below a yield
// acceleration leaves the paper's type A dam block, water at its crest, at rest; 1e-6 g above it
// starts that motion, that way. Each case's friction makes the motion tested the first to start in
// its direction.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "engine/simulate.hpp"
#include "engine/water/block_statics.hpp"

namespace blockfrag {
namespace {

Scene wet_type_a(double mu, double lambda) {
  Scene scene;
  scene.polygon = PolygonBlock{{{0, 0}, {12.55, 0}, {10, 3.4}, {10, 16.7}, {0, 16.7}}, 411204.0};
  scene.contact = {mu, 0.2};
  scene.reservoir = Reservoir{};
  scene.reservoir->level = 16.7;
  scene.ground_motion = RectangularPulse{lambda, 1.0};
  scene.duration = 0.3;
  scene.solver.tolerance = 1e-10;
  return scene;
}

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

TEST(ReservoirOnset, TheDynamicsStartEachMotionAtItsStaticYieldAcceleration) {
  const std::vector<OnsetCase> cases{
      {"slide downstream", 1.05, 1, ModeKind::slide},
      {"rock upstream", 1.05, -1, ModeKind::rock},
      {"rock downstream", 2.0, 1, ModeKind::rock},
      {"slide upstream", 0.5, -1, ModeKind::slide},
  };
  for (const OnsetCase& c : cases) {
    SCOPED_TRACE(c.name);
    const double yield = yield_of(block_statics(wet_type_a(c.mu, 0.0)).yield, c);
    ASSERT_GT(yield, 0.0);
    const Summary below = simulate(wet_type_a(c.mu, c.direction * (yield - 1e-6)));
    const Summary above = simulate(wet_type_a(c.mu, c.direction * (yield + 1e-6)));
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

}  // namespace
}  // namespace blockfrag
