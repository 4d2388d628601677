#include "engine/water/hydrostatic.hpp"

#include "engine/water/linear_pressure.hpp"

namespace blockfrag {

WaterLoad hydrostatic_load(std::span<const Vertex> polygon, const StillWater& water,
                           std::span<const std::size_t> crack_edges, const Vertex& reference) {
  const double weight = water.density * water.g;  // rho_w g, N/m^3
  WaterLoad total;
  for_each_wetted_piece(polygon, water.surface, crack_edges, [&](const WettedPiece& piece) {
    add_hydrostatic_piece(total, piece, weight, reference);
  });
  return total;
}

void add_hydrostatic_piece(WaterLoad& total, const WettedPiece& piece, double unit_weight,
                           const Vertex& reference) {
  const WaterLoad load = edge_pressure_load(piece.a, piece.b, unit_weight * piece.depth_a,
                                            unit_weight * piece.depth_b, reference);
  total.fx += load.fx;
  total.fy += load.fy;
  total.moment += load.moment;
}

}  // namespace blockfrag
