// Block states for the contact-resolution and mode tests, written from the kinematics by hand (not
// from the engine's own maps, which the tests check): a rectangle flat on its base, and one turning
// about a base corner that neither slips nor lifts. Plus readable names for modes, models and
// corners in failures.
#pragma once

#include <cmath>
#include <ostream>

#include "engine/modes/modes.hpp"

namespace blockfrag {

// gtest prints these through ADL: names instead of enum values in a failure.
inline void PrintTo(ModeKind mode, std::ostream* os) { *os << mode_name(mode); }
inline void PrintTo(Model model, std::ostream* os) { *os << model_name(model); }
inline void PrintTo(Corner corner, std::ostream* os) {
  *os << (corner == Corner::left ? "left" : "right");
}

namespace testing {

// A rectangle of half-height b flat on its base, at rest, its centre of mass at (x, b).
inline BlockState flat_state(double b, double x = 0.0) { return {x, b, 0.0, 0.0, 0.0, 0.0}; }

// A rectangle of half-height b tilted by theta and turning at omega about the base corner at
// corner_x in body coordinates (+a the right one, -a the left one), that corner at (pivot_x, 0)
// and not moving. With r = Rot(theta) (corner_x, -b) from the centre of mass to the corner, the
// centre is at (pivot_x - r_x, -r_y) and moves at omega x (centre - corner) = (omega r_y,
// -omega r_x), so the corner's velocity u = (vx - omega r_y, vy + omega r_x) is zero.
inline BlockState turning_about(double corner_x, double b, double theta, double omega,
                                double pivot_x) {
  const double c = std::cos(theta), s = std::sin(theta);
  const double r_x = corner_x * c + b * s, r_y = corner_x * s - b * c;
  return {pivot_x - r_x, -r_y, theta, omega * r_y, -omega * r_x, omega};
}

// Kinetic energy per unit mass of a rectangle of half-sizes a, b: I/M = (a^2 + b^2) / 3.
inline double rectangle_kinetic_energy(double a, double b, const BlockState& s) {
  return 0.5 * (s.vx * s.vx + s.vy * s.vy + (a * a + b * b) / 3.0 * s.omega * s.omega);
}

}  // namespace testing
}  // namespace blockfrag
