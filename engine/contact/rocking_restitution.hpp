// The rocking restitution (docs/physics.md, "The rocking restitution"): at a rocking impact, a
// contact landing while the block turns about another that holds still, the block leaves turning
// about the landing point at r times its angular velocity (omega+ = r omega-), the coefficient the
// rocking literature fits to experiments. Newton's e cannot set it: the impulse at the landing
// corner conserves the block's angular momentum about it, which fixes omega+ at Housner's
// 1 - 1.5 sin^2(alpha) of omega- for a rectangle whatever e is. Both grounds take the rule from
// here: the flat ground's two base corners and a seat's contacts.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "engine/contact/planar_contact.hpp"
#include "engine/scene/scene.hpp"

namespace blockfrag {

// omega+ / omega- of an impact that conserves the angular momentum about the landing point, for a
// block that turned about `pivot` (both minus the centre of mass): (I/M + pivot . landing) /
// (I/M + |landing|^2), Housner's 1 - 1.5 sin^2(alpha) for a rectangle.
double angular_momentum_ratio(Vec2 pivot, Vec2 landing, double inertia_per_mass);

// omega+ for a given r: r omega-, unless turning at that rate about the landing point would hold
// more kinetic energy than the block had (energy_before, per unit mass), which only a landing point
// farther from the centre of mass than the pivot allows (an asymmetric polygon, r near 1): then
// the rate that keeps the energy, with capped set.
double rocking_angular_velocity(double ratio, double omega_before, double energy_before,
                                double landing_inertia_per_mass, bool& capped);

struct RockingImpactInput {
  std::vector<PlanarContact> touching;  // every touching contact
  std::size_t landing;                  // the one that lands (approaches the ground)
  RigidVelocity velocity;               // before
  double inertia_per_mass;              // I/M, m^2
  double friction;                      // mu
  double still_speed;  // m/s: the pivot's velocity must be below this in both components
  RockingRestitution restitution;
};

struct RockingImpact {
  RigidVelocity after;  // turning about the landing point, which holds still
  bool energy_capped = false;
};

// The impact when it is a rocking one, none otherwise (Newton's law with e then applies): the
// block turns about another touching contact that holds still (the pivot), the landing point can
// stick (the impulse the ground gives lies inside its friction cone), and every other touching
// contact leaves the ground after it. Housner's value is the sticking plastic impulse of
// engine/contact/impact.hpp at the landing point (Newton's law with e = 0, to the bit); a given r
// sets omega+ = r omega- (rocking_angular_velocity).
std::optional<RockingImpact> rocking_impact(const RockingImpactInput& in);

}  // namespace blockfrag
