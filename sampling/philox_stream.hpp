// Counter-based random numbers: every value is a pure function of (seed, stream, index, draw).
//
// Generator: Random123's Philox4x32-10, the bijection checked against Random123's own known-answer
// vectors in tests/unit/sampling/sampling_stream_test.cpp. One call maps
//   key     = {seed & 0xffffffff, seed >> 32}
//   counter = {index & 0xffffffff, index >> 32, stream, draw}
// to four 32-bit words out[0..3]; the first two are joined, first word high, into the 64-bit
//   bits = (out[0] << 32) | out[1]
// and out[2], out[3] are not used. Nothing is stored between calls: there is no state to seed,
// skip or share, so any rank can compute any sample in any order and get the same bits.
//
// Streams: one per random input, a small constant such as stream_id("friction"), so that adding,
// removing or reordering inputs never changes another input's numbers. Draws number the several
// random numbers one input may need for the same sample (0, 1, 2, ...). Draw values with the top
// bit set (>= reserved_draw_flag) are reserved for the designs' internal numbers (the Latin
// hypercube permutations); callers use draws below it.
#pragma once

#include <array>
#include <cstdint>
#include <string_view>

namespace blockfrag {

inline constexpr std::uint32_t reserved_draw_flag = 0x8000'0000u;

// The raw Philox4x32-10 output for the key and counter laid out as above.
std::array<std::uint32_t, 4> philox_block(std::uint64_t seed, std::uint32_t stream,
                                          std::uint64_t index, std::uint32_t draw);

// (out[0] << 32) | out[1] of philox_block.
std::uint64_t random_bits(std::uint64_t seed, std::uint32_t stream, std::uint64_t index,
                          std::uint32_t draw);

// The 52 high bits k of `bits` mapped to (k + 1/2) 2^-52 = (2k + 1) / 2^53: 2^52 equally likely,
// equally spaced values from 2^-53 to 1 - 2^-53. Every one is an exact double (53 significant
// bits, the last one always set), so the mapping involves no rounding and is bit-identical on any
// IEEE-754 machine; 0 and 1 are never returned (inverse CDFs stay finite), and the set is
// symmetric (1 - u is exact and in the set). A 53-bit version, (k + 1/2) 2^-53, would need 54
// significant bits near 1 and round its largest value to exactly 1.0: this is Random123's
// u01fixedpt_open_open_64_double, written out so the constants are visible.
constexpr double open01_from_bits(std::uint64_t bits) {
  constexpr double two_to_minus_52 = 0x1p-52;
  return (static_cast<double>(bits >> 12) + 0.5) * two_to_minus_52;
}

// The largest value open01_from_bits returns, 1 - 2^-53.
inline constexpr double max_open01 = 1.0 - 0x1p-53;

// A uniform double strictly inside (0, 1): open01_from_bits(random_bits(...)).
double uniform_open01(std::uint64_t seed, std::uint32_t stream, std::uint64_t index,
                      std::uint32_t draw = 0);

// floor(bits n / 2^64), an integer in [0, n) with no loop and no floating point (the multiply-shift
// map). Each value has probability within n / 2^64 of 1/n: the bias is far below anything a study
// can resolve, and unlike rejection sampling the cost is the same for every draw.
constexpr std::uint32_t index_below(std::uint64_t bits, std::uint32_t n) {
  // bits n = (high 2^32 + low) n; both partial products fit in 64 bits since n < 2^32.
  const std::uint64_t high = (bits >> 32) * n;
  const std::uint64_t low = (bits & 0xffff'ffffu) * n;
  return static_cast<std::uint32_t>((high + (low >> 32)) >> 32);
}

// FNV-1a, 32-bit (offset basis 2166136261, prime 16777619) of the name's bytes: a stream id that
// depends only on the name. Two names can collide (about one chance in 2^32 per pair), which
// would silently correlate two inputs, so a plan refuses names whose ids coincide.
constexpr std::uint32_t stream_id(std::string_view name) {
  std::uint32_t hash = 2166136261u;
  for (const char c : name) {
    hash ^= static_cast<unsigned char>(c);
    hash *= 16777619u;
  }
  return hash;
}

}  // namespace blockfrag
