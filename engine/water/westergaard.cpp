#include "engine/water/westergaard.hpp"

#include <algorithm>
#include <cmath>

#include "engine/errors.hpp"
#include "engine/water/wetted_face.hpp"

namespace blockfrag {

namespace {

// The antiderivatives in the depth u of sqrt(u), sqrt(u) (Z - u) and sqrt(u) (Z - u)^2.
AddedMass depth_antiderivatives(double u, double z) {
  const double u32 = u * std::sqrt(u), u52 = u32 * u, u72 = u52 * u;
  return {2.0 / 3.0 * u32, 2.0 / 3.0 * z * u32 - 2.0 / 5.0 * u52,
          2.0 / 3.0 * z * z * u32 - 4.0 / 5.0 * z * u52 + 2.0 / 7.0 * u72};
}

}  // namespace

AddedMass westergaard_added_mass(const WorldPolygon& polygon, double surface, double density,
                                 double reservoir_depth, std::span<const std::size_t> crack_edges,
                                 double reference_y) {
  if (!(reservoir_depth > 0.0)) {
    throw ContractViolation("westergaard_added_mass: the reservoir's depth must be > 0");
  }
  const double scale = 7.0 / 8.0 * density * std::sqrt(reservoir_depth);
  const double z = surface - reference_y;  // the surface's height above the reference
  AddedMass total;
  for_each_wetted_piece(polygon, surface, crack_edges, [&](const WettedPiece& piece) {
    // Over the piece's projected height, from its shallow end to its deep end.
    const AddedMass shallow = depth_antiderivatives(std::min(piece.depth_a, piece.depth_b), z);
    const AddedMass deep = depth_antiderivatives(std::max(piece.depth_a, piece.depth_b), z);
    total.mass += scale * (deep.mass - shallow.mass);
    total.first_moment += scale * (deep.first_moment - shallow.first_moment);
    total.second_moment += scale * (deep.second_moment - shallow.second_moment);
  });
  return total;
}

}  // namespace blockfrag
