// How many trials a randomized test runs: all of them, or the share BLOCKFRAG_RANDOM_TRIALS_PERCENT
// gives (a whole percentage from 1 to 100; at least one trial). CI's sanitizer pass runs a fifth:
// instrumented, a trial is tens of times slower, and what the sanitizers look for needs the code
// paths rather than the count. A share runs the first trials of the full run (each test draws its
// trials from one seeded stream, in order).
#pragma once

#include <algorithm>
#include <charconv>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <string_view>

namespace blockfrag::testing {

inline int random_trials(int all) {
  const char* text = std::getenv("BLOCKFRAG_RANDOM_TRIALS_PERCENT");
  if (text == nullptr) return all;
  const std::string_view value(text);
  int percent = 0;
  const auto [end, error] = std::from_chars(value.data(), value.data() + value.size(), percent);
  if (error != std::errc() || end != value.data() + value.size() || percent < 1 || percent > 100) {
    throw std::invalid_argument(
        "BLOCKFRAG_RANDOM_TRIALS_PERCENT must be a whole number from 1 to "
        "100 (got \"" +
        std::string(value) + "\")");
  }
  return std::max(1, all * percent / 100);
}

}  // namespace blockfrag::testing
