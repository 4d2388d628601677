// Hard cases at the edges of the input space: slender, stocky, tiny and huge blocks, 100 g, a
// 600 s record, and the safety net's budgets.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "engine/simulate.hpp"
#include "tests/support/both_integrators.hpp"
#include "tests/support/scene_builders.hpp"

namespace blockfrag {
namespace {

using testing::block_scene;

using testing::BothMethods;

TEST_P(BothMethods, VerySlenderBlockRocksWithHousnersRatio) {
  const double a = 0.05, b = 1.0, alpha = std::atan(a / b);
  Scene scene = with_method(block_scene(a, b, 5.0, 0.0, NoMotion{}, 4.0));
  scene.initial.theta = -0.5 * alpha;
  const auto run = simulate_with_history(scene, 0.01);
  ASSERT_FALSE(run.impacts.empty());
  EXPECT_NEAR(run.impacts[0].omega_after / run.impacts[0].omega_before,
              1 - 1.5 * std::sin(alpha) * std::sin(alpha), 1e-9);
}

TEST_P(BothMethods, VeryStockyBlockOnlySlidesAsNewmarkSays) {
  // a/b = 2 > mu: rocking can never start.
  const double A = 0.9, mu = 0.5, t0 = 0.4, g = 9.81;
  const Summary s =
      simulate(with_method(block_scene(1.0, 0.5, mu, 0.5, RectangularPulse{A, t0}, 2.0)));
  EXPECT_EQ(s.max_abs_theta, 0.0);
  EXPECT_NEAR(s.final_slide, std::pow(A * g * t0, 2) * (1 - mu / A) / (2 * g * mu), 1e-6);
}

TEST_P(BothMethods, TinyAndHugeBlocksFollowSimilarity) {
  // b = 0.01 m and b = 50 m against b = 1 m with the pulse period scaled by sqrt(size).
  const Scene base = with_method(block_scene(0.3, 1.0, 0.7, 0.4, CosinePulse{0.6, 1.0, 2.0}, 4.0));
  const Summary reference = simulate(base);
  ASSERT_GT(reference.max_abs_theta, 0.05);
  for (const double k : {0.01, 50.0}) {
    Scene scaled = base;
    scaled.block.half_width *= k;
    scaled.block.half_height *= k;
    scaled.duration = *scaled.duration * std::sqrt(k);
    std::get<CosinePulse>(scaled.ground_motion).period *= std::sqrt(k);
    if (GetParam() == Method::rk4) scaled.solver.dt *= std::sqrt(k);
    const Summary s = simulate(scaled);
    EXPECT_EQ(s.status, Status::ok);
    EXPECT_EQ(s.overturned, reference.overturned);
    EXPECT_NEAR(s.max_abs_theta, reference.max_abs_theta, 1e-6) << "k = " << k;
    EXPECT_NEAR(s.final_slide / k, reference.final_slide, 1e-6) << "k = " << k;
  }
}

TEST_P(BothMethods, HundredGPulseFinishesWithFiniteResults) {
  for (const double mu : {0.3, 0.8, 3.0}) {
    const Summary s =
        simulate(with_method(block_scene(0.4, 1.0, mu, 0.5, CosinePulse{100.0, 0.5, 1.0}, 3.0)));
    EXPECT_EQ(s.status, Status::ok) << s.status_reason;
    EXPECT_TRUE(std::isfinite(s.final_slide) && std::isfinite(s.max_abs_theta));
    EXPECT_LE(s.max_impact_energy_gain, 1e-12);
    EXPECT_LT(s.max_contact_violation, 1e-9);
  }
}

TEST(MicroBounces, ACornerLiftedByAHairUnderVerticalMotionLandsAgain) {
  // A tall trapezoid with e = 0.03 under a horizontal and a vertical pulse (found by random scenes
  // with vertical motion and polygons): after a flight its corner rose at 3e-7 m/s from just past
  // the unarmed guard's margin and gravity brought it back within 6e-8 s. The guard, already past
  // its margin at the start, fired at once: 767,786 flights 1e-15 s apart. Both methods now agree.
  Scene scene = block_scene(0, 0, 0.5855228558758101, 0.03184581861417798,
                            RectangularPulse{0.2145435656209346, 0.10508537169095258},
                            2.210170743381905, 2.278275560157184e-08);
  scene.polygon = PolygonBlock{{{-0.9322354296338197, 0.0},
                                {0.9322354296338197, 0.0},
                                {0.885614280612365, 10.76065821552097},
                                {-0.768408490832598, 10.76065821552097}},
                               1.0};
  scene.vertical_motion = SinePulse{-0.17545141966842082, 3.693767030383173, 2.0};
  const auto runs = testing::simulate_with_both_methods(
      scene, {ModeKind::rock, ModeKind::flight, ModeKind::rock});
  for (const Summary& s : runs) EXPECT_LT(s.events, 1000);
  EXPECT_EQ(runs[0].impacts, runs[1].impacts);
  EXPECT_NEAR(runs[0].max_abs_theta, runs[1].max_abs_theta, 1e-9);
  EXPECT_NEAR(runs[0].final_slide, runs[1].final_slide, 1e-7);
}

TEST(CornerUnderTheGround, ABouncingCornerTheContactToleranceLeftUnderTheGroundLandsThere) {
  // A near-flat block making small bounces (found by the random scenes test once it measured
  // penetration): one corner lands and bounces off while the other, 9.5e-10 R up, is within the
  // contact tolerance; the rock mode about it puts it on the ground, which leaves the bouncing
  // corner 9.5e-10 R under. Its landing guard, starting below zero, was never armed: the block
  // rotated on through the ground to 0.2 R. It is watched like any unarmed guard now. Bound: no
  // corner deeper than the contact tolerance (the helper's 1e-9 R); the mirrored pulse mirrors
  // the response.
  Scene scene =
      block_scene(0.09431906616914858, 0.07975991013875293, 1.6036322979355901, 0.06288283695023845,
                  CosinePulse{1.3788519599203863, 0.3090951492387029, 2.0}, 2.6181902984774057,
                  1.5497186686440278e-08);
  const auto runs = testing::simulate_with_both_methods(scene, {ModeKind::rock, ModeKind::flight});
  EXPECT_EQ(runs[0].impacts, runs[1].impacts);
  EXPECT_NEAR(runs[0].max_abs_theta, runs[1].max_abs_theta, 1e-8);

  std::get<CosinePulse>(scene.ground_motion).amplitude_g *= -1;
  const Summary mirrored = simulate(scene);
  EXPECT_EQ(mirrored.impacts, runs[0].impacts);
  EXPECT_NEAR(mirrored.max_abs_theta, runs[0].max_abs_theta, 1e-12);
  EXPECT_NEAR(mirrored.final_slide, -runs[0].final_slide, 1e-12);
}

TEST(LongRecord, SixHundredSecondsOfShakingFinishInBoundedWork) {
  // 600 s of a sine that keeps the block rocking and bouncing without overturning; the adaptive
  // method only (RK4 at the paper's dt would take 2.4 M steps).
  const Summary s =
      simulate(block_scene(0.6, 2.0, 0.9, 0.5, SinePulse{0.33, 1.0, 600.0}, 600.0, 1e-8));
  EXPECT_EQ(s.status, Status::ok) << s.status_reason;
  EXPECT_FALSE(s.overturned);
  EXPECT_GT(s.impacts, 1000);
  EXPECT_LT(s.steps, 2'000'000);
  EXPECT_TRUE(std::isfinite(s.final_slide));
}

TEST(SafetyNet, BudgetsStopAScenesLoudly) {
  Scene scene = block_scene(0.5, 1.0, 0.6, 0.6, CosinePulse{1.0, 2.0, 1.0}, 4.0);
  Scene few_steps = scene;
  few_steps.solver.max_steps = 5;
  const Summary steps = simulate(few_steps);
  EXPECT_EQ(steps.status, Status::failed);
  EXPECT_NE(steps.status_reason.find("step budget"), std::string::npos);
  EXPECT_GT(steps.end_time, 0.0);
  EXPECT_LT(steps.end_time, 4.0);

  Scene few_events = scene;
  few_events.solver.max_events = 2;
  const Summary events = simulate(few_events);
  EXPECT_EQ(events.status, Status::failed);
  EXPECT_NE(events.status_reason.find("event budget"), std::string::npos);
}

}  // namespace
}  // namespace blockfrag
