// The live guards a watch follows: set_indices reads a watch's flags eight at a time, and must
// name exactly the guards one pass over the flags names, in the same order.
#include <array>
#include <cstddef>
#include <vector>

#include <gtest/gtest.h>

#include "engine/integrate/guard_crossing.hpp"
#include "tests/support/fixed_uniforms.hpp"

namespace blockfrag {
namespace {

template <std::size_t G>
std::vector<int> true_flags_one_by_one(const std::array<bool, G>& flags) {
  std::vector<int> found;
  for (std::size_t i = 0; i < G; ++i) {
    if (flags[i]) found.push_back(static_cast<int>(i));
  }
  return found;
}

template <std::size_t G>
std::vector<int> true_flags_by_words(const std::array<bool, G>& flags) {
  std::array<int, G> out{};
  const int count = set_indices(flags, out);
  return {out.begin(), out.begin() + count};
}

// Every density of flags, including none and all, over a seat's 64 slots and over sizes that
// leave a tail shorter than a word.
template <std::size_t G>
void expect_same_indices_as_one_pass(testing::FixedUniforms& u) {
  for (int trial = 0; trial < 2000; ++trial) {
    const double live = static_cast<double>(trial % 11) / 10.0;
    std::array<bool, G> flags;
    for (bool& flag : flags) flag = u(0.0, 1.0) < live;
    ASSERT_EQ(true_flags_by_words(flags), true_flags_one_by_one(flags)) << "G " << G;
  }
}

TEST(GuardWatchLive, NamesTheTrueFlagsInOrderAsOnePassDoes) {
  testing::FixedUniforms u(20261207);
  expect_same_indices_as_one_pass<64>(u);
  expect_same_indices_as_one_pass<13>(u);
  expect_same_indices_as_one_pass<5>(u);
  expect_same_indices_as_one_pass<1>(u);
}

TEST(GuardWatchLive, EachSlotAloneIsNamed) {
  for (std::size_t i = 0; i < 64; ++i) {
    std::array<bool, 64> flags{};
    flags[i] = true;
    EXPECT_EQ(true_flags_by_words(flags), std::vector<int>{static_cast<int>(i)}) << i;
  }
}

}  // namespace
}  // namespace blockfrag
