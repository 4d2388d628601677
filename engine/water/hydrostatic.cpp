#include "engine/water/hydrostatic.hpp"

#include "engine/water/linear_pressure.hpp"
#include "engine/water/wetted_face.hpp"

namespace blockfrag {

WaterLoad hydrostatic_load(const WorldPolygon& polygon, const StillWater& water,
                           std::span<const std::size_t> crack_edges, const Vertex& reference) {
  const double weight = water.density * water.g;  // rho_w g, N/m^3
  WaterLoad total;
  for_each_wetted_piece(polygon, water.surface, crack_edges, [&](const WettedPiece& piece) {
    const WaterLoad load = edge_pressure_load(piece.a, piece.b, weight * piece.depth_a,
                                              weight * piece.depth_b, reference);
    total.fx += load.fx;
    total.fy += load.fy;
    total.moment += load.moment;
  });
  return total;
}

}  // namespace blockfrag
