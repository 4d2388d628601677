// The turn cache (engine/seat/turn_cache.hpp) gives sine_cosine's values to the bit, whichever of
// its entries holds the tilt asked for and however long ago it was turned.
#include "engine/seat/turn_cache.hpp"

#include <bit>
#include <cstdint>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "engine/sine_cosine.hpp"

namespace blockfrag {
namespace {

void expect_same_bits(SineCosine got, double theta) {
  const SineCosine want = sine_cosine(theta);
  EXPECT_EQ(std::bit_cast<std::uint64_t>(got.sin), std::bit_cast<std::uint64_t>(want.sin)) << theta;
  EXPECT_EQ(std::bit_cast<std::uint64_t>(got.cos), std::bit_cast<std::uint64_t>(want.cos)) << theta;
}

// Tilts asked for again after 0 to 11 others (within the cache's reach and beyond it), through
// both askers, in a random order: a pivot's steps ask for their start after their four stages.
TEST(TurnCache, GivesSineCosineForTiltsTurnedAnyTimeAgo) {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> tilt(-2.0, 2.0);
  std::uniform_int_distribution<int> age(0, 11);
  std::vector<double> asked;
  for (int k = 0; k < 4000; ++k) {
    const int back = age(random);
    const bool again = back < static_cast<int>(asked.size()) && k % 3 != 0;
    const double theta =
        again ? asked[asked.size() - 1 - static_cast<std::size_t>(back)] : tilt(random);
    expect_same_bits(k % 5 == 0 ? fresh_turn(theta) : cached_turn(theta), theta);
    asked.push_back(theta);
  }
}

// A step's pattern: its start turned, four new tilts after it, then its start asked for again.
TEST(TurnCache, GivesAStepsStartAfterItsFourStages) {
  const double start = 0.123456789;
  expect_same_bits(cached_turn(start), start);
  for (const double stage : {0.2, 0.3, 0.4, 0.5}) expect_same_bits(fresh_turn(stage), stage);
  expect_same_bits(cached_turn(start), start);
  expect_same_bits(cached_turn(0.5), 0.5);
  expect_same_bits(cached_turn(-0.0), -0.0);
  expect_same_bits(cached_turn(0.0), 0.0);
}

}  // namespace
}  // namespace blockfrag
