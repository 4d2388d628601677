// The block's outline at a pose (engine/scene/block_state.hpp) in the scene's frame, where the
// reservoir's level is given: a polygon's vertices as given, a rectangle's about its centre, a
// seat's points. A seat's BlockState holds the centre of mass in that frame; the flat ground's
// holds its slide from where it started and its height above the ground, whose y is the block's
// lowest vertex at rest.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "engine/scene/block_state.hpp"
#include "engine/sine_cosine.hpp"
#include "engine/water/water_load.hpp"

namespace blockfrag {

class BlockOutline {
 public:
  explicit BlockOutline(const Scene& scene);

  // The vertices at rest, counter-clockwise, in the scene's frame.
  const std::vector<Vertex>& rest() const { return rest_; }
  // The vertices about the centre of mass, unturned.
  const std::vector<Vertex>& body() const { return body_; }
  Vertex rest_centre() const { return centre_; }
  // The lowest y of the block at rest: the flat ground's height.
  double rest_bottom() const { return bottom_; }

  // The pose at rest (unturned, on its ground).
  BlockState rest_state() const {
    BlockState s;
    s.x = centre_[0] - offset_[0];
    s.y = centre_[1] - offset_[1];
    return s;
  }
  // The centre of mass at pose s, in the scene's frame.
  Vertex centre(const BlockState& s) const { return {offset_[0] + s.x, offset_[1] + s.y}; }
  // The vertices at pose s into `out` (as many as body()), s.theta's sine and cosine given: the
  // caller turns more than the outline.
  void place(const BlockState& s, const SineCosine& turn, std::span<Vertex> out) const;
  // Vertex i at the pose whose centre of mass is `centre`, to place()'s bits.
  Vertex placed_vertex(std::size_t i, const Vertex& centre, const SineCosine& turn) const {
    const Vertex& p = body_[i];
    return {centre[0] + p[0] * turn.cos - p[1] * turn.sin,
            centre[1] + p[0] * turn.sin + p[1] * turn.cos};
  }

 private:
  std::vector<Vertex> rest_, body_;
  Vertex centre_;
  double bottom_;
  Vertex offset_;  // the scene-frame point BlockState's (0, 0) is
};

}  // namespace blockfrag
