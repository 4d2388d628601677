#include "engine/sine_cosine.hpp"

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

#include <gtest/gtest.h>

namespace blockfrag {
namespace {

// How many units in the last place of the true value (in long double) x is from it.
double ulps_from(double x, long double truth) {
  const double nearest = static_cast<double>(truth);
  const double ulp = std::nextafter(std::abs(nearest), std::numeric_limits<double>::infinity()) -
                     std::abs(nearest);
  return static_cast<double>(std::abs(static_cast<long double>(x) - truth) / ulp);
}

TEST(SineCosine, IsWithinOneAndAHalfUlpOfTheTrueValues) {
  std::mt19937_64 generator(7);
  for (const double range : {0.5, 1.6, 40.0, 9e4}) {
    std::uniform_real_distribution<double> uniform(-range, range);
    double worst = 0.0;
    for (int i = 0; i < 200000; ++i) {
      const double x = uniform(generator);
      const SineCosine got = sine_cosine(x);
      // Away from the zeros, where an absolute error of 1e-21 is many ulps of a tiny value.
      if (std::abs(std::sin(x)) > 1e-3) worst = std::max(worst, ulps_from(got.sin, sinl(x)));
      if (std::abs(std::cos(x)) > 1e-3) worst = std::max(worst, ulps_from(got.cos, cosl(x)));
      EXPECT_NEAR(got.sin, std::sin(x), 1e-16 + 4e-16 * std::abs(std::sin(x)));
      EXPECT_NEAR(got.cos, std::cos(x), 1e-16 + 4e-16 * std::abs(std::cos(x)));
    }
    EXPECT_LE(worst, 1.5) << "range " << range;
  }
}

TEST(SineCosine, KeepsTheSignOfZeroAndHandsTheRestToTheLibrary) {
  EXPECT_EQ(sine_cosine(0.0).cos, 1.0);
  EXPECT_TRUE(std::signbit(sine_cosine(-0.0).sin));
  EXPECT_FALSE(std::signbit(sine_cosine(0.0).sin));
  for (const double x : {1e6, -3e7, 1e300}) {
    EXPECT_EQ(sine_cosine(x).sin, std::sin(x));
    EXPECT_EQ(sine_cosine(x).cos, std::cos(x));
  }
  EXPECT_TRUE(std::isnan(sine_cosine(std::numeric_limits<double>::quiet_NaN()).sin));
  EXPECT_TRUE(std::isnan(sine_cosine(std::numeric_limits<double>::infinity()).cos));
}

// A pulse's lambda takes cosine() or sine() alone: the same bits as sine_cosine's, so choosing
// one changes no result.
TEST(SineCosine, CosineAndSineAloneAreSineCosinesToTheBit) {
  std::mt19937_64 generator(11);
  for (const double range : {1e-9, 0.7, 1.6, 40.0, 9e4, 1e6}) {
    std::uniform_real_distribution<double> uniform(-range, range);
    for (int i = 0; i < 100000; ++i) {
      const double x = uniform(generator);
      const SineCosine both = sine_cosine(x);
      ASSERT_EQ(std::bit_cast<std::uint64_t>(cosine(x)), std::bit_cast<std::uint64_t>(both.cos))
          << x;
      ASSERT_EQ(std::bit_cast<std::uint64_t>(sine(x)), std::bit_cast<std::uint64_t>(both.sin)) << x;
    }
  }
  EXPECT_TRUE(std::signbit(sine(-0.0)));
  EXPECT_TRUE(std::isnan(cosine(std::numeric_limits<double>::quiet_NaN())));
}

}  // namespace
}  // namespace blockfrag
