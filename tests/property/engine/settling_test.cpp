// Runs without a duration go on until the block's fate is final: every excitation over and the
// block at rest on its base, or overturned. The verdict is then the block's, not the clock's: a
// block still falling when a guessed duration ends is reported standing, and the settled run
// finds it on its side; any duration past the settle time gives the settled run's summary.
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

#include <gtest/gtest.h>

#include "engine/simulate.hpp"
#include "tests/support/scene_builders.hpp"

namespace blockfrag {
namespace {

using testing::block_scene;

// The paper's block under lambda = A cos(pi t) for 2 s.
Scene paper_block(double amplitude_g, std::optional<double> duration) {
  Scene scene = block_scene(0.5, 1.0, 0.6, 0.6, CosinePulse{amplitude_g, 2.0, 1.0}, 4.0, 1e-8);
  scene.duration = duration;
  return scene;
}

TEST(Settling, ABlockStillFallingAtTheGuessedDurationOverturnsWhenRunToSettle) {
  // At 4 s, the paper's cut, the block has rocked past alpha and is still falling: the 4 s run
  // reports it standing, unsettled.
  const Summary cut = simulate(paper_block(1.295, 4.0));
  EXPECT_EQ(cut.status, Status::ok);
  EXPECT_FALSE(cut.overturned);
  EXPECT_FALSE(cut.settled);
  EXPECT_FALSE(cut.settle_time.has_value());
  EXPECT_GT(std::abs(cut.final_theta), std::atan(0.5));  // past alpha: it can only fall
  // Run to settle, it lies on its side soon after.
  const Summary settled = simulate(paper_block(1.295, std::nullopt));
  EXPECT_EQ(settled.status, Status::ok);
  EXPECT_TRUE(settled.overturned);
  EXPECT_TRUE(settled.settled);
  ASSERT_TRUE(settled.overturn_time.has_value());
  ASSERT_TRUE(settled.settle_time.has_value());
  EXPECT_GT(*settled.overturn_time, 4.0);
  EXPECT_LT(*settled.overturn_time, 4.5);
  EXPECT_EQ(*settled.settle_time, *settled.overturn_time);
  EXPECT_EQ(settled.end_time, *settled.overturn_time);
}

// Scenes that end in each way a block settles: rocking back to rest, sliding to a stop, flying
// and landing, overturning, never moving.
std::vector<Scene> settling_scenes() {
  std::vector<Scene> scenes;
  scenes.push_back(paper_block(0.55, std::nullopt));  // rocks a little, comes back to rest
  scenes.push_back(paper_block(1.0, std::nullopt));   // overturns (after 1.8 s)
  scenes.push_back(paper_block(0.3, std::nullopt));   // below a/b and mu: never moves
  Scene sliding = block_scene(0.5, 1.0, 0.3, 0.5, SinePulse{0.6, 1.0, 2.0}, 4.0, 1e-8);
  sliding.duration.reset();  // mu < a/b: slides, and stops after the pulse
  scenes.push_back(sliding);
  Scene bouncing = block_scene(0.2, 1.0, 0.8, 0.5, CosinePulse{0.5, 0.5, 1.0}, 4.0, 1e-8);
  bouncing.duration.reset();  // a slender block rocking with impacts after the pulse
  scenes.push_back(bouncing);
  return scenes;
}

TEST(Settling, EveryScenesFateIsFinalAndItsSettleTimeIsWhenItGotThere) {
  int rested = 0, overturned = 0, still = 0;
  for (const Scene& scene : settling_scenes()) {
    const Summary s = simulate(scene);
    ASSERT_EQ(s.status, Status::ok);
    EXPECT_TRUE(s.settled);
    ASSERT_TRUE(s.settle_time.has_value());
    if (s.overturned) {
      ++overturned;
      continue;
    }
    // At rest on its base: flat, and the run stops where the last excitation ends or later.
    EXPECT_EQ(s.final_theta, 0.0);
    ASSERT_FALSE(s.modes.empty());
    EXPECT_EQ(s.modes.back().mode, ModeKind::rest);
    EXPECT_EQ(*s.settle_time, s.modes.back().time);
    EXPECT_GE(s.end_time, *s.settle_time);
    (s.modes.size() == 1 ? still : rested) += 1;
    if (s.modes.size() == 1) {
      EXPECT_EQ(*s.settle_time, 0.0);
    }
  }
  EXPECT_EQ(overturned, 1);
  EXPECT_EQ(still, 1);
  EXPECT_EQ(rested, 3);
}

TEST(Settling, AnyDurationPastTheSettleTimeGivesTheSameSummary) {
  for (const Scene& scene : settling_scenes()) {
    const Summary settled = simulate(scene);
    ASSERT_TRUE(settled.settle_time.has_value());
    for (const double extra : {0.25, 3.0, 30.0}) {
      Scene fixed = scene;
      fixed.duration = std::max(settled.end_time, *settled.settle_time) + extra;
      const Summary s = simulate(fixed);
      SCOPED_TRACE(extra);
      EXPECT_EQ(s.overturned, settled.overturned);
      EXPECT_EQ(s.overturn_time, settled.overturn_time);
      EXPECT_EQ(s.max_abs_theta, settled.max_abs_theta);
      EXPECT_EQ(s.final_theta, settled.final_theta);
      EXPECT_EQ(s.final_slide, settled.final_slide);
      EXPECT_EQ(s.max_abs_slide, settled.max_abs_slide);
      EXPECT_EQ(s.impacts, settled.impacts);
      EXPECT_EQ(s.steps, settled.steps);
      EXPECT_EQ(s.events, settled.events);
      EXPECT_EQ(s.modes.size(), settled.modes.size());
      EXPECT_EQ(s.settled, settled.settled);
      EXPECT_EQ(s.settle_time, settled.settle_time);
    }
  }
}

TEST(Settling, ABlockThatNeverStopsRockingEndsUnsettledAtMaxDurationNotFailed) {
  // Housner's rocking without impact losses: nothing dissipates the rocking.
  Scene scene = block_scene(0.2, 1.0, 5.0, 1.0, NoMotion{}, 4.0, 1e-10);
  scene.initial.theta = -0.1;
  scene.effects = {false, true, false, false, false, false};  // Housner rocking, no impact losses
  scene.duration.reset();
  scene.max_duration = 20.0;
  const Summary s = simulate(scene);
  EXPECT_EQ(s.status, Status::ok);
  EXPECT_FALSE(s.settled);
  EXPECT_FALSE(s.settle_time.has_value());
  EXPECT_EQ(s.end_time, 20.0);
  EXPECT_GT(s.events, 10);                  // it changed pivot again and again
  EXPECT_NEAR(s.max_abs_theta, 0.1, 1e-9);  // and kept its energy
  EXPECT_GT(std::abs(s.final_theta), 0.0);  // still rocking at the end
  // Without max_duration it stops the documented allowance after the (absent) excitation: 60 s.
  scene.max_duration.reset();
  EXPECT_EQ(simulate(scene).end_time, 60.0);
}

TEST(Settling, ABlockOnADamCrestWaitsForTheCrestsRingingToDie) {
  // A block that cannot move under the pulse (mu and a/b far above it) on a lightly damped dam:
  // the crest rings on after the foundation stops at 1 s, and the run ends only once that ringing
  // is below 1e-6 g: the amplitude decays as exp(-zeta omega t), so some ln(1e6) / (zeta omega)
  // = 13.8 / (0.02 x 2 pi / 0.5) = 55 s at most after the pulse.
  Scene scene = block_scene(0.9, 1.0, 1.0, 0.3, CosinePulse{0.05, 1.0, 1.0}, 4.0, 1e-8);
  scene.duration.reset();
  scene.dam = DamCrest{DamPeriod{0.5}, 0.02, 1.0};
  const Summary s = simulate(scene);
  EXPECT_TRUE(s.settled);
  EXPECT_GT(s.end_time, 20.0);  // the crest still rings well above 1e-6 g after 20 s
  EXPECT_LT(s.end_time, 1.0 + 55.0 + 1e-9);
  ASSERT_TRUE(s.settle_time.has_value());
  EXPECT_EQ(*s.settle_time, 0.0);  // it never moved
}

}  // namespace
}  // namespace blockfrag
