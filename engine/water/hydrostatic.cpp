#include "engine/water/hydrostatic.hpp"

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

}  // namespace blockfrag
