// The crack under a block: its bottom from the upstream mouth, where the reservoir enters, to the
// downstream end, where the water leaves. A block standing free has a crack through its whole
// base: on the flat ground the base edge, on a seat its outline between the outermost points
// where the seat holds it (the type B block's base and the incline next to it, folded).
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "engine/water/block_supports.hpp"
#include "engine/water/water_load.hpp"

namespace blockfrag {

struct CrackPath {
  // From the mouth to the end along the block's outline, counter-clockwise (left to right along
  // its bottom); a mouth on the end is a crack of no length, a single point.
  std::vector<Vertex> points;
  // The block's edges the crack runs along: the reservoir does not wet them
  // (engine/water/wetted_face.hpp), the crack's water presses there instead.
  std::vector<std::size_t> edges;

  double length() const;
};

// The crack of the counter-clockwise `block` from `mouth` to `end`, two points on its outline
// (each within `tolerance` of an edge; a point within `tolerance` of a vertex is that vertex).
// Throws ContractViolation for a point off the outline.
CrackPath crack_between(const WorldPolygon& block, const Vertex& mouth, const Vertex& end,
                        double tolerance);

// The crack of a block held by `supports` (not empty): from the upstream one to the downstream one.
CrackPath crack_under(const WorldPolygon& block, const std::vector<Support>& supports,
                      double tolerance);

// The same crack in another pose: each point turned by (cos, sin) about the origin, then moved by
// `shift`, into `out` (as many as body_points).
void place_crack(const std::vector<Vertex>& body_points, double cos_theta, double sin_theta,
                 const Vertex& shift, std::span<Vertex> out);

}  // namespace blockfrag
