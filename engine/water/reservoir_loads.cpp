#include "engine/water/reservoir_loads.hpp"

#include <algorithm>

#include "engine/errors.hpp"
#include "engine/scene/block_geometry.hpp"
#include "engine/sine_cosine.hpp"
#include "engine/tolerances.hpp"
#include "engine/water/hydrostatic.hpp"

namespace blockfrag {

CrackPath rest_crack(const Scene& scene, const BlockOutline& outline) {
  const double tolerance = kContactHeight * scene_geometry(scene).size();
  const std::vector<Support> supports =
      scene_supports(scene, outline.rest_bottom(), outline.rest(), tolerance);
  if (supports.empty())
    throw ContractViolation("rest_crack: the block does not rest on its ground");
  return crack_under(outline.rest(), supports, tolerance);
}

ReservoirLoads::ReservoirLoads(const Scene& scene)
    : reservoir_(scene.reservoir.value()), g_(scene.g), outline_(scene) {
  crack_ = rest_crack(scene, outline_);
  crack_length_ = crack_.length();
  crack_lengths_ = segment_lengths(crack_.points);
  const double rest_head = std::max(0.0, reservoir_.level - crack_.points.front()[1]);
  rest_mouth_pressure_ = reservoir_.uplift_area_factor * reservoir_.density * g_ * rest_head;
  added_mass_scale_ = reservoir_.hydrodynamic == Hydrodynamic::westergaard
                          ? westergaard_scale(reservoir_.density, reservoir_.depth)
                          : 0.0;
  const Vertex centre = outline_.rest_centre();
  for (Vertex& p : crack_.points) p = {p[0] - centre[0], p[1] - centre[1]};
}

ReservoirLoadSet ReservoirLoads::at(const BlockState& s, CrackOpening open) const {
  ReservoirLoadSet loads;
  const SineCosine turn = sine_cosine(s.theta);
  outline_.place(s, turn, world_);
  const Vertex centre = outline_.centre(s);
  // The push and the added mass in one pass over the wetted face.
  const double unit_weight = reservoir_.density * g_;
  const bool added_mass = reservoir_.hydrodynamic == Hydrodynamic::westergaard;
  const double z = reservoir_.level - centre[1];
  AddedMassWithRates added;
  for_each_wetted_piece(world_, reservoir_.level, crack_.edges, [&](const WettedPiece& piece) {
    add_hydrostatic_piece(loads.hydrostatic, piece, unit_weight, centre);
    if (added_mass) add_added_mass_piece(added, piece, added_mass_scale_, z, centre);
  });
  loads.added_mass = added.at;
  loads.added_mass_d_dy = added.d_dy;
  loads.added_mass_d_dtheta = added.d_dtheta;
  if (reservoir_.uplift == UpliftRule::none) return loads;
  place_crack(crack_.points, turn.cos, turn.sin, centre, crack_world_);
  const double head = std::max(0.0, reservoir_.level - crack_world_.front()[1]);
  const double full_head = reservoir_.density * g_ * head;
  const double closed_mouth = reservoir_.uplift == UpliftRule::unchanged
                                  ? rest_mouth_pressure_
                                  : reservoir_.uplift_area_factor * full_head;
  const CrackPressure pressure =
      crack_pressure(reservoir_.uplift, crack_length_, closed_mouth, full_head, open);
  loads.uplift = crack_pressure_load(crack_world_, crack_lengths_, pressure, centre);
  return loads;
}

}  // namespace blockfrag
