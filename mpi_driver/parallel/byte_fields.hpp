// Plain values into and out of a byte string, in native byte order: the fields of blockfrag's own
// binary files (checkpoints, bisection states), which are resumed on the machine type that wrote
// them.
#pragma once

#include <cstddef>
#include <cstring>
#include <string>
#include <string_view>

namespace blockfrag::bytes {

template <typename T>
void append(std::string& out, const T& value) {
  char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  out.append(raw, sizeof(T));
}

// The caller has checked that bytes holds sizeof(T) bytes at offset.
template <typename T>
T read_at(std::string_view bytes, std::size_t offset) {
  T value;
  std::memcpy(&value, bytes.data() + offset, sizeof(T));
  return value;
}

}  // namespace blockfrag::bytes
