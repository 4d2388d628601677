// The reservoir's hydrostatic push on a block: the pressure rho_w g (y_w - y) integrated exactly
// over the wetted upstream face (engine/water/wetted_face.hpp) at the block's current pose. The
// pressure is linear along each wetted piece, so each piece's resultant has a closed form
// (engine/water/linear_pressure.hpp); an inclined or polyline face gets its vertical component.
// For a vertical face wetted to depth d the push is 1/2 rho_w g d^2 at d/3 above the face's
// foot (USACE EM 1110-2-2200, 1995, Gravity Dam Design).
#pragma once

#include <cstddef>
#include <span>

#include "engine/water/linear_pressure.hpp"
#include "engine/water/water_load.hpp"
#include "engine/water/wetted_face.hpp"

namespace blockfrag {

// The force and its moment about `reference` (the block's centre of mass in the world frame).
// `crack_edges`: the edge indices the reservoir does not wet (the crack's: see wetted_face.hpp).
WaterLoad hydrostatic_load(std::span<const Vertex> polygon, const StillWater& water,
                           std::span<const std::size_t> crack_edges, const Vertex& reference);

// One wetted piece's push and moment added to `total`; `unit_weight` rho_w g.
inline void add_hydrostatic_piece(WaterLoad& total, const WettedPiece& piece, double unit_weight,
                                  const Vertex& reference) {
  const WaterLoad load = edge_pressure_load(piece.a, piece.b, unit_weight * piece.depth_a,
                                            unit_weight * piece.depth_b, reference);
  total.fx += load.fx;
  total.fy += load.fy;
  total.moment += load.moment;
}

}  // namespace blockfrag
