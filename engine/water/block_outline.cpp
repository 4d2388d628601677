#include "engine/water/block_outline.hpp"

#include <algorithm>

#include "engine/scene/polygon_properties.hpp"
#include "engine/scene/seat.hpp"

namespace blockfrag {

BlockOutline::BlockOutline(const Scene& scene) : rest_(scene_block_vertices(scene)) {
  centre_ = polygon_properties(rest_).centroid;
  bottom_ = rest_.front()[1];
  for (const Vertex& v : rest_) {
    body_.push_back({v[0] - centre_[0], v[1] - centre_[1]});
    bottom_ = std::min(bottom_, v[1]);
  }
  offset_ = scene.seat ? Vertex{0.0, 0.0} : Vertex{centre_[0], bottom_};
}

void BlockOutline::place(const BlockState& s, const SineCosine& turn, std::span<Vertex> out) const {
  const Vertex c = centre(s);
  for (std::size_t i = 0; i < body_.size(); ++i) out[i] = placed_vertex(i, c, turn);
}

}  // namespace blockfrag
