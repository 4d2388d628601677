// The speeds at which contacts rest and settle, rules of both grounds' contact resolution (the flat
// ground's, the reduced models' and the seat's): a touching contact slower than the resting speed
// rests or slips, with no impact; a rebound slower than the settling speed loses its bounce, and a
// landing that leaves every contact slower than it is laid on its contacts, keeping their slip
// where that adds no kinetic energy (engine/tolerances.hpp, kRestingVelocity and kSettleVelocity).
#pragma once

#include <algorithm>
#include <cmath>

#include "engine/tolerances.hpp"

namespace blockfrag {

// kSettleVelocity sqrt(g_v R) for a block of size R in the gravity it feels, g_v = g (1 +
// lambda_v): a corner leaving the ground at this speed rises within the contact height. Zero where
// the ground falls faster than g (g_v <= 0): nothing settles in free fall.
inline double settling_speed(double felt_gravity, double size) {
  return kSettleVelocity * std::sqrt(std::max(felt_gravity, 0.0) * size);
}

// kRestingVelocity sqrt(g R): a touching contact slower than this rests or slips on the ground.
inline double resting_speed(double g, double size) {
  return kRestingVelocity * std::sqrt(g * size);
}

// Whether a landing at normal velocity u_n < 0 with restitution e is plastic (e = 0): where its
// rebound e |u_n| would be slower than the settling speed, a bounce that small would end in a time
// the event location cannot resolve.
inline bool lands_plastically(double restitution, double landing_normal_velocity,
                              double settle_speed) {
  return -landing_normal_velocity * restitution < settle_speed;
}

// The restitution such a landing takes: e, or 0 where it lands plastically.
inline double landing_restitution(double restitution, double landing_normal_velocity,
                                  double settle_speed) {
  return lands_plastically(restitution, landing_normal_velocity, settle_speed) ? 0.0 : restitution;
}

// Whether a landing block laid on its contacts (their normal velocities taken to zero) keeps their
// slip along the ground: only where that adds no kinetic energy. Kept regardless, a tall block
// turning as it lands would slide off at its centre's speed plus omega times its height, up to
// twice the landing's energy; otherwise the block takes the least change of its velocity, in the
// kinetic metric, that zeroes the normal velocities (which never adds energy). Energies per unit
// mass, before laying and laid with the slip kept.
inline bool keeps_slip(double energy_before, double energy_with_slip) {
  return energy_with_slip <= energy_before;
}

}  // namespace blockfrag
