// sin and cos of the last few tilts asked for: a step asks for the block's vertices at the same
// tilts many times over (its ends, by its guards, its forces and its touch checks, which alternate
// between the step's start and end), and on a pivot every state's position turns its arm. One cache
// per thread serves every asker: a right-hand side's chart turns the arm at a stage's tilt and the
// contacts' poses then turn the vertices at the same tilt, which two caches computed twice.
#pragma once

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>

#include "engine/sine_cosine.hpp"

namespace blockfrag {

namespace turn_cache_detail {

struct RecentTurns {
  static constexpr std::size_t kEntries = 4;
  std::array<std::uint64_t, kEntries> bits{};  // theta = 0 in all at first
  std::array<SineCosine, kEntries> turns{{{0.0, 1.0}, {0.0, 1.0}, {0.0, 1.0}, {0.0, 1.0}}};
  std::size_t next = 0;  // the entry replaced next, in turn
};

}  // namespace turn_cache_detail

// sine_cosine(theta), to the bit.
inline SineCosine cached_turn(double theta) {
  using turn_cache_detail::RecentTurns;
  thread_local RecentTurns recent;
  const auto bits = std::bit_cast<std::uint64_t>(theta);
  for (std::size_t i = 0; i < RecentTurns::kEntries; ++i) {
    if (recent.bits[i] == bits) return recent.turns[i];
  }
  const std::size_t at = recent.next;
  recent.next = (at + 1) % RecentTurns::kEntries;
  recent.bits[at] = bits;
  recent.turns[at] = sine_cosine(theta);
  return recent.turns[at];
}

}  // namespace blockfrag
