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

// Flattened, as with_crack is: a right-hand side asks for the loads through here.
[[gnu::flatten]] LoadAddition ReservoirLoad::at(const BlockState& s, double lambda, double g,
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

// Every call it makes inlined (the pose's pass, the added mass's terms, the uplift): ~100 of its
// ~700 instructions a call were calls and their copies.
[[gnu::flatten]] LoadAddition ReservoirLoad::with_crack(const BlockState& s, double lambda,
                                                        double g, CrackOpening open) const {
  const ReservoirPose pose = loads_.pose(s);
  return with_pushes(added_mass_terms(pose, s, lambda, g), pose.hydrostatic,
                     loads_.uplift(pose, open));
}

void ReservoirLoad::search_openings(const BlockState& s, double lambda, double g,
                                    CrackOpeningSearch& search) const {
  class AtPose final : public CrackOpenings {
   public:
    AtPose(const ReservoirLoad& load, const ReservoirPose& pose, const LoadAddition& added)
        : load_(load), pose_(pose), added_(added) {}
    LoadAddition opened(LiftingSide side, double fraction) const override {
      return load_.with_pushes(added_, pose_.hydrostatic,
                               load_.loads_.uplift(pose_, CrackOpening::from_side(side, fraction)));
    }

   private:
    const ReservoirLoad& load_;
    const ReservoirPose& pose_;
    const LoadAddition& added_;
  };
  const ReservoirPose pose = loads_.pose(s);
  search.search(AtPose(*this, pose, added_mass_terms(pose, s, lambda, g)));
}

LoadAddition ReservoirLoad::added_mass_terms(const ReservoirPose& pose, const BlockState& s,
                                             double lambda, double g) const {
  return hydrodynamic_ ? hydrodynamic_->from_rates(pose.added, s, lambda, g) : LoadAddition{};
}

LoadAddition ReservoirLoad::with_pushes(LoadAddition added, const WaterLoad& hydrostatic,
                                        const WaterLoad& uplift) const {
  added.force.x += (hydrostatic.fx + uplift.fx) / mass_;
  added.force.y += (hydrostatic.fy + uplift.fy) / mass_;
  added.moment += (hydrostatic.moment + uplift.moment) / mass_;
  return added;
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
