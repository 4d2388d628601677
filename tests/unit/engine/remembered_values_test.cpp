// The values the engine remembers (a piece's last lambda, a geometry's last rotation, a motion's
// last piece) are the ones computed anew, to the bit, whatever order they are asked for in.
#include <cstddef>
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "engine/motion/ground_motion.hpp"
#include "engine/scene/block_geometry.hpp"
#include "engine/sine_cosine.hpp"
#include "tests/support/fixed_uniforms.hpp"
#include "tests/support/same_bits.hpp"

namespace blockfrag {
namespace {

using testing::same_bits;

// Times or angles as a step asks for them: fresh ones, the last one again, one from before, and
// +0 right after -0 (equal as doubles, not as bits).
std::vector<double> asked(double lo, double hi, std::uint64_t seed) {
  testing::FixedUniforms u(seed);
  std::vector<double> xs = {-0.0, 0.0, -0.0, 0.0, 0.0};
  for (int n = 0; n < 400; ++n) {
    const double x = u(lo, hi);
    xs.push_back(x);
    if (n % 3 == 0) xs.push_back(x);
    if (n % 5 == 0) xs.push_back(xs[xs.size() / 2]);
    if (n % 7 == 0) xs.insert(xs.end(), {-0.0, 0.0});
  }
  return xs;
}

TEST(RememberedValues, APiecesLambdaIsItsFormulasValue) {
  // A linear piece of value -0 at t = 0: lambda(-0) is -0 and lambda(+0) is +0.
  MotionPiece linear{
      {.shape = MotionPiece::Shape::linear, .amplitude = -0.0, .slope = 0.7}, 0.0, 5.0};
  MotionPiece cosine{{MotionPiece::Shape::cosine, 0.4, 2.3, 0.2}, 0.0, 5.0};
  ASSERT_FALSE(same_bits(linear.formula_value(-0.0), linear.formula_value(0.0)));
  int compared = 0;
  for (MotionPiece* piece : {&linear, &cosine}) {
    for (const double t : asked(-1.0, 5.0, 4701)) {
      ASSERT_TRUE(same_bits(piece->lambda(t), piece->formula_value(t))) << t;
      ++compared;
    }
  }
  EXPECT_GT(compared, 1000);
}

TEST(RememberedValues, AGeometrysRotationIsTheSineAndCosineOfItsAngle) {
  BlockGeometry geometry{PolygonBlock{{{-0.6, -1.0}, {0.5, -1.1}, {0.4, 0.9}, {-0.5, 1.2}}, 1.0}};
  ASSERT_FALSE(same_bits(sine_cosine(-0.0).sin, sine_cosine(0.0).sin));
  for (const double theta : asked(-1.5, 1.5, 4702)) {
    const SineCosine turn = sine_cosine(theta);
    const Rotation rotation = geometry.rotation(theta);
    ASSERT_TRUE(same_bits(rotation.cos, turn.cos)) << theta;
    ASSERT_TRUE(same_bits(rotation.sin, turn.sin)) << theta;
    for (int i = 0; i < geometry.corner_count(); ++i) {
      const Vec2 turned = rotate(geometry.corner(i), turn.cos, turn.sin);
      const Vec2 corner = geometry.corner_at(i, theta);
      ASSERT_TRUE(same_bits(corner.x, turned.x) && same_bits(corner.y, turned.y)) << theta;
    }
  }
}

// The first piece with t < end, by a plain scan.
std::size_t scanned_piece(const std::vector<MotionPiece>& pieces, double t) {
  std::size_t k = 0;
  while (!(t < pieces[k].end())) ++k;
  return k;
}

TEST(RememberedValues, AMotionsPieceIsTheFirstThatEndsAfterTheTime) {
  // A record with a jump (1.0 twice) and short pieces, asked forwards, backwards and at random.
  GroundMotionPieces motion({0.0, 0.1, 0.3, 1.0, 1.0, 1.05, 2.0, 2.5},
                            {0.0, 0.2, -0.1, 0.4, -0.3, 0.1, 0.5, 0.0});
  const std::vector<MotionPiece>& pieces = motion.pieces();
  std::vector<double> times = asked(-0.5, 3.0, 4703);
  for (double t = 0.0; t < 3.0; t += 0.0125) times.push_back(t);
  for (double t = 3.0; t > -0.5; t -= 0.0125) times.push_back(t);
  times.insert(times.end(), {1.0, 0.3, 0.3, 1.05, 0.1, 2.5, 0.0, 2.5});
  for (const double t : times) {
    const std::size_t k = scanned_piece(pieces, t);
    ASSERT_EQ(&motion.piece_at(t), &pieces[k]) << t;
    ASSERT_TRUE(same_bits(motion.lambda(t), pieces[k].formula_value(t))) << t;
  }
}

}  // namespace
}  // namespace blockfrag
