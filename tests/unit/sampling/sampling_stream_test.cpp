// Counter-based streams: known answers pin the generator, the key/counter layout and the
// bits-to-double map, so neither a library upgrade nor a refactoring can silently change every
// study's inputs.
#include <array>
#include <cmath>
#include <cstdint>
#include <set>

#include <Random123/philox.h>
#include <gtest/gtest.h>

#include "sampling/philox_stream.hpp"

namespace blockfrag {
namespace {

// Random123's tests/kat_vectors, the three "philox4x32 10" lines: counter (4 words), key (2 words),
// expected output (4 words).
struct KnownAnswer {
  std::array<std::uint32_t, 4> counter;
  std::array<std::uint32_t, 2> key;
  std::array<std::uint32_t, 4> expected;
};

constexpr std::array<KnownAnswer, 3> philox4x32_10_known_answers = {{
    {{0x00000000, 0x00000000, 0x00000000, 0x00000000},
     {0x00000000, 0x00000000},
     {0x6627e8d5, 0xe169c58d, 0xbc57ac4c, 0x9b00dbd8}},
    {{0xffffffff, 0xffffffff, 0xffffffff, 0xffffffff},
     {0xffffffff, 0xffffffff},
     {0x408f276d, 0x41c83b0e, 0xa20bc7c6, 0x6d5451fd}},
    {{0x243f6a88, 0x85a308d3, 0x13198a2e, 0x03707344},
     {0xa4093822, 0x299f31d0},
     {0xd16cfe09, 0x94fdcceb, 0x5001e420, 0x24126ea1}},
}};

TEST(PhiloxStream, Random123Philox4x32_10MatchesItsKnownAnswers) {
  const r123::Philox4x32_R<10> philox;
  for (const auto& answer : philox4x32_10_known_answers) {
    const r123::Philox4x32_R<10>::ctr_type counter = {
        {answer.counter[0], answer.counter[1], answer.counter[2], answer.counter[3]}};
    const r123::Philox4x32_R<10>::key_type key = {{answer.key[0], answer.key[1]}};
    const auto out = philox(counter, key);
    for (int w = 0; w < 4; ++w) EXPECT_EQ(out[w], answer.expected[w]) << "word " << w;
  }
}

TEST(PhiloxStream, BlockLaysSeedIndexStreamAndDrawOutAsDocumented) {
  // key = {seed low, seed high}, counter = {index low, index high, stream, draw}.
  for (const auto& answer : philox4x32_10_known_answers) {
    const std::uint64_t seed = (std::uint64_t{answer.key[1]} << 32) | answer.key[0];
    const std::uint64_t index = (std::uint64_t{answer.counter[1]} << 32) | answer.counter[0];
    EXPECT_EQ(philox_block(seed, answer.counter[2], index, answer.counter[3]), answer.expected);
  }
}

TEST(PhiloxStream, UniformOfKnownAnswerCountersIsPinned) {
  // (2k + 1) / 2^53 with k the top 52 bits of (out[0] << 32 | out[1]), evaluated exactly offline
  // (Python fractions) from the known-answer words above.
  EXPECT_EQ(uniform_open01(0, 0, 0, 0), 0x1.989fa35785a72p-2);  // 0.3990464708489646
  EXPECT_EQ(uniform_open01(~0ull, 0xffffffffu, ~0ull, 0xffffffffu),
            0x1.023c9db50720ep-2);  // 0.2521843568554524
  EXPECT_EQ(uniform_open01(0x299f31d0a4093822ull, 0x13198a2eu, 0x85a308d3243f6a88ull, 0x03707344u),
            0x1.a2d9fc1329fb9p-1);  // 0.8180693410295056
  EXPECT_EQ(random_bits(0, 0, 0, 0), 0x6627e8d5e169c58dull);
}

TEST(PhiloxStream, BitsMapStrictlyInsideTheUnitInterval) {
  EXPECT_EQ(open01_from_bits(0), 0x1p-53);
  EXPECT_EQ(open01_from_bits(~0ull), 1.0 - 0x1p-53);
  EXPECT_EQ(open01_from_bits(~0ull), max_open01);
  EXPECT_LT(open01_from_bits(~0ull), 1.0);
  EXPECT_EQ(open01_from_bits(0x8000'0000'0000'0000ull), 0.5 + 0x1p-53);
  // Only the top 52 bits count: the low 12 are dropped, not rounded.
  EXPECT_EQ(open01_from_bits(0xfffull), 0x1p-53);
  EXPECT_EQ(open01_from_bits(0x1000ull), 3 * 0x1p-53);
  // The set is symmetric: 1 - u is exact and is the value of the complemented bits.
  const std::uint64_t bits = 0x0123'4567'89ab'cdefull;
  EXPECT_EQ(1.0 - open01_from_bits(bits), open01_from_bits(~bits));
}

TEST(PhiloxStream, ManyDrawsAreNeverZeroOrOne) {
  for (std::uint64_t index = 0; index < 100000; ++index) {
    const double u = uniform_open01(12345, stream_id("friction"), index);
    ASSERT_GT(u, 0.0);
    ASSERT_LT(u, 1.0);
  }
}

TEST(PhiloxStream, SameArgumentsGiveBitwiseTheSameValue) {
  const double first = uniform_open01(2024, 7, 123456789, 3);
  uniform_open01(99, 1, 2, 3);  // an unrelated call in between: there is no hidden state
  EXPECT_EQ(uniform_open01(2024, 7, 123456789, 3), first);
}

TEST(PhiloxStream, ChangingAnyArgumentChangesTheValue) {
  const std::uint64_t seed = 2024;
  const std::uint32_t stream = 7;
  const std::uint64_t index = 123456789;
  const std::uint32_t draw = 3;
  const double base = uniform_open01(seed, stream, index, draw);
  EXPECT_NE(uniform_open01(seed + 1, stream, index, draw), base);
  EXPECT_NE(uniform_open01(seed ^ (1ull << 63), stream, index, draw), base);
  EXPECT_NE(uniform_open01(seed, stream + 1, index, draw), base);
  EXPECT_NE(uniform_open01(seed, stream, index + 1, draw), base);
  EXPECT_NE(uniform_open01(seed, stream, index ^ (1ull << 40), draw), base);
  EXPECT_NE(uniform_open01(seed, stream, index, draw + 1), base);
}

TEST(PhiloxStream, NeighbouringCountersGiveDistinctValues) {
  // 2^52 possible values: among 4 x 1000 draws a repeat would mean the counter is not all used.
  std::set<double> seen;
  for (std::uint64_t index = 0; index < 1000; ++index) {
    for (std::uint32_t draw = 0; draw < 2; ++draw) {
      for (std::uint32_t stream = 0; stream < 2; ++stream) {
        seen.insert(uniform_open01(1, stream, index, draw));
      }
    }
  }
  EXPECT_EQ(seen.size(), 4000u);
}

TEST(PhiloxStream, IndexBelowIsTheExactHighWordOfTheProduct) {
  __extension__ using Wide = unsigned __int128;
  const std::array<std::uint64_t, 5> all_bits = {0, 1, 0x8000'0000'0000'0000ull,
                                                 0xdead'beef'0123'4567ull, ~0ull};
  const std::array<std::uint32_t, 5> bounds = {1, 2, 3, 1000, 0xffffffffu};
  for (const std::uint64_t bits : all_bits) {
    for (const std::uint32_t n : bounds) {
      const auto expected = static_cast<std::uint32_t>((Wide{bits} * n) >> 64);
      EXPECT_EQ(index_below(bits, n), expected) << bits << " " << n;
      EXPECT_LT(index_below(bits, n), n);
    }
  }
  EXPECT_EQ(index_below(~0ull, 7), 6u);
  EXPECT_EQ(index_below(0, 7), 0u);
}

TEST(PhiloxStream, StreamIdIsFnv1a32) {
  // The FNV reference test vectors for FNV-1a, 32 bits.
  EXPECT_EQ(stream_id(""), 0x811c9dc5u);
  EXPECT_EQ(stream_id("a"), 0xe40c292cu);
  EXPECT_EQ(stream_id("foobar"), 0xbf9cf968u);
  static_assert(stream_id("a") == 0xe40c292cu, "usable as a compile-time constant");
}

}  // namespace
}  // namespace blockfrag
