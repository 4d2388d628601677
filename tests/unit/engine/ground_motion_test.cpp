#include "engine/motion/ground_motion.hpp"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

namespace blockfrag {
namespace {

TEST(GroundMotion, PulsesFollowTheirFormulasAndStopAfterTheirWindow) {
  GroundMotionPieces cosine(CosinePulse{0.8, 2.0, 1.5});
  EXPECT_DOUBLE_EQ(cosine.lambda(0.0), 0.8);
  EXPECT_NEAR(cosine.lambda(0.5), 0.0, 1e-15);
  EXPECT_DOUBLE_EQ(cosine.lambda(1.0), -0.8);
  EXPECT_EQ(cosine.lambda(3.0), 0.0);  // 1.5 cycles of 2 s end at 3 s
  EXPECT_EQ(cosine.lambda(10.0), 0.0);

  GroundMotionPieces sine(SinePulse{-0.5, 1.0, 1.0});
  EXPECT_NEAR(sine.lambda(0.25), -0.5, 1e-15);
  EXPECT_EQ(sine.lambda(1.0), 0.0);

  GroundMotionPieces step(RectangularPulse{1.2, 0.3});
  EXPECT_EQ(step.lambda(0.0), 1.2);
  EXPECT_EQ(step.lambda(0.2999), 1.2);
  EXPECT_EQ(step.lambda(0.3), 0.0);

  EXPECT_EQ(GroundMotionPieces(NoMotion{}).lambda(1.0), 0.0);
}

TEST(GroundMotion, APieceEvaluatesItsOwnFormulaAtItsEnd) {
  // The integrator's last stage in a piece lands on the piece's end: it must see the left limit.
  GroundMotionPieces step(RectangularPulse{1.2, 0.3});
  MotionPiece& pulse = step.piece_at(0.1);
  EXPECT_EQ(pulse.end(), 0.3);
  EXPECT_EQ(pulse.lambda(0.3), 1.2);
  EXPECT_EQ(step.piece_at(0.3).lambda(0.3), 0.0);
}

TEST(GroundMotion, ExtremaAreWhereTheDerivativeVanishes) {
  GroundMotionPieces cosine(CosinePulse{1.0, 2.0, 2.0});
  const auto cos_extrema = cosine.piece_at(0.0).extrema_between(0.0, 4.0);
  ASSERT_EQ(cos_extrema.size(), 3u);  // t = 1, 2, 3 (0 and 4 are the ends)
  for (std::size_t i = 0; i < 3; ++i) EXPECT_NEAR(cos_extrema[i], 1.0 + i, 1e-15);

  GroundMotionPieces sine(SinePulse{1.0, 1.0, 1.0});
  const auto sin_extrema = sine.piece_at(0.0).extrema_between(0.1, 0.9);
  ASSERT_EQ(sin_extrema.size(), 2u);
  EXPECT_NEAR(sin_extrema[0], 0.25, 1e-15);
  EXPECT_NEAR(sin_extrema[1], 0.75, 1e-15);

  EXPECT_TRUE(
      GroundMotionPieces(RectangularPulse{1.0, 1.0}).piece_at(0.0).extrema_between(0, 1).empty());
}

}  // namespace
}  // namespace blockfrag
