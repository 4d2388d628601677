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

// Eight entries: a pivot's Runge-Kutta step turns four new tilts (its stages and its end), and the
// step's start, turned at the last step's end, is asked for again after them (the observer's look
// at the step). A power of two, so that the ring's index wraps by a mask.
struct RecentTurns {
  static constexpr std::size_t kEntries = 8;
  static_assert(std::has_single_bit(kEntries));
  std::array<std::uint64_t, kEntries> bits{};  // theta = 0 in all at first
  std::array<SineCosine, kEntries> turns = [] {
    std::array<SineCosine, kEntries> zero_turns;
    zero_turns.fill({0.0, 1.0});
    return zero_turns;
  }();
  std::size_t next = 0;  // the entry replaced next, in turn
};

// The one cache per thread.
inline RecentTurns& recent_turns() {
  thread_local RecentTurns recent;
  return recent;
}

// Computes and remembers sine_cosine(theta) in the entry replaced next.
inline SineCosine remember_turn(RecentTurns& recent, std::uint64_t bits, double theta) {
  const std::size_t at = recent.next;
  recent.next = (at + 1) & (RecentTurns::kEntries - 1);
  recent.bits[at] = bits;
  // Returned as computed, not read back from the ring: every pivot's right-hand side takes it.
  const SineCosine turn = sine_cosine(theta);
  recent.turns[at] = turn;
  return turn;
}

}  // namespace turn_cache_detail

// sine_cosine(theta), to the bit. The entries are looked at newest first: most askers want the
// tilt last turned (a step's end, turned by its last stage).
inline SineCosine cached_turn(double theta) {
  using turn_cache_detail::RecentTurns;
  RecentTurns& recent = turn_cache_detail::recent_turns();
  const auto bits = std::bit_cast<std::uint64_t>(theta);
  for (std::size_t age = 1; age <= RecentTurns::kEntries; ++age) {
    const std::size_t i = (recent.next - age) & (RecentTurns::kEntries - 1);
    if (recent.bits[i] == bits) return recent.turns[i];
  }
  return turn_cache_detail::remember_turn(recent, bits, theta);
}

// cached_turn(theta) for a tilt not asked for before, remembered for the askers after it without
// looking for it first: a Runge-Kutta stage's (a pivot's right-hand side turns its arm to each
// stage's new tilt; its step's end is asked for again by the guards). Were it there, the entry
// added holds the same bits as the one found.
inline SineCosine fresh_turn(double theta) {
  return turn_cache_detail::remember_turn(turn_cache_detail::recent_turns(),
                                          std::bit_cast<std::uint64_t>(theta), theta);
}

}  // namespace blockfrag
