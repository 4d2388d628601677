// Impacts of a block on its seat at one contact or at several at once (docs/physics.md, "Contact
// on a seat"): Newton's restitution on each approaching contact's normal velocity, Coulomb
// friction, and never a gain of kinetic energy.
#pragma once

#include <vector>

#include "engine/contact/planar_contact.hpp"

namespace blockfrag {

struct PlanarImpactInput {
  std::vector<PlanarContact> contacts;  // touching; those with u_n < 0 approach
  RigidVelocity velocity;               // before
  BodyInertia inertia;                  // the mass matrix per unit mass
  double friction, restitution;         // mu, e
  double length;                        // R, m: tolerances and theta' comparisons
};

struct PlanarImpact {
  RigidVelocity after;
  std::vector<ContactState> states;     // how each contact leaves the impact
  std::vector<double> normal, tangent;  // impulses per unit mass, along n and t
  bool energy_capped = false;           // Newton's law would have created energy: less restitution
  Determinacy determinacy = Determinacy::unique;
};

// One contact: the paper's law of engine/contact/impact.hpp (Coulomb friction followed along the
// impulse, with its repairs) in the contact's frame, so a block landing on one corner is treated
// as on the flat ground. Several: simultaneous_impact.
PlanarImpact resolve_contact_impact(const PlanarImpactInput& in);
// resolve_contact_impact's velocity after for the one contact c (length: R), without the states
// and impulses it reports, nor their allocations: a seat's every landing asks it.
RigidVelocity velocity_after_impact(const PlanarContact& c, const RigidVelocity& velocity,
                                    const BodyInertia& inertia, double friction, double restitution,
                                    double length);

// Every contact at once: the complementarity problem of engine/contact/contact_lcp.hpp on the
// velocities after the impact (each active contact leaves at u_n+ = -e min(u_n-, 0), sticking or
// slipping against its impulse; an inactive one does not approach faster than that). With e = 0
// it cannot create kinetic energy (T+ - T- = P . u+ - P.W.P / 2 and P . u+ = sum of P_t u_t+ <= 0);
// Newton's law at several contacts can, so where it would, the largest e below the asked one
// that does not is applied (found by bisection, 30 halvings: e to 1e-9 of its value).
PlanarImpact simultaneous_impact(const PlanarImpactInput& in);

}  // namespace blockfrag
