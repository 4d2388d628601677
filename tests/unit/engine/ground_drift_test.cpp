#include "engine/motion/ground_drift.hpp"

#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

namespace blockfrag {
namespace {

using Shape = MotionPiece::Shape;

// The first and second integrals of lambda from t0 to t by Simpson's rule on many panels: the
// second is the integral of (t - s) lambda(s), so no nested quadrature is needed.
GroundDrift::Integrals simpson(const MotionPiece& piece, double t0, double t) {
  constexpr int kPanels = 20000;
  const double h = (t - t0) / kPanels;
  double first = 0.0, second = 0.0;
  for (int i = 0; i <= kPanels; ++i) {
    const double s = t0 + h * i;
    const double weight = (i == 0 || i == kPanels) ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0);
    const double lambda = piece.formula_value(s);
    first += weight * lambda;
    second += weight * (t - s) * lambda;
  }
  return {first * h / 3.0, second * h / 3.0};
}

std::vector<MotionPiece> every_shape() {
  return {
      MotionPiece({.shape = Shape::constant, .amplitude = 0.7}, 0.0, 5.0),
      MotionPiece({.shape = Shape::linear, .amplitude = 0.2, .origin = 0.5, .slope = -0.9}, 0.5,
                  2.0),
      MotionPiece({.shape = Shape::cosine,
                   .amplitude = 0.8,
                   .angular_frequency = std::numbers::pi,
                   .phase = 0.3},
                  0.0, 2.0),
      MotionPiece({.shape = Shape::sine, .amplitude = -0.6, .angular_frequency = 5.0}, 0.0, 3.0),
      MotionPiece(
          {.shape = Shape::ricker, .amplitude = 0.9, .angular_frequency = 4.0, .origin = 1.0}, 0.0,
          2.0),
      MotionPiece({.shape = Shape::mavroeidis_papageorgiou,
                   .amplitude = 0.5,
                   .angular_frequency = 3.0,
                   .phase = 0.4,
                   .origin = 0.2,
                   .modulation = 0.5},
                  0.2, 2.3),
  };
}

TEST(GroundDrift, IntegratesEveryShapeOfLambda) {
  for (const MotionPiece& piece : every_shape()) {
    for (const double t0 : {piece.start(), 0.5 * (piece.start() + piece.end())}) {
      const GroundDrift drift(piece, t0);
      for (const double t : {t0 + 0.01, t0 + 0.3, piece.end()}) {
        const GroundDrift::Integrals got = drift.at(t), want = simpson(piece, t0, t);
        EXPECT_NEAR(got.first, want.first, 1e-12) << static_cast<int>(piece.formula().shape);
        EXPECT_NEAR(got.second, want.second, 1e-12) << static_cast<int>(piece.formula().shape);
      }
      EXPECT_EQ(drift.at(t0).first, 0.0);
      EXPECT_EQ(drift.at(t0).second, 0.0);
    }
  }
}

TEST(GroundDrift, KeepsItsRelativePrecisionOverAShortFlight) {
  // A micro-bounce lasts microseconds: the integrals are then lambda u and lambda u^2 / 2 to first
  // order, and differences of nearly equal sines would lose most of their digits.
  for (const MotionPiece& piece : every_shape()) {
    const double t0 = 0.5 * (piece.start() + piece.end());
    const double u = (t0 + 1e-6) - t0;
    const double lambda = piece.formula_value(t0);
    const double slope = (piece.formula_value(t0 + 1e-7) - piece.formula_value(t0 - 1e-7)) / 2e-7;
    const GroundDrift::Integrals got = GroundDrift(piece, t0).at(t0 + u);
    EXPECT_NEAR(got.first, lambda * u + 0.5 * slope * u * u, 1e-10 * std::abs(lambda) * u);
    EXPECT_NEAR(got.second, 0.5 * lambda * u * u + slope * u * u * u / 6.0,
                1e-10 * std::abs(lambda) * u * u);
  }
}

// A flight that starts long before a Ricker wavelet's centre, where exp(-v0^2) is below the
// smallest double, and lasts into the wavelet: the integrals stay finite and right.
TEST(GroundDrift, AFlightFromLongBeforeARickerWaveletIntegratesIt) {
  const MotionPiece piece(
      {.shape = Shape::ricker, .amplitude = 0.9, .angular_frequency = 4.0, .origin = 10.0}, 0.0,
      20.0);
  const double t0 = 2.0;  // v0 = -32
  const GroundDrift drift(piece, t0);
  for (const double t : {8.0, 9.5, 11.0}) {
    const GroundDrift::Integrals got = drift.at(t), want = simpson(piece, t0, t);
    EXPECT_NEAR(got.first, want.first, 1e-12) << t;
    EXPECT_NEAR(got.second, want.second, 1e-12) << t;
  }
}

TEST(GroundDrift, AZeroPieceDoesNotMoveTheGround) {
  const MotionPiece zero({}, 0.0, 1.0);
  const GroundDrift::Integrals got = GroundDrift(zero, 0.2).at(0.9);
  EXPECT_EQ(got.first, 0.0);
  EXPECT_EQ(got.second, 0.0);
}

}  // namespace
}  // namespace blockfrag
