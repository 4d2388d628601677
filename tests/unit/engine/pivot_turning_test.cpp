// The dry block's turning about its pivot (engine/seat/pivot_turning.hpp) is the general formula's
// with M's added parts zero, to the bit: at arms with a signed zero, at zero loads and at
// turning rates whose square overflows, where the zeros' signs and NaN would tell them apart.
#include "engine/seat/pivot_turning.hpp"

#include <cmath>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "tests/support/same_bits.hpp"

namespace blockfrag {
namespace {

double value_or_edge(std::mt19937_64& random, double value) {
  constexpr double kEdgeInfinity = std::numeric_limits<double>::infinity();
  const double special[] = {0.0, -0.0, 5e-324, -1e-300, 1e200, -1.0, kEdgeInfinity, -kEdgeInfinity};
  return random() % 4 == 0 ? special[random() % 8] : value;
}

TEST(PivotTurning, DryIsTheGeneralFormulaWithoutAddedMass) {
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> value(-20.0, 20.0);
  for (int k = 0; k < 200000; ++k) {
    const double k2 = std::abs(value(random)) + 1e-3;
    const BodyLoad load{
        {value_or_edge(random, value(random)), value_or_edge(random, value(random))}, 0.0, k2};
    // An arm is a turned body vector: finite, its coordinates possibly a signed zero.
    const Vec2 r{random() % 4 == 0 ? -0.0 : value(random),
                 random() % 4 == 0 ? -0.0 : value(random)};
    const double omega = value_or_edge(random, value(random));
    const double general = turning_about_pivot(load, omega, r);
    const double dry = dry_turning_about_pivot(load, omega, r);
    ASSERT_TRUE(testing::same_bits(dry, general) || (std::isnan(dry) && std::isnan(general)))
        << k << ": " << dry << " vs " << general;
  }
}

}  // namespace
}  // namespace blockfrag
