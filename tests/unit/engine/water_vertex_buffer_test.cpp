// The room for a placed polygon (engine/water/vertex_buffer.hpp): up to its inline capacity the
// vertices are inside the buffer itself (no allocation at a right-hand side), beyond it on the
// heap, and either way it holds what is written to it.
#include <cstddef>
#include <span>

#include <gtest/gtest.h>

#include "engine/water/vertex_buffer.hpp"

namespace blockfrag {
namespace {

bool inside(const VertexBuffer& buffer) {
  const auto* first = reinterpret_cast<const std::byte*>(&buffer);
  const auto* vertices = reinterpret_cast<const std::byte*>(buffer.vertices().data());
  return vertices >= first && vertices < first + sizeof(VertexBuffer);
}

// Writes vertex i as (i, -2 i) and reads every one back.
void expect_holds_what_is_written(VertexBuffer& buffer) {
  const std::span<Vertex> vertices = buffer.vertices();
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    vertices[i] = {static_cast<double>(i), -2.0 * static_cast<double>(i)};
  }
  const VertexBuffer& read = buffer;
  for (std::size_t i = 0; i < read.vertices().size(); ++i) {
    EXPECT_EQ(read.vertices()[i][0], static_cast<double>(i));
    EXPECT_EQ(read.vertices()[i][1], -2.0 * static_cast<double>(i));
  }
}

TEST(WaterVertexBuffer, AnOrdinaryBlocksVerticesStayInside) {
  for (const std::size_t size : {std::size_t{0}, std::size_t{4}, VertexBuffer::kInlineCapacity}) {
    VertexBuffer buffer(size);
    EXPECT_EQ(buffer.vertices().size(), size);
    EXPECT_TRUE(inside(buffer)) << size;
    expect_holds_what_is_written(buffer);
  }
}

TEST(WaterVertexBuffer, ABiggerPolygonsVerticesGoToTheHeap) {
  for (const std::size_t size : {VertexBuffer::kInlineCapacity + 1, std::size_t{10'000}}) {
    VertexBuffer buffer(size);
    EXPECT_EQ(buffer.vertices().size(), size);
    EXPECT_FALSE(inside(buffer)) << size;
    expect_holds_what_is_written(buffer);
  }
}

}  // namespace
}  // namespace blockfrag
