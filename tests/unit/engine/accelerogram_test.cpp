// A record's samples: the checks that refuse what cannot be a motion, resampling onto a step grid,
// and a record as ground motion pieces.
#include "engine/motion/accelerogram.hpp"

#include <cmath>
#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "engine/errors.hpp"
#include "engine/motion/ground_motion.hpp"
#include "engine/motion/scene_motion.hpp"

namespace blockfrag {
namespace {

// Samples every step s from 0 to (count - 1) s of a(t).
template <class Acceleration>
Accelerogram tabulated(std::size_t count, double step, const Acceleration& a) {
  Accelerogram record;
  for (std::size_t k = 0; k < count; ++k) {
    const double t = static_cast<double>(k) * step;
    record.times.push_back(t);
    record.acceleration_g.push_back(a(t));
  }
  return record;
}

TEST(Accelerogram, CheckRefusesRecordsThatCannotBeAMotion) {
  EXPECT_NO_THROW(check_accelerogram({{0.0, 0.5}, {0.1, -0.2}}));
  EXPECT_THROW(check_accelerogram({{0.0}, {0.1}}), InvalidInput);
  EXPECT_THROW(check_accelerogram({{0.0, 0.5}, {0.1}}), InvalidInput);
  EXPECT_THROW(check_accelerogram({{0.0, 0.0}, {0.1, 0.2}}), InvalidInput);
  EXPECT_THROW(check_accelerogram({{-0.1, 0.5}, {0.1, 0.2}}), InvalidInput);
  EXPECT_THROW(check_accelerogram({{0.0, 0.5}, {0.1, NAN}}), InvalidInput);
}

TEST(Accelerogram, OnStepGridToARelativeBillionth) {
  const Accelerogram at2 = tabulated(400, 0.005, [](double t) { return std::sin(t); });
  EXPECT_TRUE(on_step_grid(at2, 0.005));
  EXPECT_TRUE(on_step_grid(at2, 0.00025));  // 0.005 = 20 x 0.00025
  EXPECT_TRUE(on_step_grid(at2, 0.001));
  EXPECT_FALSE(on_step_grid(at2, 0.0003));
  EXPECT_FALSE(on_step_grid(at2, 0.01));  // every other sample is between grid points
  EXPECT_TRUE(on_step_grid({{0.0, 0.1 + 1e-12}, {0, 0}}, 0.05));
  EXPECT_FALSE(on_step_grid({{0.0, 0.1 + 1e-8}, {0, 0}}, 0.05));
}

TEST(Accelerogram, ResampleInterpolatesLinearlyOntoTheGrid) {
  // Starts at 0.15 s: zero before it, as the motion is; ends at 0.65 s, between grid points.
  const Accelerogram record{{0.15, 0.35, 0.65}, {1.0, -1.0, 2.0}};
  const Accelerogram grid = resample(record, 0.1);
  // By hand: 0 before 0.15; from 1 at 0.15 falling 10/s to -1 at 0.35; rising 10/s to 2 at 0.65.
  const std::vector<double> expected = {0.0, 0.0, 0.5, -0.5, -0.5, 0.5, 1.5};
  ASSERT_EQ(grid.times.size(), expected.size());
  for (std::size_t k = 0; k < expected.size(); ++k) {
    EXPECT_DOUBLE_EQ(grid.times[k], static_cast<double>(k) * 0.1);
    EXPECT_NEAR(grid.acceleration_g[k], expected[k], 1e-12) << "k = " << k;
  }
  EXPECT_TRUE(on_step_grid(grid, 0.1));
}

TEST(Accelerogram, ResampleOntoAFinerGridKeepsALinearRecordExactly) {
  const Accelerogram ramp = tabulated(11, 0.01, [](double t) { return 0.1 - 0.5 * t; });
  const Accelerogram fine = resample(ramp, 0.003);
  ASSERT_EQ(fine.times.size(), 34u);  // 0, 0.003, ..., 0.099
  for (std::size_t k = 0; k < fine.times.size(); ++k) {
    EXPECT_NEAR(fine.acceleration_g[k], 0.1 - 0.5 * fine.times[k], 1e-14);
  }
}

TEST(RecordedMotion, LambdaIsMinusTheScaledRecordLinearBetweenSamplesAndZeroAfter) {
  const auto record =
      std::make_shared<const Accelerogram>(Accelerogram{{0.5, 1.0, 2.0}, {0.2, -0.4, 0.6}});
  GroundMotionPieces motion(RecordedMotion{"r.txt", 2.5, record});
  EXPECT_EQ(motion.lambda(0.25), 0.0);                         // before the first sample
  EXPECT_NEAR(motion.lambda(0.5), -0.5, 1e-15);                // -2.5 x 0.2
  EXPECT_NEAR(motion.lambda(0.75), -2.5 * -0.1, 1e-15);        // halfway from 0.2 to -0.4
  EXPECT_NEAR(motion.lambda(1.5), -2.5 * 0.1, 1e-15);          // halfway from -0.4 to 0.6
  EXPECT_NEAR(motion.piece_at(1.5).lambda(2.0), -1.5, 1e-15);  // the left limit at the last sample
  EXPECT_EQ(motion.lambda(2.0), 0.0);
  EXPECT_EQ(motion.lambda(100.0), 0.0);
}

std::vector<double> piece_ends(const Scene& scene) {
  const GroundMotionPieces motion = scene_motion(scene);
  std::vector<double> ends;
  for (const auto& piece : motion.pieces()) ends.push_back(piece.end());
  return ends;
}

TEST(RecordedMotion, Rk4RunsAnOffGridRecordOnItsStepGridAndAdaptiveMethodsAsItIs) {
  const auto record =
      std::make_shared<const Accelerogram>(Accelerogram{{0.0, 0.03, 0.07}, {0.0, 0.3, -0.1}});
  Scene scene;
  scene.ground_motion = RecordedMotion{"r.txt", 1.0, record};
  scene.solver.method = Method::adaptive;
  EXPECT_EQ(piece_ends(scene), (std::vector<double>{0.03, 0.07, INFINITY}));

  scene.solver.method = Method::rk4;
  scene.solver.dt = 0.02;
  const std::vector<double> ends = piece_ends(scene);
  ASSERT_EQ(ends.size(), 4u);  // 0-0.02, 0.02-0.04, 0.04-0.06, then zero
  for (std::size_t k = 0; k < 3; ++k) EXPECT_DOUBLE_EQ(ends[k], 0.02 * static_cast<double>(k + 1));
  // lambda = -a: at 0.02 a = 0.2, at 0.04 a = 0.3 - 0.4 x 0.25 = 0.2, at 0.06 a = 0.3 - 0.4 x 0.75
  // = 0.
  GroundMotionPieces motion = scene_motion(scene);
  EXPECT_NEAR(motion.lambda(0.02), -0.2, 1e-12);
  EXPECT_NEAR(motion.lambda(0.04), -0.2, 1e-12);
  EXPECT_NEAR(motion.piece_at(0.05).lambda(0.06), 0.0, 1e-12);

  scene.solver.dt = 0.01;  // the record fits this grid: used as it is
  EXPECT_EQ(piece_ends(scene), (std::vector<double>{0.03, 0.07, INFINITY}));
}

}  // namespace
}  // namespace blockfrag
