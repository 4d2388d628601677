// The impact law of one corner of a planar rigid body on the ground (y = 0, normal +y): the
// impulse at the corner, given the corner's velocity just before. Paper eqs. 2.10 to 2.18 and
// Table 2.1: Coulomb friction followed along the normal impulse (Darboux-Keller), Newton's
// kinematic restitution, plus the two repairs that model needs (Painleve, energy gain).
#pragma once

#include <optional>

#include "engine/scene/block_state.hpp"

namespace blockfrag {

struct CornerImpactInput {
  double mass;         // M, kg
  double inertia;      // I about the centre of mass, kg m^2
  double r_x, r_y;     // corner minus centre of mass, world frame, m
  double u_x, u_y;     // corner velocity before the impact, m/s; u_y < 0 approaches the ground
  double friction;     // mu >= 0
  double restitution;  // e in [0, 1]: Newton's u_y+ = -e u_y-
};

// How the corner moves tangentially during the impact.
enum class ImpactRegime {
  stick,            // u_x = 0 throughout
  slip,             // slips in one direction throughout (the whole impulse on the cone's edge)
  slip_then_stick,  // slips, stops (by friction or by the Painleve impulse), then sticks: u_x+ = 0
  slip_reversal,    // slips, stops, then slips the other way
};

struct CornerImpulse {
  double p_x = 0.0;  // N s, at the corner
  double p_y = 0.0;  // N s, >= 0
  ImpactRegime regime = ImpactRegime::stick;
  bool painleve_stick = false;  // the slip could not continue and was stopped by a jump to stick
  bool energy_capped = false;   // Newton's law would have created energy: u_y+ < -e u_y-
};

// Throws ContractViolation for M <= 0, I <= 0, mu < 0, e outside [0, 1] or a non-finite
// value. A corner that does not approach (u_y >= 0) gets no impulse.
CornerImpulse corner_impact(const CornerImpactInput& in);

// A corner in contact (u_y = 0) slipping with s = sign(u_x) where I/M + r_x^2 + s mu r_x r_y <= 0:
// the slip's normal force has no non-negative solution (Painleve). Returns the impulse that
// stops the slip (u_x+ = 0) and leaves u_y unchanged; it lies inside the friction cone exactly in
// that condition, so std::nullopt otherwise (and for u_x = 0). u_y and e are not used.
std::optional<CornerImpulse> painleve_stick_impulse(const CornerImpactInput& in);

struct RigidVelocity {
  double vx, vy;  // centre of mass, m/s
  double omega;   // rad/s, counter-clockwise positive
};

inline RigidVelocity velocity_of(const BlockState& s) { return {s.vx, s.vy, s.omega}; }

inline void set_velocity(BlockState& s, const RigidVelocity& v) {
  s.vx = v.vx;
  s.vy = v.vy;
  s.omega = v.omega;
}

struct CornerVelocity {
  double u_x, u_y;
};

// Inline: the contact resolution calls these at every impact of a chattering block.
inline CornerVelocity corner_velocity(const RigidVelocity& v, double r_x, double r_y) {
  return {v.vx - v.omega * r_y, v.vy + v.omega * r_x};
}

inline RigidVelocity apply_impulse(const RigidVelocity& v, double mass, double inertia, double r_x,
                                   double r_y, const CornerImpulse& impulse) {
  return {v.vx + impulse.p_x / mass, v.vy + impulse.p_y / mass,
          v.omega + (r_x * impulse.p_y - r_y * impulse.p_x) / inertia};
}

inline double kinetic_energy(const RigidVelocity& v, double mass, double inertia) {
  return 0.5 * mass * (v.vx * v.vx + v.vy * v.vy) + 0.5 * inertia * v.omega * v.omega;
}

}  // namespace blockfrag
