// Room for a placed polygon's vertices that a call keeps on its own stack: the reservoir's loads
// place the block's outline and crack at every right-hand side of its equations (~1000
// instructions a call), where a heap allocation would show, yet a polygon may have up to 10,000
// vertices (engine/scene/parameter_domains.hpp). Up to kInlineCapacity vertices (every dam block's
// outline and crack) are held inside the buffer; a bigger polygon's on the heap.
#pragma once

#include <array>
#include <cstddef>
#include <memory>
#include <span>

#include "engine/scene/polygon_properties.hpp"

namespace blockfrag {

class VertexBuffer {
 public:
  static constexpr std::size_t kInlineCapacity = 32;

  // `size` vertices, their values unset until written.
  explicit VertexBuffer(std::size_t size)
      : size_(size),
        heap_(size > kInlineCapacity ? std::make_unique_for_overwrite<Vertex[]>(size) : nullptr),
        data_(heap_ ? heap_.get() : inline_.data()) {}
  // data_ may point into the buffer itself, which a copy would not.
  VertexBuffer(const VertexBuffer&) = delete;
  VertexBuffer& operator=(const VertexBuffer&) = delete;

  std::span<Vertex> vertices() { return {data_, size_}; }
  std::span<const Vertex> vertices() const { return {data_, size_}; }

 private:
  std::size_t size_;
  std::array<Vertex, kInlineCapacity> inline_;  // left unset: the caller writes what it uses
  std::unique_ptr<Vertex[]> heap_;
  Vertex* data_;
};

}  // namespace blockfrag
