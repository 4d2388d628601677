// A study scales a Mavroeidis-Papageorgiou pulse, which is given by its ground velocity, so that
// its peak |lambda| (its PGA in g) is the intensity level.
#include <algorithm>
#include <cmath>
#include <variant>

#include <gtest/gtest.h>

#include "engine/motion/ground_motion.hpp"
#include "mpi_driver/config/study_config.hpp"
#include "mpi_driver/study/study_sample.hpp"

namespace blockfrag {
namespace {

// max |lambda| on a grid of 1e5 points: an estimate independent of the engine's extrema.
double scanned_peak(const GroundMotionPieces& motion, double end) {
  double peak = 0.0;
  for (int i = 0; i <= 100000; ++i)
    peak = std::max(peak, std::abs(motion.lambda(end * i / 100000.0)));
  return peak;
}

TEST(PulseStudy, MavroeidisPapageorgiouIsScaledToItsPeakAcceleration) {
  StudyConfig config;
  config.base_scene.g = 9.7;
  config.base_scene.ground_motion = MavroeidisPapageorgiouPulse{-0.5, 0.8, 2.5, 0.4, {}};
  for (const double im : {0.3, -0.45}) {  // a negative level is the "direction" input's flip
    const Scene scene = apply_sample(config, {}, im);
    const auto& pulse = std::get<MavroeidisPapageorgiouPulse>(scene.ground_motion);
    EXPECT_EQ(pulse.velocity_amplitude > 0, im > 0);  // the level's sign, not the base's
    EXPECT_EQ(pulse.gamma, 2.5);
    const GroundMotionPieces motion(scene.ground_motion, scene.g);
    EXPECT_NEAR(scanned_peak(motion, 2.0), std::abs(im), 1e-7 * std::abs(im));
    EXPECT_NEAR(motion.peak_abs_lambda(), std::abs(im), 1e-14);
  }
}

}  // namespace
}  // namespace blockfrag
