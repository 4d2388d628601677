#include "sampling/philox_stream.hpp"

#include <Random123/philox.h>

namespace blockfrag {

std::array<std::uint32_t, 4> philox_block(std::uint64_t seed, std::uint32_t stream,
                                          std::uint64_t index, std::uint32_t draw) {
  const r123::Philox4x32_R<10> philox;
  const r123::Philox4x32_R<10>::key_type key = {
      {static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32)}};
  const r123::Philox4x32_R<10>::ctr_type counter = {
      {static_cast<std::uint32_t>(index), static_cast<std::uint32_t>(index >> 32), stream, draw}};
  const auto out = philox(counter, key);
  return {out[0], out[1], out[2], out[3]};
}

std::uint64_t random_bits(std::uint64_t seed, std::uint32_t stream, std::uint64_t index,
                          std::uint32_t draw) {
  const auto out = philox_block(seed, stream, index, draw);
  return (static_cast<std::uint64_t>(out[0]) << 32) | out[1];
}

double uniform_open01(std::uint64_t seed, std::uint32_t stream, std::uint64_t index,
                      std::uint32_t draw) {
  return open01_from_bits(random_bits(seed, stream, index, draw));
}

}  // namespace blockfrag
