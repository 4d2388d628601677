// Invariances: mirror symmetry, mass independence, Dimitrakopoulos & DeJong's similarity.
#include <cmath>
#include <limits>
#include <set>

#include <gtest/gtest.h>

#include "engine/simulate.hpp"
#include "tests/support/scene_builders.hpp"

namespace blockfrag {
namespace {

using testing::block_scene;

// Scenes that visit every mode (rest, slide, rock, slide-rock, flight; checked below), with
// impacts, overturning or not.
std::vector<Scene> varied_scenes() {
  return {block_scene(0.5, 1.0, 0.6, 0.6, CosinePulse{1.0, 2.0, 1.0}, 4.0, 1e-9),
          block_scene(0.3, 1.0, 0.8, 0.3, SinePulse{0.7, 1.0, 2.0}, 4.0, 1e-9),
          block_scene(0.5, 1.0, 0.35, 0.5, RectangularPulse{0.8, 0.4}, 2.0, 1e-9),
          block_scene(0.2, 1.5, 1.0, 0.0, CosinePulse{0.45, 0.8, 3.0}, 5.0, 1e-9)};
}

TEST(Symmetry, TheVariedScenesVisitEveryMode) {
  std::set<ModeKind> visited;
  for (const Scene& scene : varied_scenes()) {
    for (const ModeChange& change : simulate(scene).modes) visited.insert(change.mode);
  }
  for (const ModeKind mode :
       {ModeKind::rest, ModeKind::slide, ModeKind::rock, ModeKind::slide_rock, ModeKind::flight}) {
    EXPECT_TRUE(visited.contains(mode)) << mode_name(mode) << " is never visited";
  }
}

TEST(Symmetry, ReversingThePulseMirrorsThetaAndX) {
  for (const Scene& scene : varied_scenes()) {
    Scene mirrored = scene;
    std::visit(
        [](auto& m) {
          if constexpr (requires { m.amplitude_g; }) m.amplitude_g = -m.amplitude_g;
        },
        mirrored.ground_motion);
    const Summary a = simulate(scene), b = simulate(mirrored);
    EXPECT_EQ(a.overturned, b.overturned);
    EXPECT_EQ(a.impacts, b.impacts);
    EXPECT_NEAR(a.final_theta, -b.final_theta, 1e-12);
    EXPECT_NEAR(a.final_slide, -b.final_slide, 1e-12);
    EXPECT_NEAR(a.max_abs_theta, b.max_abs_theta, 1e-12);
    ASSERT_EQ(a.modes.size(), b.modes.size());
    for (std::size_t i = 0; i < a.modes.size(); ++i) {
      EXPECT_EQ(a.modes[i].mode, b.modes[i].mode);
      // Where a guard crosses zero slowly (friction margin near its extremum) rounding in its
      // value moves the located time by ~1e-10 s; the states themselves mirror to 1e-12.
      EXPECT_NEAR(a.modes[i].time, b.modes[i].time, 1e-9);
    }
  }
}

// Every positive finite mass gives the same results to the bit: the engine works per unit mass.
TEST(Invariance, ResultsDoNotDependOnTheMass) {
  const double masses[] = {std::numeric_limits<double>::denorm_min(), 1e-300, 2.5e6, 1e308,
                           std::numeric_limits<double>::max()};
  for (const Scene& scene : varied_scenes()) {
    const Summary a = simulate(scene);
    for (const double mass : masses) {
      SCOPED_TRACE(mass);
      Scene other = scene;
      other.block.mass = mass;
      const Summary b = simulate(other);
      EXPECT_EQ(b.status, Status::ok);
      EXPECT_EQ(a.overturned, b.overturned);
      EXPECT_EQ(a.impacts, b.impacts);
      EXPECT_EQ(a.steps, b.steps);
      EXPECT_EQ(a.final_theta, b.final_theta);
      EXPECT_EQ(a.final_slide, b.final_slide);
      EXPECT_EQ(a.max_abs_theta, b.max_abs_theta);
      EXPECT_EQ(a.max_contact_violation, b.max_contact_violation);
    }
  }
}

TEST(Similarity, ScaledBlocksGiveTheSameRotationInScaledTime) {
  // Lengths times k and the excitation's time axis times sqrt(k) at the same accelerations:
  // theta_k(sqrt(k) t) = theta_1(t), slips scale by k (docs/references.md, Dimitrakopoulos &
  // DeJong 2012).
  for (const Scene& base : varied_scenes()) {
    for (const double k : {0.01, 9.0}) {
      Scene scaled = base;
      scaled.block.half_width *= k;
      scaled.block.half_height *= k;
      scaled.duration = *scaled.duration * std::sqrt(k);
      std::visit(
          [k](auto& m) {
            if constexpr (requires { m.period; }) m.period *= std::sqrt(k);
            if constexpr (requires { m.duration; }) m.duration *= std::sqrt(k);
          },
          scaled.ground_motion);
      const auto a = simulate_with_history(base, 0.01);
      const auto b = simulate_with_history(scaled, 0.01 * std::sqrt(k));
      EXPECT_EQ(a.summary.overturned, b.summary.overturned);
      EXPECT_EQ(a.summary.impacts, b.summary.impacts);
      EXPECT_NEAR(a.summary.max_abs_theta, b.summary.max_abs_theta, 1e-6);
      EXPECT_NEAR(a.summary.final_theta, b.summary.final_theta, 1e-6);
      EXPECT_NEAR(a.summary.final_slide * k, b.summary.final_slide, 1e-6 * k);
      const std::size_t rows = std::min(a.history.size(), b.history.size());
      ASSERT_GT(rows, 10u);
      for (std::size_t i = 0; i < rows; ++i) {
        EXPECT_NEAR(a.history[i].theta, b.history[i].theta, 1e-6) << "row " << i;
      }
    }
  }
}

}  // namespace
}  // namespace blockfrag
