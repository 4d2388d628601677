// Vertical ground motion: gravity in the ground's frame becomes g (1 + lambda_v). Checked against
// the similarity it implies (a constant lambda_v is the same scene with g' = g (1 + c) and
// lambda' = lambda / (1 + c)), the closed-form lift-off flight, and the onset thresholds of
// docs/references.md with g replaced by g (1 + lambda_v).
#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "engine/motion/accelerogram.hpp"
#include "engine/simulate.hpp"
#include "tests/support/scene_builders.hpp"

namespace blockfrag {
namespace {

using testing::block_scene;

// On the flat ground and on a flat seat (whose engine is another): every tolerance of either
// scales with g, the settling speed with the g the block feels.
TEST(VerticalMotion, ConstantVerticalAccelerationIsScaledGravity) {
  int rocked = 0, slid = 0, flew = 0, overturned = 0;
  for (const bool on_seat : {false, true}) {
    for (const double c : {0.3, -0.4}) {
      for (const double mu : {0.2, 0.8}) {
        for (const double amplitude : {0.35, 0.6}) {
          // The seat integrates a slide in x, y and theta, the flat ground in x alone: at
          // tolerance 1e-10 the seat's two runs, their inputs an ulp apart, part by 1.2e-9 m
          // over a 0.28 m slide.
          Scene vertical = block_scene(0.3, 1.0, mu, 0.5, SinePulse{amplitude, 1.0, 1.0}, 4.0,
                                       on_seat ? 1e-12 : 1e-10);
          if (on_seat) vertical.seat = Seat{{{-100.0, -1.0}, {100.0, -1.0}}};
          vertical.vertical_motion = RectangularPulse{c, 10.0};
          Scene scaled = vertical;
          scaled.vertical_motion = NoMotion{};
          scaled.g = 9.81 * (1 + c);
          scaled.ground_motion = SinePulse{amplitude / (1 + c), 1.0, 1.0};
          const Summary a = simulate(vertical), b = simulate(scaled);
          SCOPED_TRACE(std::string(on_seat ? "seat" : "flat") + " c " + std::to_string(c) + " mu " +
                       std::to_string(mu) + " A " + std::to_string(amplitude));
          EXPECT_EQ(a.model, Model::full_vertical);
          EXPECT_EQ(a.overturned, b.overturned);
          EXPECT_EQ(a.impacts, b.impacts);
          EXPECT_EQ(a.modes.size(), b.modes.size());
          EXPECT_NEAR(a.max_abs_theta, b.max_abs_theta, 1e-9);
          EXPECT_NEAR(a.final_theta, b.final_theta, 1e-9);
          EXPECT_NEAR(a.final_slide, b.final_slide, 1e-9);
          EXPECT_NEAR(a.max_abs_slide, b.max_abs_slide, 1e-9);
          rocked += a.rock_start_time.has_value();
          slid += a.slide_start_time.has_value();
          overturned += a.overturned;
          for (const ModeChange& change : a.modes) flew += change.mode == ModeKind::flight;
        }
      }
    }
  }
  // The comparison covered each kind of motion.
  EXPECT_GT(rocked, 0);
  EXPECT_GT(slid, 0);
  EXPECT_GT(flew, 0);
  EXPECT_GT(overturned, 0);
}

TEST(VerticalMotion, TheBlockLiftsOffOnlyWhenTheGroundFallsFasterThanG) {
  // lambda_v = -1.5 for 0.2 s: relative to the ground the block rises at 0.5 g, then falls at g.
  const double g = 9.81, t1 = 0.2;
  const double v = 0.5 * g * t1, h = 0.25 * g * t1 * t1;
  const double landing = t1 + (v + std::sqrt(v * v + 2 * g * h)) / g;
  Scene scene = block_scene(0.5, 1.0, 0.6, 0.0, NoMotion{}, 1.0);
  scene.vertical_motion = RectangularPulse{-1.5, t1};
  const Summary lifted = simulate(scene);
  ASSERT_EQ(lifted.modes.size(), 2u);
  EXPECT_EQ(lifted.modes[0].mode, ModeKind::flight);  // from the first instant
  EXPECT_EQ(lifted.modes[1].mode, ModeKind::rest);
  EXPECT_NEAR(lifted.modes[1].time, landing, 1e-9);
  ASSERT_TRUE(lifted.first_impact_time.has_value());
  EXPECT_NEAR(*lifted.first_impact_time, landing, 1e-9);
  EXPECT_EQ(lifted.max_abs_theta, 0.0);  // it lands flat, e = 0: at rest again

  scene.vertical_motion = RectangularPulse{-0.99, t1};
  const Summary held = simulate(scene);
  ASSERT_EQ(held.modes.size(), 1u);
  EXPECT_EQ(held.modes[0].mode, ModeKind::rest);
  EXPECT_EQ(held.impacts, 0);
}

RecordedMotion record_of(std::vector<double> times, std::vector<double> acceleration_g) {
  auto record = std::make_shared<Accelerogram>();
  record->times = std::move(times);
  record->acceleration_g = std::move(acceleration_g);
  RecordedMotion motion;
  motion.record = record;
  return motion;
}

TEST(VerticalMotion, ARecordsAccelerationIsTheGroundsUpwardAcceleration) {
  // a(t) = +0.3 g upward throughout is lambda_v = +0.3 (unlike the horizontal lambda = -a).
  Scene pulse = block_scene(0.3, 1.0, 0.8, 0.5, SinePulse{0.6, 1.0, 1.0}, 3.0);
  pulse.vertical_motion = RectangularPulse{0.3, 10.0};
  Scene recorded = pulse;
  recorded.vertical_motion = record_of({0.0, 10.0}, {0.3, 0.3});
  const Summary a = simulate(pulse), b = simulate(recorded);
  ASSERT_TRUE(a.rock_start_time.has_value());
  ASSERT_TRUE(b.rock_start_time.has_value());
  EXPECT_NEAR(*b.rock_start_time, *a.rock_start_time, 1e-12);
  EXPECT_NEAR(b.max_abs_theta, a.max_abs_theta, 1e-12);
}

TEST(VerticalMotion, ASlideEndsInFlightWhereTheGroundStartsFallingFasterThanG) {
  // Sliding at lambda = 0.5 > mu = 0.3 on a stocky block; at t = 0.3 s the ground drops away at
  // 1.5 g for 0.2 s (reached over 1 ns in the record): the slide must end there, not slip on with
  // no load.
  Scene scene = block_scene(1.0, 1.0, 0.3, 0.0, RectangularPulse{0.5, 1.0}, 1.0);
  scene.vertical_motion =
      record_of({0.0, 0.3, 0.3 + 1e-9, 0.5, 0.5 + 1e-9, 1.0}, {0.0, 0.0, -1.5, -1.5, 0.0, 0.0});
  const Summary s = simulate(scene);
  ASSERT_GE(s.modes.size(), 3u);
  EXPECT_EQ(s.modes[0].mode, ModeKind::slide);
  EXPECT_EQ(s.modes[1].mode, ModeKind::flight);
  EXPECT_NEAR(s.modes[1].time, 0.3 + 1e-9 / 1.5, 1e-12);
}

// Shenton's thresholds with g replaced by g (1 + lambda_v): a constant lambda below them starts
// the motion once the vertical sine lowers them far enough.
TEST(VerticalMotion, OnsetFromRestWhenTheVerticalMotionLowersTheThreshold) {
  const double two_pi = 2 * std::numbers::pi;
  {  // rocking: 0.4 > 0.5 (1 + 0.5 sin(2 pi t)) first where sin = -0.4
    Scene scene = block_scene(0.5, 1.0, 2.0, 0.5, RectangularPulse{0.4, 3.0}, 1.0);
    scene.vertical_motion = SinePulse{0.5, 1.0, 1.0};
    const Summary s = simulate(scene);
    ASSERT_TRUE(s.rock_start_time.has_value());
    EXPECT_NEAR(*s.rock_start_time, 0.5 + std::asin(0.4) / two_pi, 1e-9);
  }
  {  // sliding: 0.25 > 0.3 (1 + 0.5 sin(2 pi t)) first where sin = -1/3
    Scene scene = block_scene(1.0, 1.0, 0.3, 0.5, RectangularPulse{0.25, 3.0}, 1.0);
    scene.vertical_motion = SinePulse{0.5, 1.0, 1.0};
    const Summary s = simulate(scene);
    ASSERT_TRUE(s.slide_start_time.has_value());
    EXPECT_FALSE(s.rock_start_time.has_value());
    EXPECT_NEAR(*s.slide_start_time, 0.5 + std::asin(1.0 / 3.0) / two_pi, 1e-9);
  }
  {  // a vertical motion alone that never reaches -g moves nothing
    Scene scene = block_scene(0.2, 1.0, 0.5, 0.5, NoMotion{}, 2.0);
    scene.vertical_motion = CosinePulse{0.9, 0.5, 3.0};
    const Summary s = simulate(scene);
    EXPECT_EQ(s.modes.size(), 1u);
    EXPECT_EQ(s.max_abs_slide, 0.0);
  }
}

}  // namespace
}  // namespace blockfrag
