// The dam as a filter: its steady-state amplification of a harmonic foundation motion against the
// damped oscillator's transfer functions (at resonance 1/(2 zeta) for the pseudo-acceleration and
// sqrt(1 + 4 zeta^2)/(2 zeta) for the absolute acceleration; far below resonance the crest moves
// with the foundation), and the block on the crest: a stiff dam is no dam, a resonant one rocks a
// block the foundation alone leaves standing, from the instant Housner's criterion says.
#include <algorithm>
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "engine/motion/dam_crest.hpp"
#include "engine/simulate.hpp"
#include "tests/support/paper_block.hpp"
#include "tests/support/scene_builders.hpp"

namespace blockfrag {
namespace {

using testing::kGravity;
using testing::pi;

DamCrest dam_with(double period, double zeta) {
  DamCrest dam;
  dam.stiffness = DamPeriod{period};
  dam.damping = zeta;
  return dam;
}

// |pseudo-acceleration| / |a_g| and |absolute acceleration| / |a_g| of the steady state at
// frequency ratio r (Chopra, Dynamics of Structures, sections 3.2 and 3.6).
double pseudo_ratio(double r, double zeta) { return 1.0 / std::hypot(1 - r * r, 2 * zeta * r); }
double absolute_ratio(double r, double zeta) {
  return std::hypot(1.0, 2 * zeta * r) / std::hypot(1 - r * r, 2 * zeta * r);
}

struct SteadyState {
  double pseudo_peak;    // max omega^2 |q| over the last cycles, / |a_g| amplitude
  double absolute_peak;  // max |crest lambda| over the last cycles, / |lambda_g| amplitude
  double pseudo_exact;   // omega^2 sqrt(q^2 + (q'/omega_g)^2) at the end, / |a_g| amplitude
};

// A sine of the given period on a dam of period 1, run until the transient has decayed to e^-16 of
// its start (zeta omega t = 16), measured over the last three excitation cycles.
SteadyState steady_state(double excitation_period, double zeta) {
  const double dam_period = 1.0, omega = 2 * pi / dam_period;
  const double omega_g = 2 * pi / excitation_period, lambda = 0.1;
  const double cycles = std::ceil(16.0 / (zeta * omega) / excitation_period) + 3.0;
  const double duration = cycles * excitation_period;
  const GroundMotionPieces foundation(SinePulse{lambda, excitation_period, cycles});
  const CrestHistory h =
      dam_crest_history(foundation, dam_with(dam_period, zeta), duration, kGravity);
  SteadyState s{0, 0, 0};
  for (std::size_t i = 0; i < h.times.size(); ++i) {
    if (h.times[i] < duration - 3 * excitation_period) continue;
    s.pseudo_peak =
        std::max(s.pseudo_peak, omega * omega * std::abs(h.modal[i].q) / (lambda * kGravity));
    s.absolute_peak = std::max(s.absolute_peak, std::abs(h.crest_lambda[i]) / lambda);
  }
  // In the steady state q is a sinusoid at omega_g: its amplitude is sqrt(q^2 + (q'/omega_g)^2).
  const OscillatorState end = h.modal.back();
  s.pseudo_exact = omega * omega * std::hypot(end.q, end.v / omega_g) / (lambda * kGravity);
  return s;
}

// Nodes every period / 100 sample a peak within 1 - cos(pi / 100) = 4.9e-4 of it.
constexpr double kPeakSampling = 1e-3;

TEST(DamCrestResponse, AmplificationAtResonanceIsOneOverTwoZeta) {
  for (const double zeta : {0.02, 0.05, 0.1}) {
    const SteadyState s = steady_state(1.0, zeta);
    const double pseudo = 1 / (2 * zeta), absolute = std::sqrt(1 + 4 * zeta * zeta) / (2 * zeta);
    // The filter is exact for the foundation drawn linearly between nodes h = T / 100 apart,
    // whose fundamental is the sine's times sinc^2(omega h / 2) = 1 - 3.3e-4 (the chords lie
    // inside the curve): the response at resonance is that much below 1/(2 zeta), and no more.
    const double x = pi / 100, chords = std::pow(std::sin(x) / x, 2);
    EXPECT_NEAR(s.pseudo_exact, chords * pseudo, 1e-6 * pseudo) << "zeta " << zeta;
    EXPECT_NEAR(s.pseudo_exact, pseudo, 5e-4 * pseudo) << "zeta " << zeta;
    EXPECT_NEAR(s.pseudo_peak, pseudo, kPeakSampling * pseudo) << "zeta " << zeta;
    EXPECT_LE(s.pseudo_peak, pseudo * (1 + 1e-6)) << "zeta " << zeta;  // samples never overshoot
    EXPECT_NEAR(s.absolute_peak, absolute, kPeakSampling * absolute) << "zeta " << zeta;
    // The same numbers through the general transfer functions at r = 1.
    EXPECT_NEAR(pseudo_ratio(1.0, zeta), pseudo, 1e-12);
    EXPECT_NEAR(absolute_ratio(1.0, zeta), absolute, 1e-12);
  }
}

TEST(DamCrestResponse, FarBelowResonanceTheCrestMovesWithTheFoundation) {
  const double zeta = 0.05, r = 1.0 / 50.0;  // excitation period 50 times the dam's
  const SteadyState s = steady_state(1.0 / r, zeta);
  EXPECT_NEAR(s.absolute_peak, absolute_ratio(r, zeta), 1e-5);
  EXPECT_NEAR(s.pseudo_exact, pseudo_ratio(r, zeta), 1e-6);
  EXPECT_NEAR(s.absolute_peak, 1.0, 1e-3);
}

TEST(DamCrestResponse, AboveResonanceTheCrestIsIsolated) {
  const double zeta = 0.05, r = 3.0;
  const SteadyState s = steady_state(1.0 / r, zeta);
  EXPECT_NEAR(s.absolute_peak, absolute_ratio(r, zeta), kPeakSampling * absolute_ratio(r, zeta));
  EXPECT_LT(s.absolute_peak, 0.2);
}

// A slender block on stiff friction: it rocks when |lambda| first exceeds a/b (Housner).
Scene rocking_scene(GroundMotion motion, double duration) {
  return testing::block_scene(0.15, 0.6, 0.9, 0.9, motion, duration, 1e-9);
}

TEST(DamCrestResponse, AStiffDamIsNoDam) {
  // A one-cycle sine of 1 s that rocks the block hard without overturning it, and one of 2 s that
  // overturns a larger block. A 0.01 s dam is rigid for both: the crest follows the foundation to
  // (T_dam / T_g)^2 = 1e-4, and the ringing started by the sine's initial slope (T_dam / T_g of
  // it) has decayed to 2e-5 by the onset. Measured: max |theta| differs by 0.46% at 0.01 s and
  // by 0.0045% at 0.001 s (the (T_dam / T_g)^2 convergence; 0.001 s costs 10 times more to run).
  const double stiff = 0.01;
  {
    const Scene bare = rocking_scene(SinePulse{0.3, 1.0, 1.0}, 2.5);
    Scene on_dam = bare;
    on_dam.dam = dam_with(stiff, 0.05);
    const Summary a = simulate(bare), b = simulate(on_dam);
    ASSERT_EQ(a.status, Status::ok);
    ASSERT_EQ(b.status, Status::ok);
    ASSERT_TRUE(a.rock_start_time.has_value());
    ASSERT_TRUE(b.rock_start_time.has_value());
    EXPECT_FALSE(a.overturned);
    EXPECT_FALSE(b.overturned);
    EXPECT_GT(a.max_abs_theta, 0.1);
    EXPECT_NEAR(b.max_abs_theta, a.max_abs_theta, 0.01 * a.max_abs_theta);
    EXPECT_NEAR(*b.rock_start_time, *a.rock_start_time, 1e-4);
  }
  {
    const Scene bare =
        testing::block_scene(0.3, 1.2, 0.9, 0.9, SinePulse{0.3, 2.0, 1.0}, 5.0, 1e-9);
    Scene on_dam = bare;
    on_dam.dam = dam_with(stiff, 0.05);
    const Summary a = simulate(bare), b = simulate(on_dam);
    ASSERT_TRUE(a.overturned);
    ASSERT_TRUE(b.overturned);
    ASSERT_TRUE(a.overturn_time.has_value());
    ASSERT_TRUE(b.overturn_time.has_value());
    ASSERT_TRUE(a.rock_start_time.has_value());
    ASSERT_TRUE(b.rock_start_time.has_value());
    EXPECT_NEAR(*b.overturn_time, *a.overturn_time, 0.01 * *a.overturn_time);
    EXPECT_NEAR(*b.rock_start_time, *a.rock_start_time, 1e-4);
  }
}

TEST(DamCrestResponse, AResonantDamRocksABlockTheFoundationLeavesStanding) {
  // 0.2 g < a/b = 0.25: on the foundation the block never rocks (and mu = 0.9 > 0.2: never
  // slides). Twelve cycles at the dam's own period build the crest up toward 1/(2 zeta) = 10 times.
  const double period = 0.25, tan_alpha = 0.15 / 0.6;
  const SinePulse sine{0.2, period, 12.0};
  const Scene bare = rocking_scene(sine, 4.0);
  Scene on_dam = bare;
  on_dam.dam = dam_with(period, 0.05);
  const Summary a = simulate(bare), b = simulate(on_dam);
  ASSERT_EQ(a.status, Status::ok);
  ASSERT_EQ(b.status, Status::ok);
  EXPECT_FALSE(a.rock_start_time.has_value());
  EXPECT_EQ(a.max_abs_theta, 0.0);
  ASSERT_TRUE(b.rock_start_time.has_value());
  // The crest's 4 Hz motion is fast for this block (omega / p = 7): it rocks, to 0.114 rad, about
  // half its alpha, where the foundation's motion leaves it standing.
  EXPECT_GT(b.max_abs_theta, 0.25 * std::atan(tan_alpha)) << "max |theta| " << b.max_abs_theta;
  // Housner's onset on the crest's motion: the first time |lambda_crest| reaches a/b.
  const GroundMotionPieces crest =
      dam_crest_motion(GroundMotionPieces(sine), *on_dam.dam, 4.0, kGravity);
  double onset = -1;
  for (const MotionPiece& piece : crest.pieces()) {
    const double l0 = piece.formula_value(piece.start()), l1 = piece.formula_value(piece.end());
    if (std::max(std::abs(l0), std::abs(l1)) < tan_alpha) continue;
    const double target = std::copysign(tan_alpha, std::abs(l1) >= tan_alpha ? l1 : l0);
    onset = piece.start() + (target - l0) / (l1 - l0) * (piece.end() - piece.start());
    break;
  }
  ASSERT_GT(onset, 0.0);
  EXPECT_NEAR(*b.rock_start_time, onset, 1e-6);
}

}  // namespace
}  // namespace blockfrag
