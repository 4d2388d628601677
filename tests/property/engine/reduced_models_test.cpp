// The one-degree-of-freedom models against the full model where they must agree, against their own
// closed forms, and "auto" against the full model over random scenes (docs/physics.md: pruning must
// never change a result).
#include <cmath>
#include <numbers>
#include <random>

#include <gtest/gtest.h>

#include "engine/contact/reduced_contact.hpp"
#include "engine/errors.hpp"
#include "engine/simulate.hpp"
#include "tests/support/scene_builders.hpp"

namespace blockfrag {
namespace {

using testing::block_scene;

constexpr Effects kFull{.automatic = false};
constexpr Effects kHousner{.automatic = false, .sliding = false, .flight = false};
constexpr Effects kHousnerLossless{
    .automatic = false, .sliding = false, .impact = false, .flight = false};
constexpr Effects kNewmark{.automatic = false, .rocking = false, .impact = false, .flight = false};

Scene with(Scene scene, Effects effects) {
  scene.effects = effects;
  return scene;
}

void expect_same_response(const Summary& full, const Summary& reduced, double tol) {
  EXPECT_EQ(reduced.overturned, full.overturned);
  EXPECT_EQ(reduced.impacts, full.impacts);
  EXPECT_NEAR(reduced.max_abs_theta, full.max_abs_theta, tol);
  EXPECT_NEAR(reduced.final_theta, full.final_theta, tol);
  EXPECT_NEAR(reduced.final_slide, full.final_slide, tol);
  EXPECT_NEAR(reduced.max_abs_slide, full.max_abs_slide, tol);
}

bool only_rests_and_rocks(const Summary& s) {
  for (const ModeChange& change : s.modes) {
    if (change.mode != ModeKind::rest && change.mode != ModeKind::rock) return false;
  }
  return true;
}

TEST(HousnerModel, EqualsTheFullModelForASlenderBlockWithHugeFriction) {
  int rocked = 0;
  for (const double a : {0.1, 0.15, 0.25}) {
    for (const double scale : {1.05, 1.3, 1.6}) {
      for (const GroundMotion& motion : {GroundMotion{SinePulse{scale * a, 1.0, 1.0}},
                                         GroundMotion{CosinePulse{scale * a, 0.6, 2.0}}}) {
        const Scene scene = block_scene(a, 1.0, 1e3, 0.0, motion, 5.0);
        const Summary full = simulate(with(scene, kFull));
        // Where the full block lifts off or slips, Housner's model does not apply.
        if (!only_rests_and_rocks(full) || full.overturned) continue;
        const Summary housner = simulate(with(scene, kHousner));
        EXPECT_EQ(housner.model, Model::housner_rocking);
        // The two step with different guard sets, so their steps differ; over up to ~240 impacts
        // at tolerance 1e-10 per step the answers drift apart by ~1e-8 rad.
        expect_same_response(full, housner, 1e-7);
        rocked += full.impacts > 0;
      }
    }
  }
  EXPECT_GE(rocked, 10);  // the comparison covered rocking with impacts
}

TEST(HousnerModel, ImpactKeepsHousnersRatioOfAngularVelocities) {
  for (const double a : {0.1, 0.3, 0.5}) {
    const double alpha = std::atan(a / 1.0);
    const double ratio = 1.0 - 1.5 * std::pow(std::sin(alpha), 2);
    EXPECT_NEAR(housner_impact_ratio(BlockGeometry(RectangularBlock{a, 1.0, 1.0}), Corner::right),
                ratio, 1e-14);
    Scene free_rocking = with(block_scene(a, 1.0, 0.6, 0.0, NoMotion{}, 3.0), kHousner);
    free_rocking.initial.theta = -0.5 * alpha;
    const auto run = simulate_with_history(free_rocking, 0.01);
    ASSERT_GE(run.impacts.size(), 2u);
    for (std::size_t i = 0; i < 2; ++i) {
      EXPECT_NEAR(run.impacts[i].omega_after / run.impacts[i].omega_before, ratio, 1e-12);
    }
  }
}

TEST(HousnerModel, WithoutImpactLossFreeRockingKeepsItsAmplitude) {
  Scene scene = with(block_scene(0.2, 1.0, 0.6, 0.0, NoMotion{}, 10.0), kHousnerLossless);
  scene.initial.theta = 0.1;
  const auto run = simulate_with_history(scene, 0.001);
  EXPECT_EQ(run.summary.impacts, 0);
  double late_peak = 0.0;
  for (const HistoryRow& row : run.history) {
    if (row.t > 8.0) late_peak = std::max(late_peak, std::abs(row.theta));
  }
  // Energy is conserved: the peaks stay at the release angle (to the output grid's resolution).
  EXPECT_NEAR(late_peak, 0.1, 1e-5);
  EXPECT_LE(run.summary.max_abs_theta, 0.1 + 1e-9);
}

TEST(NewmarkModel, EqualsTheFullModelForABlockTooStockyToRock) {
  for (const double mu : {0.2, 0.45}) {
    for (const GroundMotion& motion :
         {GroundMotion{RectangularPulse{0.6, 0.4}}, GroundMotion{SinePulse{1.5, 0.8, 2.0}},
          GroundMotion{CosinePulse{-0.9, 1.2, 1.0}}}) {
      const Scene scene = block_scene(1.0, 2.0, mu, 0.5, motion, 4.0);  // a/b = 0.5 > mu
      const Summary full = simulate(with(scene, kFull));
      const Summary newmark = simulate(with(scene, kNewmark));
      EXPECT_EQ(newmark.model, Model::newmark_sliding);
      EXPECT_GT(full.max_abs_slide, 0.01);
      expect_same_response(full, newmark, 1e-12);
    }
  }
}

TEST(NewmarkModel, ASlenderBlockStillSlidesAsNewmarksBlock) {
  // The full model would rock this block (mu > a/b); Newmark's model slides it by the closed form.
  const double A = 0.5, N = 0.3, t0 = 0.5, g = 9.81;
  const double closed_form = std::pow(A * g * t0, 2) * (1 - N / A) / (2 * g * N);
  const Scene scene = block_scene(0.2, 1.0, N, 0.5, RectangularPulse{A, t0}, 2.0);
  EXPECT_TRUE(simulate(with(scene, kFull)).rock_start_time.has_value());
  const Summary newmark = simulate(with(scene, kNewmark));
  EXPECT_NEAR(newmark.final_slide, closed_form, 1e-6);
  EXPECT_NEAR(closed_form, 0.408750, 5e-7);
  EXPECT_EQ(newmark.max_abs_theta, 0.0);
}

TEST(AutoModel, NeverChangesAResultComparedWithTheFullModel) {
  std::mt19937_64 rng(20261122);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::array<int, 4> chosen{};
  for (int i = 0; i < 600; ++i) {
    const double b = 0.5 + 2.0 * unit(rng), a = b * (0.1 + 1.4 * unit(rng));
    const double mu = 0.1 + 1.2 * unit(rng),
                 amplitude = (unit(rng) < 0.5 ? -1 : 1) * 1.5 * unit(rng);
    const double period = 0.2 + 2.0 * unit(rng);
    const GroundMotion motion = i % 3 == 0   ? GroundMotion{SinePulse{amplitude, period, 1.0}}
                                : i % 3 == 1 ? GroundMotion{CosinePulse{amplitude, period, 2.0}}
                                             : GroundMotion{RectangularPulse{amplitude, period}};
    const Scene scene = block_scene(a, b, mu, unit(rng), motion, 4.0, 1e-8);
    const Summary full = simulate(with(scene, kFull));
    const Summary automatic = simulate(scene);
    ++chosen[static_cast<std::size_t>(automatic.model)];
    SCOPED_TRACE("scene " + std::to_string(i));
    EXPECT_EQ(automatic.status, full.status);
    EXPECT_EQ(automatic.modes.size(), full.modes.size());
    expect_same_response(full, automatic, 1e-12);
  }
  // Each pruning was exercised.
  EXPECT_GT(chosen[static_cast<std::size_t>(Model::at_rest)], 20);
  EXPECT_GT(chosen[static_cast<std::size_t>(Model::newmark_sliding)], 20);
  EXPECT_GT(chosen[static_cast<std::size_t>(Model::full)], 20);
}

TEST(AutoModel, FrictionAboveThePeakGroundAccelerationDoesNotPreventSliding) {
  // Why "auto" keeps sliding for such blocks: a rocking block's friction demand includes its
  // angular terms, and its impacts slip. This slender block slides though mu > max |lambda|.
  const Scene scene = block_scene(0.15, 1.0, 0.759, 0.26, SinePulse{0.523, 1.5, 1.0}, 6.0, 1e-8);
  const Summary full = simulate(with(scene, kFull));
  EXPECT_TRUE(full.slide_start_time.has_value());
  EXPECT_EQ(simulate(scene).model, Model::full);
}

TEST(Effects, SetsThatNameNoModelAreRefused) {
  Scene scene = block_scene(0.2, 1.0, 0.5, 0.5, NoMotion{}, 1.0);
  scene.effects = {
      .automatic = false, .rocking = true, .sliding = true, .impact = false, .flight = true};
  EXPECT_THROW(simulate(scene), InvalidInput);
  scene.effects = {
      .automatic = false, .rocking = false, .sliding = true, .impact = true, .flight = false};
  EXPECT_THROW(simulate(scene), InvalidInput);
}

}  // namespace
}  // namespace blockfrag
