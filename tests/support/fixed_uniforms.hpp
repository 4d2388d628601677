// A fixed-seed source of uniforms that is the same on every platform, for randomized tests:
// std::mt19937_64's output sequence is fixed by the standard (unlike the
// std::*_distribution classes), its top 53 bits map to [0, 1) exactly.
#pragma once

#include <cstdint>
#include <random>

namespace blockfrag::testing {

class FixedUniforms {
 public:
  explicit FixedUniforms(std::uint64_t seed) : bits_(seed) {}
  double operator()(double lo, double hi) {
    return lo + (hi - lo) * static_cast<double>(bits_() >> 11) * 0x1p-53;
  }

 private:
  std::mt19937_64 bits_;
};

}  // namespace blockfrag::testing
