// The settling speed, one rule of both grounds' contact resolution: a rebound slower than it loses
// its bounce, and a landing that leaves every contact slower than it is laid on its contacts
// (engine/tolerances.hpp, kSettleVelocity).
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

}  // namespace blockfrag
