// Free rocking with a rocking restitution r (engine/contact/rocking_restitution.hpp), on the flat
// ground and on a flat seat: each half-cycle's peak against the exact amplitude map, energy at
// r = 1, and Housner's value against the scene without the key.
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "engine/scene/block_geometry.hpp"
#include "engine/simulate.hpp"
#include "tests/support/scene_builders.hpp"

namespace blockfrag {
namespace {

using testing::block_scene;

// A block of alpha = 0.25 rad and R = 1 m released from rest at 0.9 alpha onto its right corner,
// mu = 2 (the landing corner sticks at r = 0.5: mu >= (1 - r) / ((1 + r) tan alpha) = 1.31),
// e = 0.3 (which rocking impacts do not use).
constexpr double kDecayAlpha = 0.25;
constexpr double kDecayTheta0 = 0.9 * kDecayAlpha;

Scene free_rocking_with(std::optional<RockingRestitution> rocking, bool on_seat, double e = 0.3) {
  const double a = std::sin(kDecayAlpha), b = std::cos(kDecayAlpha);
  Scene scene = block_scene(a, b, 2.0, e, NoMotion{}, 10.0, 1e-12);
  scene.contact.rocking_restitution = rocking;
  scene.initial.theta = -kDecayTheta0;
  if (on_seat) scene.seat = Seat{{{-5.0, -b}, {5.0, -b}}};
  return scene;
}

// The next peak from a peak theta_n of a rectangle: energy about the pivot is conserved between
// impacts, g R (cos(alpha - theta_n) - cos alpha) = I_O omega-^2 / (2 M) at the impact, omega+ =
// r omega-, and the same about the other corner, equally far from the centre of mass, up to
// theta_n+1.
double next_peak(double theta_n, double r) {
  const double ca = std::cos(kDecayAlpha);
  return kDecayAlpha - std::acos(ca + r * r * (std::cos(kDecayAlpha - theta_n) - ca));
}

// |theta|'s peak in each half-cycle: the release tilt, then between each two impacts the largest
// sample with the parabola through it and its neighbours (the history is dense output, its error
// far below the parabola's, O(dt^3) at a smooth maximum).
std::vector<double> half_cycle_peaks(const SimulationWithHistory& run) {
  std::vector<double> peaks = {kDecayTheta0};
  for (std::size_t k = 0; k + 1 < run.impacts.size(); ++k) {
    const double from = run.impacts[k].time, to = run.impacts[k + 1].time;
    std::size_t top = 0;
    for (std::size_t i = 1; i + 1 < run.history.size(); ++i) {
      const double t = run.history[i].t;
      if (t <= from || t >= to) continue;
      if (top == 0 || std::abs(run.history[i].theta) > std::abs(run.history[top].theta)) top = i;
    }
    if (top == 0) break;
    const double y0 = std::abs(run.history[top - 1].theta), y1 = std::abs(run.history[top].theta),
                 y2 = std::abs(run.history[top + 1].theta);
    // Too short a half-cycle to hold a sample on both sides of its peak: the map ends here.
    if (run.history[top - 1].t <= from || run.history[top + 1].t >= to) break;
    peaks.push_back(y1 - (y2 - y0) * (y2 - y0) / (8.0 * (y2 - 2.0 * y1 + y0)));
  }
  return peaks;
}

struct DecayCase {
  const char* name;
  std::optional<double> r;  // none: "housner"
  bool on_seat;
};

class RockingRestitutionDecay : public ::testing::TestWithParam<DecayCase> {};

TEST_P(RockingRestitutionDecay, EachHalfCyclesPeakFollowsTheExactAmplitudeMap) {
  const DecayCase c = GetParam();
  const double housner = 1.0 - 1.5 * std::sin(kDecayAlpha) * std::sin(kDecayAlpha);
  const double r = c.r.value_or(housner);
  const RockingRestitution rocking =
      c.r ? RockingRestitution{false, *c.r} : RockingRestitution{true, 1.0};
  const auto run = simulate_with_history(free_rocking_with(rocking, c.on_seat), 1e-3);
  ASSERT_EQ(run.summary.status, Status::ok);
  const std::vector<double> peaks = half_cycle_peaks(run);
  ASSERT_GE(peaks.size(), 4u);
  for (std::size_t n = 1; n < peaks.size() && peaks[n] > 1e-4; ++n) {
    // The peaks agree with the map to about 1e-12 rad (the solver's tolerance).
    EXPECT_NEAR(peaks[n], next_peak(peaks[n - 1], r), 1e-10) << "half-cycle " << n;
  }
  // Every rocking impact leaves turning about the other corner at r omega- (or less where r omega-
  // would add energy, which a rectangle never needs).
  for (const ImpactRecord& impact : run.impacts) {
    if (std::abs(impact.omega_before) < 1e-3) break;  // the settling impacts lay the block flat
    EXPECT_NEAR(impact.omega_after / impact.omega_before, r, 1e-9) << "t = " << impact.time;
    EXPECT_EQ(impact.mode_after, ModeKind::rock);
  }
}

INSTANTIATE_TEST_SUITE_P(
    FlatGroundAndSeat, RockingRestitutionDecay,
    ::testing::Values(DecayCase{"flat_r0.5", 0.5, false}, DecayCase{"flat_r0.9", 0.9, false},
                      DecayCase{"flat_r1", 1.0, false}, DecayCase{"flat_housner", {}, false},
                      DecayCase{"seat_r0.5", 0.5, true}, DecayCase{"seat_r0.9", 0.9, true},
                      DecayCase{"seat_r1", 1.0, true}, DecayCase{"seat_housner", {}, true}),
    [](const ::testing::TestParamInfo<DecayCase>& decay_case) {
      std::string name = decay_case.param.name;
      for (char& ch : name) {
        if (ch == '.') ch = '_';
      }
      return name;
    });

class RockingRestitutionOfOne : public ::testing::TestWithParam<bool> {};

TEST_P(RockingRestitutionOfOne, ConservesTheEnergy) {
  const double g = 9.81, k2 = 1.0 / 3.0;  // I/M of a rectangle of R = 1
  const auto run =
      simulate_with_history(free_rocking_with(RockingRestitution{false, 1.0}, GetParam()), 1e-3);
  ASSERT_GE(run.impacts.size(), 3u);
  for (const ImpactRecord& impact : run.impacts) {
    EXPECT_NEAR(impact.kinetic_energy_after / impact.kinetic_energy_before, 1.0, 1e-12);
  }
  EXPECT_LE(run.summary.max_impact_energy_gain, 1e-12);
  const double start = g * run.history.front().y;
  for (const HistoryRow& row : run.history) {
    const double energy =
        0.5 * (row.vx * row.vx + row.vy * row.vy + k2 * row.omega * row.omega) + g * row.y;
    EXPECT_NEAR(energy / start - 1.0, 0.0, 1e-9) << "t = " << row.t;
  }
}

INSTANTIATE_TEST_SUITE_P(FlatGroundAndSeat, RockingRestitutionOfOne, ::testing::Bool());

// A polygon whose base corners lie at different distances from the centre of mass, rocking at
// r = 1: onto its nearer corner (the left one, landing while it turns counter-clockwise) the energy
// falls to I_near / I_far of itself (I about each corner), onto the farther one r omega- would
// raise it by I_far / I_near and the block keeps its energy instead. No impact gains energy.
TEST_P(RockingRestitutionOfOne, KeepsALopsidedPolygonsEnergyAtMost) {
  Scene scene = free_rocking_with(RockingRestitution{false, 1.0}, false);
  scene.polygon = PolygonBlock{{{0.0, 0.0}, {1.0, 0.0}, {0.3, 2.0}, {0.0, 2.0}}, 1.0};
  scene.initial.theta = -0.1;
  if (GetParam()) scene.seat = Seat{{{-5.0, 0.0}, {6.0, 0.0}}};
  const BlockGeometry geometry(*scene.polygon);
  const auto about = [&](Corner c) {
    const Vec2 r = geometry.base_corner(c);
    return geometry.inertia_per_mass() + r.x * r.x + r.y * r.y;
  };
  const double i_near = about(Corner::left), i_far = about(Corner::right);
  ASSERT_LT(i_near, 0.9 * i_far);
  const auto run = simulate_with_history(scene, 1e-3);
  ASSERT_GE(run.impacts.size(), 4u);
  for (const ImpactRecord& impact : run.impacts) {
    if (std::abs(impact.omega_before) < 1e-3) break;
    const bool onto_near = impact.omega_before > 0.0;
    EXPECT_NEAR(impact.kinetic_energy_after / impact.kinetic_energy_before,
                onto_near ? i_near / i_far : 1.0, 1e-12)
        << "t = " << impact.time;
    EXPECT_NEAR(impact.omega_after / impact.omega_before,
                onto_near ? 1.0 : std::sqrt(i_near / i_far), 1e-12);
  }
  EXPECT_LE(run.summary.max_impact_energy_gain, 1e-12);
}

bool same_runs(const SimulationWithHistory& x, const SimulationWithHistory& y) {
  const Summary &a = x.summary, &b = y.summary;
  bool same = a.impacts == b.impacts && a.events == b.events && a.steps == b.steps &&
              a.max_abs_theta == b.max_abs_theta && a.final_theta == b.final_theta &&
              a.final_slide == b.final_slide && a.end_time == b.end_time &&
              a.settle_time == b.settle_time && x.history.size() == y.history.size();
  for (std::size_t i = 0; same && i < x.history.size(); ++i) {
    const HistoryRow &p = x.history[i], &q = y.history[i];
    same = p.t == q.t && p.x == q.x && p.y == q.y && p.theta == q.theta && p.vx == q.vx &&
           p.vy == q.vy && p.omega == q.omega;
  }
  return same;
}

class HousnersRockingRestitution : public ::testing::TestWithParam<bool> {};

// Housner's value is the plastic sticking impulse at the landing corner, the law a scene without
// the key applies at e = 0: the same results to the bit. With it, e does not reach the rocking
// impacts, the only impacts of free rocking: e = 0.3 gives the same results too (without the key
// it throws the block into a flight at each).
TEST_P(HousnersRockingRestitution, GivesTheResultsOfThePlasticImpactToTheBit) {
  const bool on_seat = GetParam();
  const auto without = simulate_with_history(free_rocking_with(std::nullopt, on_seat, 0.0), 1e-3);
  ASSERT_GE(without.summary.impacts, 5);
  const RockingRestitution housner{true, 1.0};
  EXPECT_TRUE(
      same_runs(without, simulate_with_history(free_rocking_with(housner, on_seat, 0.0), 1e-3)));
  EXPECT_TRUE(
      same_runs(without, simulate_with_history(free_rocking_with(housner, on_seat, 0.3), 1e-3)));
}

INSTANTIATE_TEST_SUITE_P(FlatGroundAndSeat, HousnersRockingRestitution, ::testing::Bool());

// Housner's one-degree-of-freedom model takes a given r too.
TEST(HousnersModelWithARockingRestitution, LeavesEachImpactAtRTimesOmega) {
  Scene scene = free_rocking_with(RockingRestitution{false, 0.7}, false);
  scene.effects = {
      .automatic = false, .rocking = true, .sliding = false, .impact = true, .flight = false};
  const auto run = simulate_with_history(scene, 1e-3);
  ASSERT_EQ(run.summary.model, Model::housner_rocking);
  ASSERT_GE(run.impacts.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_NEAR(run.impacts[k].omega_after / run.impacts[k].omega_before, 0.7, 1e-12);
  }
}

}  // namespace
}  // namespace blockfrag
