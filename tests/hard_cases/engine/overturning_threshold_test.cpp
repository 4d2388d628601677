// Amplitudes just below and above the overturning threshold of a rectangular pulse: the verdict
// flips once, at the nonlinear threshold of docs/references.md, for both integrators.
#include <cmath>

#include <gtest/gtest.h>

#include "engine/simulate.hpp"
#include "tests/support/scene_builders.hpp"

namespace blockfrag {
namespace {

using testing::block_scene;
using testing::housner_p;
using testing::rk4;

struct Threshold {
  double p_t1;     // pulse length in units of 1/p
  double psi_tan;  // threshold amplitude over tan(alpha), nonlinear rocking
};

class RectangularPulseThreshold : public ::testing::TestWithParam<std::tuple<Threshold, Method>> {};

TEST_P(RectangularPulseThreshold, VerdictFlipsOnceAtTheNonlinearThreshold) {
  // Copies, not structured bindings: clang 14 cannot capture those in the lambda below.
  const Threshold threshold = std::get<0>(GetParam());
  const Method method = std::get<1>(GetParam());
  const double a = 0.5, b = 1.0, beta = a / b, p = housner_p(a, b);
  const double t1 = threshold.p_t1 / p;
  // mu high enough for pure rocking at these amplitudes; a long run lets a late overturn show.
  const auto overturns = [&](double psi) {
    Scene scene = block_scene(a, b, 5.0, 0.0, RectangularPulse{psi * beta, t1}, t1 + 6.0);
    if (method == Method::rk4) scene = rk4(scene, 2.5e-4);
    return simulate(scene).overturned;
  };
  int flips = 0;
  bool previous = overturns(threshold.psi_tan * 0.98);
  EXPECT_FALSE(previous);
  for (int k = -19; k <= 20; ++k) {
    const bool now = overturns(threshold.psi_tan * (1 + 0.001 * k));
    flips += now != previous;
    previous = now;
  }
  EXPECT_EQ(flips, 1);
  EXPECT_TRUE(previous);
  // Bisect the flip and compare with the reference (6 printed digits).
  double lo = threshold.psi_tan * 0.99, hi = threshold.psi_tan * 1.01;
  for (int i = 0; i < 30; ++i) {
    const double mid = 0.5 * (lo + hi);
    (overturns(mid) ? hi : lo) = mid;
  }
  const double tolerance = method == Method::rk4 ? 2e-5 : 2e-6;
  EXPECT_NEAR(0.5 * (lo + hi) / threshold.psi_tan, 1.0, tolerance);
}

INSTANTIATE_TEST_SUITE_P(References, RectangularPulseThreshold,
                         ::testing::Combine(::testing::Values(Threshold{0.5, 2.564527},
                                                              Threshold{1.0, 1.583046},
                                                              Threshold{2.0, 1.151926}),
                                            ::testing::Values(Method::adaptive, Method::rk4)));

}  // namespace
}  // namespace blockfrag
