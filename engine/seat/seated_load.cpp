#include "engine/seat/seated_load.hpp"

#include <algorithm>
#include <cstddef>
#include <vector>

#include "engine/contact/crack_seating.hpp"
#include "engine/seat/fixed_state_forces.hpp"

namespace blockfrag {

BodyLoad seated_load(const SeatedLoadInput& in, const BlockState& s,
                     std::span<const PlanarContact> contacts,
                     std::span<const ContactState> states) {
  const BodyLoad closed =
      body_load(in.inertia_per_mass, in.lambda, in.lambda_v, in.g, in.external, s, Footing::seated);
  if (in.external == nullptr || !in.external->opens_seated_crack() || contacts.size() < 2) {
    return closed;
  }
  std::size_t upstream = 0, downstream = 0;
  for (std::size_t i = 1; i < contacts.size(); ++i) {
    if (contacts[i].r.x < contacts[upstream].r.x) upstream = i;
    if (contacts[i].r.x > contacts[downstream].r.x) downstream = i;
  }
  const FixedStateForces forces = fixed_state_forces(contacts, states, s, closed, in.mu);
  const double heel = forces.normal[upstream], toe = forces.normal[downstream];
  if (heel >= 0.0 && toe >= 0.0) return closed;
  const bool heel_lifts = heel <= toe;
  const LiftingSide side = heel_lifts ? LiftingSide::upstream : LiftingSide::downstream;
  const std::size_t corner = heel_lifts ? upstream : downstream;
  const auto opened = [&](double fraction) {
    return seated_body_load(in.inertia_per_mass, in.lambda, in.lambda_v, in.g, *in.external, s,
                            side, fraction);
  };
  const auto corner_force = [&](std::span<const ContactState> held, double fraction) {
    return fixed_state_forces(contacts, held, s, opened(fraction), in.mu).normal[corner];
  };
  const std::vector<ContactState> sticking(contacts.size(), ContactState::stick);
  const double at_rest = seating_opening([&](double f) { return corner_force(sticking, f); });
  const bool held = std::all_of(states.begin(), states.end(),
                                [](ContactState c) { return c == ContactState::stick; });
  if (held || !(corner_force(states, at_rest) >= 0.0)) return opened(at_rest);
  const double sliding =
      at_rest * seating_opening([&](double x) { return corner_force(states, x * at_rest); });
  return opened(sliding);
}

}  // namespace blockfrag
