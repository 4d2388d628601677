// Accelerations and contact forces of a block touching the ground at one corner (docs/physics.md,
// "Equations in one general form"). r is the corner relative to the centre of mass in the world
// frame, w the angular velocity, k2 = I/M; forces are per unit mass (divide by g for per weight).
#pragma once

#include <algorithm>

#include "engine/scene/block_geometry.hpp"
#include "engine/tolerances.hpp"

namespace blockfrag {

struct CornerContact {
  double theta_dd;   // angular acceleration
  double x_dd;       // centre of mass horizontal acceleration (ground frame)
  double friction;   // F / M (horizontal force on the block at the corner)
  double normal;     // V / M
  double corner_dd;  // horizontal acceleration of the corner (its slip acceleration)
};

// The corner sticks (rock). The w^2 terms of the moment cancel: theta'' does not depend on w.
inline CornerContact sticking_corner(Vec2 r, double w, double lambda, double g, double k2) {
  const double theta_dd = g * (r.x + lambda * r.y) / (k2 + r.x * r.x + r.y * r.y);
  const double x_dd = theta_dd * r.y + w * w * r.x;
  return {theta_dd, x_dd, x_dd - lambda * g, g - theta_dd * r.x + w * w * r.y, 0.0};
}

// Denominator of slide-rock's theta''; <= 0 is the Painleve case (no or several solutions).
inline double slide_rock_denominator(Vec2 r, int slip_sign, double mu, double k2) {
  return k2 + r.x * r.x + slip_sign * mu * r.x * r.y;
}

inline bool slide_rock_well_posed(Vec2 r, int slip_sign, double mu, double k2) {
  return slide_rock_denominator(r, slip_sign, mu, k2) > kPainleveMargin * k2;
}

// The corner slips with sign s = sign(u_x) and friction F = -s mu V. Slide-rock stops at
// kPainleveMargin; below half of it the denominator is held there, so a trial step of the
// integrator that strays past the boundary sees large but finite forces of the sign they take as
// the boundary is approached, and the guards on them stay continuous.
inline CornerContact slipping_corner(Vec2 r, double w, int slip_sign, double lambda, double g,
                                     double mu, double k2) {
  const double s_mu = slip_sign * mu;
  const double denominator =
      std::max(slide_rock_denominator(r, slip_sign, mu, k2), 0.5 * kPainleveMargin * k2);
  const double theta_dd = (r.x + s_mu * r.y) * (g + w * w * r.y) / denominator;
  const double normal = g - theta_dd * r.x + w * w * r.y;
  const double friction = -s_mu * normal;
  const double x_dd = friction + lambda * g;
  return {theta_dd, x_dd, friction, normal, x_dd - theta_dd * r.y - w * w * r.x};
}

// Vertical acceleration of another corner (at r_other) while the contact corner (at r) keeps its
// height: > 0 means it lifts off the ground.
inline double other_corner_lift_acceleration(Vec2 r, Vec2 r_other, double w, double theta_dd) {
  return theta_dd * (r_other.x - r.x) - w * w * (r_other.y - r.y);
}

}  // namespace blockfrag
