// The JSON names of an enum's values: one list that the reader's choices, its "must be one of"
// message and the canonical writer all take, so a value named in one is named in all.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string_view>

namespace blockfrag {

template <class Enum, std::size_t N>
struct EnumNames {
  std::array<Enum, N> values;
  std::array<std::string_view, N> names;  // in the order the refusal lists them

  constexpr std::string_view name(Enum value) const {
    for (std::size_t i = 0; i < N; ++i) {
      if (values[i] == value) return names[i];
    }
    return "unknown";
  }
  constexpr std::optional<Enum> value(std::string_view name) const {
    for (std::size_t i = 0; i < N; ++i) {
      if (names[i] == name) return values[i];
    }
    return std::nullopt;
  }
};

}  // namespace blockfrag
