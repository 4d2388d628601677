// The paper's RK4 and the adaptive Dormand-Prince agree, and RK4 converges at fourth order.
#include <cmath>

#include <gtest/gtest.h>

#include "engine/simulate.hpp"
#include "tests/support/scene_builders.hpp"

namespace blockfrag {
namespace {

using testing::block_scene;
using testing::rk4;

TEST(IntegratorAgreement, Rk4ConvergesAtFourthOrderOnASmoothRockingSegment) {
  // Rocking under a sine pulse, stopped before the first impact: one smooth mode throughout.
  const Scene scene = block_scene(0.4, 1.0, 3.0, 0.5, SinePulse{0.8, 1.5, 1.0}, 0.6, 1e-13);
  const Summary reference = simulate(scene);
  ASSERT_FALSE(reference.first_impact_time.has_value());
  ASSERT_GT(reference.max_abs_theta, 0.01);
  std::vector<double> errors;
  for (const double dt : {0.02, 0.01, 0.005}) {
    errors.push_back(std::abs(simulate(rk4(scene, dt)).final_theta - reference.final_theta));
  }
  for (std::size_t i = 1; i < errors.size(); ++i) {
    const double order = std::log2(errors[i - 1] / errors[i]);
    EXPECT_NEAR(order, 4.0, 0.3) << "errors " << errors[i - 1] << " -> " << errors[i];
  }
}

TEST(IntegratorAgreement, PaperMethodAgreesWithAdaptiveOnEventfulScenes) {
  for (const Scene& scene :
       {block_scene(0.5, 1.0, 0.6, 0.6, CosinePulse{1.0, 2.0, 1.0}, 4.0, 1e-10),
        block_scene(0.3, 1.0, 0.8, 0.0, SinePulse{0.5, 1.0, 2.0}, 3.0, 1e-10)}) {
    const Summary adaptive = simulate(scene);
    const Summary paper = simulate(rk4(scene, 2.5e-4));
    EXPECT_EQ(adaptive.overturned, paper.overturned);
    EXPECT_NEAR(adaptive.max_abs_theta, paper.max_abs_theta, 1e-6);
    ASSERT_TRUE(adaptive.first_impact_time && paper.first_impact_time);
    EXPECT_NEAR(*adaptive.first_impact_time, *paper.first_impact_time, 1e-6);
  }
}

}  // namespace
}  // namespace blockfrag
