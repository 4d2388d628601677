// A block that cannot rock (mu < a/b) slides exactly as Newmark's rigid block (docs/references.md).
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "engine/simulate.hpp"
#include "tests/support/scene_builders.hpp"

namespace blockfrag {
namespace {

using testing::block_scene;
using testing::rk4;

// A stocky block (a/b = 1) so friction, not tipping, limits the motion.
Scene stocky(double mu, GroundMotion motion, double duration) {
  return block_scene(1.0, 1.0, mu, 0.5, motion, duration);
}

double newmark_rectangular(double A, double N, double t0, double g = 9.81) {
  return std::pow(A * g * t0, 2) * (1 - N / A) / (2 * g * N);
}

TEST(Newmark, RectangularPulseSlipMatchesClosedForm) {
  struct Case {
    double A, N, t0, slip, stop;
  };
  for (const Case c :
       {Case{0.5, 0.3, 0.5, 0.408750, 0.833333}, Case{1.0, 0.6, 0.2, 0.130800, 1.0 / 3}}) {
    EXPECT_NEAR(newmark_rectangular(c.A, c.N, c.t0), c.slip, 5e-7);  // the closed form itself
    for (const Scene& scene : {stocky(c.N, RectangularPulse{c.A, c.t0}, 2.0),
                               rk4(stocky(c.N, RectangularPulse{c.A, c.t0}, 2.0), 2.5e-4)}) {
      const Summary s = simulate(scene);
      EXPECT_NEAR(s.final_slide, newmark_rectangular(c.A, c.N, c.t0), 1e-6);
      EXPECT_NEAR(s.max_abs_slide, s.final_slide, 1e-9);
      EXPECT_EQ(s.max_abs_theta, 0.0);
      ASSERT_EQ(s.modes.size(), 2u);
      EXPECT_EQ(s.modes[0].mode, ModeKind::slide);
      EXPECT_EQ(s.modes[1].mode, ModeKind::rest);
      EXPECT_NEAR(s.modes[1].time, c.t0 * c.A / c.N, 1e-9);
    }
  }
}

TEST(Newmark, HalfSinePulseSlipMatchesReference) {
  // A sin(omega t) for half a period (sine_pulse, cycles = 0.5): docs/references.md values.
  struct Case {
    double A, N, omega, slip;
  };
  for (const Case c :
       {Case{0.5, 0.2, std::numbers::pi, 1.123778}, Case{1.0, 0.3, 2 * std::numbers::pi, 0.950781},
        Case{0.5, 0.45, std::numbers::pi, 0.022829}}) {
    const double period = 2 * std::numbers::pi / c.omega;
    const Summary s = simulate(stocky(c.N, SinePulse{c.A, period, 0.5}, 4.0));
    EXPECT_NEAR(s.final_slide, c.slip, 1e-6) << "A = " << c.A << " N = " << c.N;
  }
  const Summary first = simulate(stocky(0.2, SinePulse{0.5, 2.0, 0.5}, 4.0));
  ASSERT_FALSE(first.modes.empty());
  EXPECT_NEAR(first.modes.back().time, 1.656104, 1e-6);  // it comes to rest
  EXPECT_EQ(first.modes.back().mode, ModeKind::rest);
}

TEST(Newmark, OneCycleSineSlidesBothWays) {
  // Two-way sliding (docs/references.md): a positive lambda pushes the block to +x, so the episodes
  // are +0.933305 then -0.851613 m, net +0.081692 m.
  const Summary s = simulate(stocky(0.2, SinePulse{0.5, 2.0, 1.0}, 6.0));
  EXPECT_NEAR(std::abs(s.final_slide), 0.081692, 1e-6);
  EXPECT_NEAR(s.max_abs_slide, 0.933305, 1e-6);
}

}  // namespace
}  // namespace blockfrag
