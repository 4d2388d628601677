// Comparing doubles to the bit: the tests of shortcuts that must give the general path's results
// exactly (+0 and -0 differ; a NaN equals only a NaN of its own bits).
#pragma once

#include <bit>
#include <cstdint>

namespace blockfrag::testing {

inline std::uint64_t bits_of(double x) { return std::bit_cast<std::uint64_t>(x); }

inline bool same_bits(double a, double b) { return bits_of(a) == bits_of(b); }

}  // namespace blockfrag::testing
