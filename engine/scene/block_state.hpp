// The block's full state in the ground frame: centre of mass (x relative to the ground, y above
// it), rotation theta (counter-clockwise), and their rates.
#pragma once

#include <cmath>

#include "engine/scene/block_geometry.hpp"

namespace blockfrag {

struct BlockState {
  double x = 0, y = 0, theta = 0, vx = 0, vy = 0, omega = 0;
};

// Where a corner is and how fast it moves, in the ground frame.
struct CornerKinematics {
  Vec2 r;         // from the centre of mass to the corner
  double height;  // above the ground
  double u_x, u_y;
};

// Corner i of the block's hull (BlockGeometry::corner).
inline CornerKinematics corner_kinematics(BlockGeometry& geometry, const BlockState& s,
                                          int corner) {
  const Vec2 r = geometry.corner_at(corner, s.theta);
  return {r, s.y + r.y, s.vx - s.omega * r.y, s.vy + s.omega * r.x};
}

inline CornerKinematics corner_kinematics(BlockGeometry& geometry, const BlockState& s,
                                          Corner corner) {
  return corner_kinematics(geometry, s, static_cast<int>(corner));
}

// Kinetic energy per unit mass.
inline double kinetic_energy_per_mass(const BlockGeometry& geometry, const BlockState& s) {
  return 0.5 * (s.vx * s.vx + s.vy * s.vy + geometry.inertia_per_mass() * s.omega * s.omega);
}

}  // namespace blockfrag
