// The part of a block the reservoir wets: the edges whose outward normal points upstream (n_x < 0,
// the reservoir being at smaller x), below the water surface, each clipped where it crosses the
// surface. The crack's edges (the block's base on flat ground, the edges resting on a seat), named
// by the caller, are never wetted by the reservoir whatever their normal: the water there is the
// uplift's (engine/water/uplift.hpp), and a base tilted upstream by a hair would otherwise take the
// reservoir's full pressure on its whole length. Edges facing straight up or down (n_x = 0) are
// dry. The rule reads the normals alone: a face turned upstream on the block's dry downstream side
// would be wetted (blockfrag's dam blocks have none), and a submerged face whose normal turns
// through the vertical as the block tilts gains or loses its load at once (their upstream faces
// are vertical, and the tops above the water).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <span>

#include "engine/water/water_load.hpp"

namespace blockfrag {

// One wetted piece of an edge, in the edge's direction (so the edge's normal is its normal too).
struct WettedPiece {
  Vertex a, b;
  Vertex edge;              // the whole edge's end less its start
  double depth_a, depth_b;  // below the surface, m, >= 0

  // The edge's outward unit normal: a counter-clockwise polygon's is (dy, -dx) / length. Found on
  // demand: the loads of a pressure along the edge need no length
  // (engine/water/linear_pressure.hpp).
  Vertex outward() const {
    const double length = std::sqrt(edge[0] * edge[0] + edge[1] * edge[1]);
    return {edge[1] / length, -edge[0] / length};
  }
};

// Calls on_cut(const WettedPiece&) with the wetted piece of the polygon's edge from a to b if the
// surface cuts the edge (the piece's depth_a is zero), on_whole(const WettedPiece&) if the edge is
// wetted whole (depth_a > 0: a lies below the surface). Either piece's b is at least as deep as
// its a: the edge descends to b, and a depth, the surface less a height, falls as the height
// rises, rounded or not.
template <class OnCut, class OnWhole>
void visit_wetted_edge_parts(const Vertex& a, const Vertex& b, double surface, OnCut&& on_cut,
                             OnWhole&& on_whole) {
  const double dx = b[0] - a[0], dy = b[1] - a[1];
  // The outward normal (dy, -dx) / length has n_x < 0 on a descending edge, whose end b is its
  // lowest point.
  if (!(dy < 0.0) || !(b[1] < surface)) return;
  WettedPiece piece{a, b, {dx, dy}, surface - a[1], surface - b[1]};
  if (!(a[1] < surface)) {  // the edge crosses the surface: its wetted part starts there
    const double t = (surface - a[1]) / dy;
    piece.a = {a[0] + t * dx, surface};
    piece.depth_a = 0.0;
    on_cut(piece);
    return;
  }
  on_whole(piece);
}

// Calls visit(const WettedPiece&) with the wetted piece of the polygon's edge from a to b, if it
// has one.
template <class Visit>
void visit_wetted_edge(const Vertex& a, const Vertex& b, double surface, Visit&& visit) {
  visit_wetted_edge_parts(a, b, surface, visit, visit);
}

// Calls visit(const WettedPiece&) for each wetted piece of the counter-clockwise polygon. A surface
// at or below the polygon's lowest point wets nothing.
template <class Visit>
void for_each_wetted_piece(std::span<const Vertex> polygon, double surface,
                           std::span<const std::size_t> crack_edges, Visit&& visit) {
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (std::find(crack_edges.begin(), crack_edges.end(), i) != crack_edges.end()) continue;
    visit_wetted_edge(polygon[i], polygon[i + 1 < n ? i + 1 : 0], surface, visit);
  }
}

}  // namespace blockfrag
