// sin and cos of the last two tilts asked for: a step asks for the block's vertices at the same
// tilts many times over (its ends, by its guards, its forces and its touch checks, which alternate
// between the step's start and end), and on a pivot every state's position turns its arm.
#pragma once

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>

#include "engine/sine_cosine.hpp"

namespace blockfrag {

class TurnCache {
 public:
  SineCosine operator()(double theta) const {
    const auto bits = std::bit_cast<std::uint64_t>(theta);
    for (std::size_t i = 0; i < kEntries; ++i) {
      if (bits_[i] == bits) return turns_[i];
    }
    older_ = 1 - older_;
    bits_[older_] = bits;
    turns_[older_] = sine_cosine(theta);
    return turns_[older_];
  }

 private:
  static constexpr std::size_t kEntries = 2;
  mutable std::array<std::uint64_t, kEntries> bits_{0, 0};  // theta = 0 in both at first
  mutable std::array<SineCosine, kEntries> turns_{sine_cosine(0.0), sine_cosine(0.0)};
  mutable std::size_t older_ = 0;
};

}  // namespace blockfrag
