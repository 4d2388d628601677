// The near-fault pulses as pieces: each lambda against its formula written out here, the Makris
// C_n pulse's return to rest, the Mavroeidis-Papageorgiou acceleration against its velocity, and
// the extrema the rest mode relies on.
#include "engine/motion/pulse_shapes.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <vector>

#include <gsl/gsl_integration.h>
#include <gtest/gtest.h>

#include "engine/motion/ground_motion.hpp"
#include "tests/support/paper_block.hpp"

namespace blockfrag {
namespace {

using testing::kGravity;
using testing::pi;

// integral of f over [a, b]: 20-point Gauss-Legendre on 400 panels, exact to round-off for the
// smooth integrands here.
double integrate(const std::function<double(double)>& f, double a, double b) {
  gsl_integration_glfixed_table* table = gsl_integration_glfixed_table_alloc(20);
  const int panels = 400;
  double sum = 0.0;
  for (int i = 0; i < panels; ++i) {
    const double lo = a + (b - a) * i / panels, hi = a + (b - a) * (i + 1) / panels;
    gsl_function F{[](double x, void* p) {
                     return (*static_cast<const std::function<double(double)>*>(p))(x);
                   },
                   const_cast<std::function<double(double)>*>(&f)};
    sum += gsl_integration_glfixed(&F, lo, hi, table);
  }
  gsl_integration_glfixed_table_free(table);
  return sum;
}

TEST(PulseShapes, MakrisTypesAAndBAreOneSineAndOneCosineOfAcceleration) {
  const double A = 0.7, Tp = 0.8, w = 2 * pi / Tp;
  GroundMotionPieces a(MakrisPulseA{A, Tp}, kGravity), b(MakrisPulseB{-A, Tp}, kGravity);
  for (const double t : {0.0, 0.1, 0.2, 0.37, 0.6, 0.79}) {
    EXPECT_NEAR(a.lambda(t), A * std::sin(w * t), 1e-15) << t;
    EXPECT_NEAR(b.lambda(t), -A * std::cos(w * t), 1e-15) << t;
  }
  EXPECT_NEAR(a.lambda(0.2), A, 1e-15);  // the quarter period: lambda's peak is amplitude_g
  for (const double t : {0.8, 0.81, 5.0}) {
    EXPECT_EQ(a.lambda(t), 0.0);
    EXPECT_EQ(b.lambda(t), 0.0);
  }
}

TEST(PulseShapes, MakrisPhaseSolvesTheZeroDisplacementEquation) {
  for (const int n : {1, 2, 3, 5, 10}) {
    const double phi = pulse::makris_c_phase(n);
    EXPECT_GT(phi, 0.0);
    EXPECT_LT(phi, pi / 2);
    EXPECT_NEAR(2 * std::cos(phi), ((2 * n + 1) * pi - 2 * phi) * std::sin(phi), 1e-14) << n;
  }
  // Makris & Roussos (2000) give phi = 0.0697 pi for the C1 pulse.
  EXPECT_NEAR(pulse::makris_c_phase(1) / pi, 0.0697, 5e-5);
}

TEST(PulseShapes, MakrisTypeCReturnsTheGroundToRest) {
  const double A = 1.3, Tp = 0.6, w = 2 * pi / Tp;
  for (const int n : {1, 2, 4}) {
    GroundMotionPieces c(MakrisPulseC{A, Tp, n}, kGravity);
    const double phi = pulse::makris_c_phase(n);
    const double end = c.pieces().front().end();
    EXPECT_NEAR(end, (n + 0.5 - phi / pi) * Tp, 1e-14);
    for (const double t : {0.0, 0.05, 0.31, 0.5 * end, end - 1e-3}) {
      EXPECT_NEAR(c.lambda(t), A * std::cos(w * t + phi), 1e-14) << t;
    }
    EXPECT_EQ(c.lambda(end), 0.0);
    EXPECT_EQ(c.lambda(end + 1.0), 0.0);
    // Ground velocity -g integral lambda and displacement -g integral (end - s) lambda(s) ds (the
    // twice-repeated integral), in m/s and m; the pulse's own scale is A g Tp / (2 pi) ~ 1.2 m/s.
    const auto lambda = [&](double s) { return c.pieces().front().formula_value(s); };
    const double velocity = -kGravity * integrate(lambda, 0.0, end);
    const double displacement =
        -kGravity * integrate([&](double s) { return (end - s) * lambda(s); }, 0.0, end);
    EXPECT_NEAR(velocity, 0.0, 1e-12) << n;
    EXPECT_NEAR(displacement, 0.0, 1e-12) << n;
    // Not zero by accident: halfway through, the ground is moving.
    EXPECT_GT(std::abs(integrate(lambda, 0.0, 0.25 * Tp)), 0.1 * A * Tp / (2 * pi));
  }
}

TEST(PulseShapes, RickerWaveletFollowsItsFormulaInsideItsWindow) {
  const double A = -0.9, Tp = 0.5;
  const RickerWavelet wavelet{A, Tp, {}};
  GroundMotionPieces r(wavelet, kGravity);
  const double t0 = 1.5 * Tp;  // the documented default
  EXPECT_EQ(wavelet.center(), t0);
  const auto formula = [&](double t) {
    const double u = pi * (t - t0) / Tp;
    return A * (1 - 2 * u * u) * std::exp(-u * u);
  };
  for (const double t : {0.0, 0.3, 0.7, 0.75, 0.8, 1.1, 1.49})
    EXPECT_NEAR(r.lambda(t), formula(t), 1e-15) << t;
  EXPECT_DOUBLE_EQ(r.lambda(t0), A);
  // The default centre cuts tails below 1e-6 A (the brief) at both ends of [0, 2 t0].
  EXPECT_LT(std::abs(r.lambda(0.0)), 1e-6 * std::abs(A));
  EXPECT_LT(std::abs(r.pieces().front().formula_value(2 * t0)), 1e-6 * std::abs(A));
  EXPECT_EQ(r.lambda(2 * t0), 0.0);
  EXPECT_EQ(r.lambda(3.0), 0.0);
  // A centre given explicitly moves the window with it.
  GroundMotionPieces late(RickerWavelet{A, Tp, 2.0}, kGravity);
  EXPECT_DOUBLE_EQ(late.lambda(2.0), A);
  EXPECT_EQ(late.lambda(4.0), 0.0);
}

TEST(PulseShapes, RickerExtremaAreAtTheCentreAndItsSideLobes) {
  const double Tp = 0.5, t0 = 0.75, side = std::sqrt(1.5) * Tp / pi;
  const GroundMotionPieces wavelet(RickerWavelet{1.0, Tp, {}}, kGravity);
  const MotionPiece& piece = wavelet.pieces().front();
  const auto extrema = piece.extrema_between(0.0, 1.5);
  ASSERT_EQ(extrema.size(), 3u);
  EXPECT_NEAR(extrema[0], t0 - side, 1e-15);
  EXPECT_NEAR(extrema[1], t0, 1e-15);
  EXPECT_NEAR(extrema[2], t0 + side, 1e-15);
  EXPECT_NEAR(piece.formula_value(extrema[0]), -2 * std::exp(-1.5),
              1e-15);                                 // the side lobes' depth
  const auto right = piece.extrema_between(t0, 1.5);  // an end is not interior
  ASSERT_EQ(right.size(), 1u);
  EXPECT_NEAR(right[0], t0 + side, 1e-15);
  EXPECT_EQ(piece.max_abs_lambda(), 1.0);
  EXPECT_EQ(piece.time_scale(), Tp);
}

// v(t) written out from Mavroeidis & Papageorgiou's formula, independently of the engine's sines.
struct MpVelocity {
  double vp, tp, gamma, nu, t0;
  double operator()(double t) const {
    const double fp = 1.0 / tp, tau = t - t0;
    if (std::abs(tau) > gamma / (2 * fp)) return 0.0;
    return 0.5 * vp * (1 + std::cos(2 * pi * fp * tau / gamma)) * std::cos(2 * pi * fp * tau + nu);
  }
};

TEST(PulseShapes, MavroeidisPapageorgiouAccelerationIsTheVelocitysDerivative) {
  const MpVelocity v{0.8, 0.9, 2.3, 0.7, 1.5};
  GroundMotionPieces mp(MavroeidisPapageorgiouPulse{v.vp, v.tp, v.gamma, v.nu, v.t0}, kGravity);
  const double start = v.t0 - v.gamma * v.tp / 2, end = v.t0 + v.gamma * v.tp / 2;
  ASSERT_EQ(mp.pieces().size(), 3u);  // rest, the pulse, rest forever
  EXPECT_NEAR(mp.pieces()[0].end(), start, 1e-15);
  EXPECT_NEAR(mp.pieces()[1].end(), end, 1e-15);
  const double h = 1e-5;
  double peak = 0.0;
  for (double t = start + 0.01; t < end - 0.01; t += 0.0371) {
    const double a = (v(t + h) - v(t - h)) / (2 * h);  // central difference, error ~ h^2 v''' / 6
    EXPECT_NEAR(mp.lambda(t), -a / kGravity, 1e-9) << t;
    peak = std::max(peak, std::abs(a / kGravity));
  }
  EXPECT_GT(peak, 0.1);  // the comparison is not between zeros
  for (const double t : {0.0, start - 1e-9, end, end + 0.5}) EXPECT_EQ(mp.lambda(t), 0.0) << t;
  // Its acceleration integrates back to v(t) (-g lambda from the start).
  const auto lambda = [&](double s) { return mp.pieces()[1].formula_value(s); };
  for (const double t : {start + 0.2, v.t0, v.t0 + 0.33, end}) {
    EXPECT_NEAR(-kGravity * integrate(lambda, start, t), v(t), 1e-12) << t;
  }
}

TEST(PulseShapes, MavroeidisPapageorgiouStartsAtZeroByDefault) {
  GroundMotionPieces mp(MavroeidisPapageorgiouPulse{1.0, 1.0, 3.0, 0.0, {}}, kGravity);
  ASSERT_EQ(mp.pieces().size(), 2u);  // no rest before the pulse
  EXPECT_NEAR(mp.pieces()[0].end(), 3.0, 1e-15);
  // Both ends are smooth: the envelope and its slope vanish there.
  EXPECT_NEAR(mp.lambda(0.0), 0.0, 1e-15);
  EXPECT_NEAR(mp.pieces()[0].formula_value(3.0), 0.0, 1e-15);
}

// Every extremum of lambda on a fine grid (a sign change of its finite-difference slope) must be
// near a reported one, every reported one must have a vanishing slope, and the bounds must hold.
void expect_extrema_found(const MotionPiece& piece, double t0, double t1, std::size_t at_least) {
  const auto found = piece.extrema_between(t0, t1);
  const double step = (t1 - t0) / 200000;
  std::size_t grid_extrema = 0;
  double peak = 0.0;
  double previous = piece.formula_value(t0 + step) - piece.formula_value(t0);
  for (double t = t0 + step; t + step < t1; t += step) {
    peak = std::max(peak, std::abs(piece.formula_value(t)));
    const double slope = piece.formula_value(t + step) - piece.formula_value(t);
    if ((slope > 0) != (previous > 0)) {
      ++grid_extrema;
      const bool near = std::any_of(found.begin(), found.end(),
                                    [&](double x) { return std::abs(x - t) < 2 * step; });
      EXPECT_TRUE(near) << "missed the extremum near t = " << t;
    }
    previous = slope;
  }
  EXPECT_GE(grid_extrema, at_least);
  EXPECT_EQ(found.size(), grid_extrema);
  const double scale = piece.max_abs_lambda() / piece.time_scale();
  for (const double x : found) {
    const double h = 1e-6 * piece.time_scale();
    EXPECT_NEAR((piece.formula_value(x + h) - piece.formula_value(x - h)) / (2 * h), 0.0,
                1e-6 * scale)
        << x;
  }
  EXPECT_GE(piece.max_abs_lambda(), peak);
}

TEST(PulseShapes, MavroeidisPapageorgiouExtremaAreAllFound) {
  for (const double gamma : {1.1, 1.5, 2.0, 3.0, 6.0}) {
    for (const double nu : {0.0, 0.9, pi / 2, 2.5}) {
      SCOPED_TRACE(::testing::Message() << "gamma " << gamma << " nu " << nu);
      const MavroeidisPapageorgiouPulse pulse{0.5, 0.7, gamma, nu, {}};
      const GroundMotionPieces pieces(pulse, kGravity);
      const MotionPiece& piece = pieces.pieces().front();
      // Roughly two extrema per carrier period over the gamma periods of the envelope.
      expect_extrema_found(piece, 0.0, gamma * 0.7, static_cast<std::size_t>(gamma));
    }
  }
}

TEST(PulseShapes, ZeroSearchFindsTwoZerosInsideOneCell) {
  // (t - 0.3)(t - 0.3 - 1e-4): no sign change at any cell end of width 1/64, yet two zeros.
  const auto f = [](double t) { return (t - 0.3) * (t - 0.3 - 1e-4); };
  const auto zeros = pulse::zeros_between(f, 2.0, 0.0, 1.0, 1.0 / 64, 1e-9);
  ASSERT_EQ(zeros.size(), 2u);
  EXPECT_NEAR(zeros[0], 0.3, 1e-15);
  EXPECT_NEAR(zeros[1], 0.3001, 1e-15);
  EXPECT_TRUE(
      pulse::zeros_between([](double t) { return 1.0 + t; }, 1.0, 0.0, 1.0, 0.1, 1e-9).empty());
}

TEST(PulseShapes, PeakLambdaIsTheLargestValueOverAllPieces) {
  EXPECT_NEAR(GroundMotionPieces(RickerWavelet{-0.4, 1.0, {}}, kGravity).peak_abs_lambda(), 0.4,
              1e-15);
  EXPECT_NEAR(GroundMotionPieces(MakrisPulseC{0.6, 1.0, 2}, kGravity).peak_abs_lambda(), 0.6,
              1e-15);
  // nu = pi/2, gamma large: at tau = 0 the three sines add to 2 (Vp Omega / (2 g)).
  const double vp = 0.3, omega = 2 * pi / 0.5;
  EXPECT_NEAR(GroundMotionPieces(MavroeidisPapageorgiouPulse{vp, 0.5, 5.0, pi / 2, {}}, kGravity)
                  .peak_abs_lambda(),
              vp * omega / kGravity, 1e-12);
}

}  // namespace
}  // namespace blockfrag
