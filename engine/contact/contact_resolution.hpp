// What happens at an event: impacts until no corner moves into the ground, then the one contact
// mode consistent with the state and the ground's current lambda (Shenton's onset conditions,
// stick/slip, lift-off, return to rest come out of the same consistency checks).
#pragma once

#include <optional>

#include "engine/modes/modes.hpp"
#include "engine/scene/block_state.hpp"
#include "engine/scene/scene.hpp"

namespace blockfrag {

struct ContactOutcome {
  Mode mode = FlightMode{};
  BlockState state;  // after impacts, projected onto the mode's constraints
  bool impact = false;
  bool painleve = false;  // a Painleve jump to stick was applied
  // The largest relative kinetic-energy change of the velocity changes at the event: each impact
  // round and each laying of the block on its contacts.
  double impact_energy_gain = 0.0;
};

class ContactResolver {
 public:
  // The contact tolerances (engine/tolerances.hpp) are scaled by the block's size R and sqrt(g R),
  // the settling speed by sqrt(g (1 + lambda_v) R).
  ContactResolver(BlockGeometry& geometry, const Contact& contact, double g);

  // gravity_factor: 1 + lambda_v, gravity in the ground's frame over g. Throws SimulationFailure
  // when the impacts do not end (no consistent outcome: reported, never hidden).
  ContactOutcome resolve(const BlockState& state, double lambda, double gravity_factor = 1.0) const;

 private:
  bool touches(const CornerKinematics& k) const { return k.height <= height_tol_; }
  // Impacts, one contact point at a time, until no corner approaches; false if it does not end.
  // A rocking impact takes the scene's rocking restitution where it sets one.
  bool resolve_impacts(BlockState& s, double settle_velocity, ContactOutcome& out) const;
  bool flat_impact(BlockState& s, double e) const;
  void lay_flat(BlockState& s, double settle_velocity) const;
  // lambda and gravity here are the effective ones: lambda g / g_v and g_v = g (1 + lambda_v).
  Mode classify_flat(BlockState& s, double lambda, double gravity, double settle_velocity) const;
  Mode classify_one_corner(BlockState& s, Corner pivot, double lambda, double gravity,
                           ContactOutcome& out) const;
  bool can_rock(const BlockState& s, Corner pivot, double lambda, double gravity,
                bool from_flat) const;
  bool can_slide_rock(const BlockState& s, Corner pivot, int slip, double lambda, double gravity,
                      bool from_flat) const;

  BlockGeometry& geometry_;
  double mu_, e_;
  std::optional<RockingRestitution> rocking_;  // engine/contact/rocking_restitution.hpp
  double g_;
  double height_tol_, velocity_tol_;
};

}  // namespace blockfrag
