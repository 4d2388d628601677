// Numbers in messages: the shortest decimal that reads back as the same double.
#pragma once

#include <array>
#include <charconv>
#include <cmath>
#include <string>

namespace blockfrag {

// "-1", "0.3", "1e-07", "nan", "inf": independent of the locale, for messages that quote a value.
inline std::string format_number(double value) {
  // to_chars spells these "nan", "-nan", "inf"; a sign on a NaN means nothing to a reader.
  if (std::isnan(value)) return "nan";
  std::array<char, 32> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  return std::string(buffer.data(), result.ptr);
}

}  // namespace blockfrag
