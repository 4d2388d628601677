#include "engine/water/reservoir_load.hpp"

#include "engine/scene/block_geometry.hpp"
#include "engine/scene/seat.hpp"
#include "engine/seat/seat_simulation.hpp"
#include "engine/tolerances.hpp"
#include "engine/water/block_outline.hpp"

namespace blockfrag {

namespace {

double block_mass(const Scene& scene) {
  return scene.polygon ? scene.polygon->mass : scene.block.mass;
}

Scene on_flat_seat(Scene scene) {
  if (scene.seat) return scene;
  const BlockOutline outline(scene);
  const double x = outline.rest_centre()[0];
  const double reach = kFlatSeatHalfLength * scene_geometry(scene).size();
  scene.seat = Seat{{{x - reach, outline.rest_bottom()}, {x + reach, outline.rest_bottom()}}};
  return scene;
}

}  // namespace

ReservoirLoad::ReservoirLoad(const Scene& scene) : loads_(scene), mass_(block_mass(scene)) {
  if (scene.reservoir->hydrodynamic == Hydrodynamic::westergaard) {
    const BlockOutline outline(scene);
    hydrodynamic_.emplace(
        WettedBlock{outline.body(), loads_.crack().edges, mass_, scene_geometry(scene).size()},
        scene.reservoir->level, scene.reservoir->density, scene.reservoir->depth);
  }
}

LoadAddition ReservoirLoad::at(const BlockState& s, double lambda, double g,
                               Footing footing) const {
  return with_crack(s, lambda, g,
                    footing == Footing::seated ? CrackOpening::closed() : CrackOpening::whole());
}

SeatedCrack ReservoirLoad::seated_crack() const {
  switch (loads_.uplift_rule()) {
    case UpliftRule::zero_in_gap: return SeatedCrack::drains;
    case UpliftRule::full_head_in_gap: return SeatedCrack::fills;
    case UpliftRule::none:
    case UpliftRule::unchanged: break;
  }
  return SeatedCrack::unaffected;
}

LoadAddition ReservoirLoad::seated_opened(const BlockState& s, double lambda, double g,
                                          LiftingSide side, double fraction) const {
  return with_crack(s, lambda, g, CrackOpening::from_side(side, fraction));
}

LoadAddition ReservoirLoad::with_crack(const BlockState& s, double lambda, double g,
                                       CrackOpening open) const {
  const ReservoirLoadSet loads = loads_.at(s, open);
  LoadAddition out =
      hydrodynamic_
          ? hydrodynamic_->from_rates(
                {loads.added_mass, loads.added_mass_d_dy, loads.added_mass_d_dtheta}, s, lambda, g)
          : LoadAddition{};
  out.force.x += (loads.hydrostatic.fx + loads.uplift.fx) / mass_;
  out.force.y += (loads.hydrostatic.fy + loads.uplift.fy) / mass_;
  out.moment += (loads.hydrostatic.moment + loads.uplift.moment) / mass_;
  return out;
}

bool reservoir_wets(const Scene& scene) {
  return scene.reservoir && scene.reservoir->level > BlockOutline(scene).rest_bottom();
}

SimulationWithHistory simulate_under_reservoir(const Scene& scene, double output_interval) {
  const Scene seated = on_flat_seat(scene);
  const ReservoirLoad load(seated);
  return simulate_on_seat(seated, output_interval, &load);
}

}  // namespace blockfrag
