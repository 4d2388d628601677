// theta'' of a block turning about a fixed point at r from its centre of mass, held there by one
// sticking contact, under a load (SeatSystem::pivot_turning). Inline: every right-hand side of a
// pivot takes it.
#pragma once

#include "engine/contact/body_load.hpp"
#include "engine/scene/block_geometry.hpp"

namespace blockfrag {

// Under any load, the block turning at omega.
inline double turning_about_pivot(const BodyLoad& load, double omega, Vec2 r) {
  const BodyInertia& m = load.inertia;
  const double along_x = (1.0 + m.xx) * r.y + m.xtheta;             // (J^T M)_x
  const double along_theta = m.xtheta * r.y + m.k2 + m.thetatheta;  // (J^T M)_theta
  const double inertia = along_x * r.y + r.x * r.x + along_theta;
  const double load_along = load.force.x * r.y - load.force.y * r.x + load.moment;
  return (load_along - omega * omega * r.x * (along_x - r.y)) / inertia;
}

// turning_about_pivot where M has no added parts (the dry block's), to the bit, in fewer steps
// (4 % of a dry pivot's right-hand side): with them zero, (1 + xx) r_y + xtheta is r_y but at
// -0 (whose square, and whose difference from r_y, are the same), and xtheta r_y + k2 + thetatheta
// is k2; the omega term's factor along_x - r_y is +0, kept as a product so that a non-finite omega
// gives NaN as there.
inline double dry_turning_about_pivot(const BodyLoad& load, double omega, Vec2 r) {
  const double inertia = r.y * r.y + r.x * r.x + load.inertia.k2;
  const double load_along = load.force.x * r.y - load.force.y * r.x + load.moment;
  return (load_along - omega * omega * r.x * 0.0) / inertia;
}

}  // namespace blockfrag
