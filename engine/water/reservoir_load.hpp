// The reservoir in the block's equations of motion (engine/contact/body_load.hpp): the hydrostatic
// push and the crack's uplift at the block's pose (engine/water/reservoir_loads.hpp), the uplift
// under the scene's rule with the crack closed while the block is seated on its base (under
// "zero_in_gap" opened from a lifting corner as far as that corner needs:
// engine/seat/seated_load.hpp) and opened whole while it rocks or flies, and Westergaard's added
// mass (engine/water/hydrodynamic_load.hpp). A scene whose water wets the block runs on the seat's
// engine, the flat ground as a seat of one long segment under the block's base
// (simulate_under_reservoir).
#pragma once

#include <optional>

#include "engine/contact/body_load.hpp"
#include "engine/simulate.hpp"
#include "engine/water/hydrodynamic_load.hpp"
#include "engine/water/reservoir_loads.hpp"

namespace blockfrag {

class ReservoirLoad : public ExternalLoad {
 public:
  // The scene must be valid and have a seat and a reservoir.
  explicit ReservoirLoad(const Scene& scene);
  LoadAddition at(const BlockState& s, double lambda, double g, Footing footing) const override;
  // "zero_in_gap" and "full_head_in_gap": a seated block's crack opens from the lifting side
  // (engine/seat/seated_load.hpp).
  SeatedCrack seated_crack() const override;
  LoadAddition seated_opened(const BlockState& s, double lambda, double g, LiftingSide side,
                             double fraction) const override;
  // The block placed once at s, the uplift alone found anew for each opening.
  void search_openings(const BlockState& s, double lambda, double g,
                       CrackOpeningSearch& search) const override;

 private:
  LoadAddition with_crack(const BlockState& s, double lambda, double g, CrackOpening open) const;
  // The added mass's terms at the pose (none without Westergaard's).
  LoadAddition added_mass_terms(const ReservoirPose& pose, const BlockState& s, double lambda,
                                double g) const;
  // Those with the hydrostatic push and the uplift, per unit of the block's mass.
  LoadAddition with_pushes(LoadAddition added, const WaterLoad& hydrostatic,
                           const WaterLoad& uplift) const;

  ReservoirLoads loads_;  // hydrostatic, uplift, and the added mass with its rates
  std::optional<HydrodynamicLoad> hydrodynamic_;  // the added mass's terms in the equations
  double mass_;
};

// Whether the scene's reservoir wets its block at rest (level above the block's lowest point).
bool reservoir_wets(const Scene& scene);

// A valid scene whose reservoir wets its block.
SimulationWithHistory simulate_under_reservoir(const Scene& scene, double output_interval);

}  // namespace blockfrag
