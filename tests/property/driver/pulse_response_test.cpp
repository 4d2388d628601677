// Blocks under the near-fault pulses: Makris's types A and B are the one-cycle sine and cosine
// pulses by another name, and a block that cannot slide starts to rock where lambda first passes
// a/b (Shenton 1996), at the time each pulse's own formula gives.
#include <cmath>
#include <functional>
#include <numbers>

#include <gtest/gtest.h>

#include "engine/simulate.hpp"
#include "mpi_driver/io/summary_json.hpp"
#include "tests/support/paper_block.hpp"
#include "tests/support/scene_builders.hpp"

namespace blockfrag {
namespace {

using testing::block_scene;

using testing::kGravity;
using testing::pi;

TEST(PulseResponse, MakrisTypesAAndBDriveTheSameSimulationAsOneCycleSineAndCosine) {
  // Rocking, impacts and (with the low friction) sliding: the whole summary must agree.
  for (const double mu : {0.7, 0.3}) {
    for (const double amplitude : {0.6, -1.4}) {
      const Scene sine = block_scene(0.2, 0.8, mu, 0.7, SinePulse{amplitude, 0.5, 1.0}, 3.0);
      const Scene a = block_scene(0.2, 0.8, mu, 0.7, MakrisPulseA{amplitude, 0.5}, 3.0);
      const Scene cosine = block_scene(0.2, 0.8, mu, 0.7, CosinePulse{amplitude, 0.5, 1.0}, 3.0);
      const Scene b = block_scene(0.2, 0.8, mu, 0.7, MakrisPulseB{amplitude, 0.5}, 3.0);
      const Summary s_sine = simulate(sine), s_cosine = simulate(cosine);
      EXPECT_GT(s_sine.max_abs_theta + s_sine.max_abs_slide, 0.0);  // something happens
      EXPECT_EQ(summary_to_json(simulate(a)), summary_to_json(s_sine)) << mu << " " << amplitude;
      EXPECT_EQ(summary_to_json(simulate(b)), summary_to_json(s_cosine)) << mu << " " << amplitude;
    }
  }
}

// The first t in [from, to] where f(t) >= 0, with f < 0 at from: a scan fine enough for these
// pulses, then bisection to round-off.
double first_crossing(const std::function<double(double)>& f, double from, double to) {
  const double step = (to - from) / 20000;
  double a = from;
  for (double b = from + step; b <= to; b += step) {
    if (f(b) >= 0) {
      for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (a + b);
        (f(mid) >= 0 ? b : a) = mid;
      }
      return b;
    }
    a = b;
  }
  ADD_FAILURE() << "no crossing in [" << from << ", " << to << "]";
  return to;
}

// A block with a/b = beta, friction far above Shenton's critical value and e = 0: it starts to
// rock, never slides, and the first mode change is to rocking at `expected`.
void expect_rocking_onset(const GroundMotion& motion, double beta, double expected,
                          double duration) {
  const Summary s = simulate(block_scene(beta, 1.0, 10.0, 0.0, motion, duration));
  ASSERT_TRUE(s.rock_start_time.has_value());
  EXPECT_NEAR(*s.rock_start_time, expected, 1e-9);
  EXPECT_FALSE(s.slide_start_time.has_value());
  ASSERT_GE(s.modes.size(), 2u);
  EXPECT_EQ(s.modes[1].mode, ModeKind::rock);
}

TEST(PulseResponse, RockingStartsWhereEachPulseFirstExceedsTheAspectRatio) {
  const double beta = 0.25;
  {  // Makris A: A sin(w t) = beta.
    const double A = 0.5, Tp = 0.6, w = 2 * pi / Tp;
    expect_rocking_onset(MakrisPulseA{A, Tp}, beta, std::asin(beta / A) / w, 1.0);
  }
  {  // Makris B with A > beta: rocks at once.
    expect_rocking_onset(MakrisPulseB{0.5, 0.6}, beta, 0.0, 1.0);
  }
  {  // Makris C_1, solved here for its phase: 2 cos(phi) = (3 pi - 2 phi) sin(phi). It starts at
     // A cos(phi) < beta and first passes -beta on its way down, at w t + phi = arccos(-beta / A).
    double lo = 0.0, hi = pi / 2;
    for (int i = 0; i < 200; ++i) {
      const double mid = 0.5 * (lo + hi);
      (2 * std::cos(mid) > (3 * pi - 2 * mid) * std::sin(mid) ? lo : hi) = mid;
    }
    const double phi = lo, A = 0.255, Tp = 0.6, w = 2 * pi / Tp;
    ASSERT_LT(A * std::cos(phi), beta);
    expect_rocking_onset(MakrisPulseC{A, Tp, 1}, beta, (std::acos(-beta / A) - phi) / w, 1.0);
  }
  {  // Ricker with its side lobes (-0.446 A) short of -beta: the main lobe's rise passes beta where
     // (1 - 2 u^2) exp(-u^2) = beta / A, u = pi (t - t0) / Tp in (-1/sqrt(2), 0).
    const double A = 0.5, Tp = 0.5, t0 = 0.75;
    const auto rise = [&](double t) {
      const double u = pi * (t - t0) / Tp;
      return A * (1 - 2 * u * u) * std::exp(-u * u) - beta;
    };
    expect_rocking_onset(RickerWavelet{A, Tp, {}}, beta,
                         first_crossing(rise, t0 - 0.5 * Tp / pi, t0), 2.0);
  }
  {  // Mavroeidis-Papageorgiou: lambda = -v'/g from its velocity, differentiated by hand as a
     // product: v' = -(Vp Omega / 2) [k sin(k x) cos(x + nu) + (1 + cos(k x)) sin(x + nu)], x =
     // Omega (t - t0).
    const double vp = 0.3, Tp = 0.5, gamma = 2.0, nu = 0.5, t0 = 0.5 * gamma * Tp, k = 1 / gamma;
    const double omega = 2 * pi / Tp;
    const auto excess = [&](double t) {
      const double x = omega * (t - t0);
      const double lambda =
          vp * omega / (2 * kGravity) *
          (k * std::sin(k * x) * std::cos(x + nu) + (1 + std::cos(k * x)) * std::sin(x + nu));
      return std::abs(lambda) - beta;
    };
    expect_rocking_onset(MavroeidisPapageorgiouPulse{vp, Tp, gamma, nu, {}}, beta,
                         first_crossing(excess, 0.0, 2 * t0), 2.0);
  }
}

}  // namespace
}  // namespace blockfrag
