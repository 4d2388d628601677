// The contact rules of the two one-degree-of-freedom models: what follows an event in Housner's
// rocking block (never slides, never lifts off) and in Newmark's sliding block (never rocks).
#pragma once

#include <optional>

#include "engine/contact/contact_resolution.hpp"

namespace blockfrag {

// omega after an impact on the other base corner that sticks and does not bounce (angular momentum
// about it is conserved): (I/M + r_new . r_old) / (I/M + |r_new|^2), Housner's 1 - 1.5 sin^2(alpha)
// for a rectangle.
double housner_impact_ratio(const BlockGeometry& geometry, Corner old_pivot);

class HousnerRules {
 public:
  // rocking: the scene's rocking restitution; a given r sets omega+ = r omega- at each impact
  // (engine/contact/rocking_restitution.hpp), Housner's or none keeps housner_impact_ratio.
  HousnerRules(BlockGeometry& geometry, bool impacts_lose_energy, double g,
               std::optional<RockingRestitution> rocking = std::nullopt);

  // From rest (or a release from a tilt): rocks once lambda exceeds a tipping threshold.
  ContactOutcome start(const BlockState& state, double lambda) const;
  // The rocking block came back to theta = 0 on `pivot`: the other corner takes over.
  ContactOutcome impact(const BlockState& state, Corner pivot, double lambda) const;

 private:
  ContactOutcome rock_on(BlockState s, Corner pivot) const;

  // omega after an impact on the other corner of `pivot`.
  double omega_after_impact(double omega, Corner pivot) const;

  BlockGeometry& geometry_;
  bool impacts_lose_energy_;
  double settle_velocity_;
  std::optional<RockingRestitution> rocking_;
};

class NewmarkRules {
 public:
  NewmarkRules(const BlockGeometry& geometry, double mu, double g);

  // Slides while the base moves relative to the ground, or from a stop once |lambda| exceeds mu.
  ContactOutcome resolve(const BlockState& state, double lambda) const;

 private:
  double mu_, velocity_tol_;
};

}  // namespace blockfrag
