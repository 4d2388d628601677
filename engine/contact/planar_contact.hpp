// A rigid block touching a fixed seat (engine/scene/seat.hpp) at any number of points at once: the
// contact forces as a linear complementarity problem, each contact unilateral with Coulomb
// friction (docs/physics.md, "Contact on a seat"). Per unit mass, as the rest of the engine.
#pragma once

#include <functional>
#include <vector>

#include "engine/contact/body_load.hpp"
#include "engine/contact/impact.hpp"
#include "engine/scene/block_geometry.hpp"
#include "engine/tolerances.hpp"

namespace blockfrag {

class LcpDecompositions;

// Which body the contact's normal belongs to: a block vertex on a seat segment (the segment's
// normal, fixed) or a seat point on a block edge (the edge's normal, turning with the block, which
// adds the term -2 omega u_t to the normal acceleration).
enum class ContactKind { block_vertex, seat_point };

// One contact. The seat pushes the block along `normal` (a unit vector); the contact's tangent is
// the normal turned clockwise, t = (n_y, -n_x): +x on flat ground.
struct PlanarContact {
  Vec2 r;       // the contact point minus the block's centre of mass, world frame, m
  Vec2 normal;  // unit
  ContactKind kind = ContactKind::block_vertex;
};

inline Vec2 contact_tangent(const PlanarContact& c) { return {c.normal.y, -c.normal.x}; }

// The velocity of the block's material point at the contact, in the contact's (t, n) components.
struct ContactVelocity {
  double tangent, normal;
};
inline ContactVelocity contact_velocity(const PlanarContact& c, const RigidVelocity& v) {
  const CornerVelocity u = corner_velocity(v, c.r.x, c.r.y);
  const Vec2 t = contact_tangent(c);
  return {t.x * u.u_x + t.y * u.u_y, c.normal.x * u.u_x + c.normal.y * u.u_y};
}

// The block's accelerations: centre of mass (x'', y'') and theta''.
struct BodyAcceleration {
  double x_dd, y_dd, theta_dd;
};

// The contact's accelerations for given body accelerations: the normal one is the gap's second
// derivative (> 0 opens it), the tangential one the material point's along t.
struct ContactAcceleration {
  double tangent, normal;
};
// Inline: the contact forces on a seat ask for it at every right-hand side and guard.
inline ContactAcceleration contact_acceleration(const PlanarContact& c, const RigidVelocity& v,
                                                const BodyAcceleration& a) {
  // The row d . u of engine/contact/contact_lcp.hpp's contact_row times q'', in Eigen's order for
  // a product of three; then the velocity-product terms: the material point's centripetal
  // acceleration -omega^2 r, and for a seat point on a block edge the turning of the edge's
  // normal, -2 omega u_t (the gap n . (p - s) with n turning at omega: 2 n' . p' = -2 omega t . u).
  const auto row_times = [&](Vec2 d) {
    return (d.x * a.x_dd + d.y * a.y_dd) + (c.r.x * d.y - c.r.y * d.x) * a.theta_dd;
  };
  const Vec2 t = contact_tangent(c);
  const double w2 = v.omega * v.omega;
  double normal = -w2 * (c.normal.x * c.r.x + c.normal.y * c.r.y);
  if (c.kind == ContactKind::seat_point) normal -= 2.0 * v.omega * contact_velocity(c, v).tangent;
  return {row_times(t) + -w2 * (t.x * c.r.x + t.y * c.r.y), row_times(c.normal) + normal};
}

// What a contact does: sticks, slips along +t or -t (friction -s mu V), or carries no force.
enum class ContactState { stick, slip_positive, slip_negative, off };

// s of a slipping state (+1 or -1); 0 for stick and off.
inline int slip_sign(ContactState s) {
  return s == ContactState::slip_positive ? 1 : s == ContactState::slip_negative ? -1 : 0;
}

// unique: every consistent choice of contact states gives the same accelerations (or velocities);
// indeterminate: consistent choices disagree (the Painleve family: the chosen one follows the
// preference order below); inconsistent: no choice is consistent.
enum class Determinacy { unique, indeterminate, inconsistent };

// every_choice: the first consistent choice, and whether others disagree with it (determinacy);
// first_consistent: the same choice without looking further (its determinacy says only whether
// one was found), for questions the choice alone answers, such as whether a body stays at rest.
enum class LcpSearch { every_choice, first_consistent };

struct PlanarForcesInput {
  std::vector<PlanarContact> contacts;  // touching, normal velocity zero
  RigidVelocity velocity;
  BodyInertia inertia;  // the mass matrix per unit mass (engine/contact/body_load.hpp)
  Vec2 applied;         // force per unit mass at the centre of mass: (lambda g, -g) on a ground
  double friction;      // mu
  // A contact whose |u_t| exceeds this slips (its friction is -sign(u_t) mu V): m/s.
  double slip_velocity;
  double g;       // scales the tolerances (accelerations are compared to tolerance g)
  double length;  // R, m: theta'' is compared through R theta''
  double tolerance = kContactProblemTolerance;  // relative to g
  // The body may not stay put: choices that leave it no freedom are skipped (LcpProblem).
  bool must_move = false;
  double applied_moment = 0.0;  // per unit mass, about the centre of mass
};

struct PlanarForces {
  std::vector<ContactState> states;
  std::vector<double> normal, tangent;  // V/M and F/M at each contact, along n and t
  BodyAcceleration acceleration;
  Determinacy determinacy = Determinacy::unique;
  int consistent_choices = 0;
};

// Every choice of contact states (stick, slip either way, off; a slipping contact slips its way
// or is off) is tried: the forces that keep the active contacts' normal accelerations at 0 and
// the sticking ones' tangential accelerations at 0, each force inside its Coulomb cone; an off
// contact must not accelerate into the seat, a contact starting to slip must accelerate the way
// it slips. Of the consistent choices the first in this order is taken: fewest contacts not
// sticking, then fewest off (a corner sticks before it slips and slips before it lifts off, as
// engine/contact/contact_resolution.hpp chooses for one corner), then by the contacts' order. A
// statically indeterminate set (three contacts holding a block at rest) gets one of its force
// distributions. Inconsistent: no forces (the free motion), reported, never silent.
// `decompositions`: kept across a series of problems of one shape (engine/contact/contact_lcp.hpp).
PlanarForces resolve_contact_forces(const PlanarForcesInput& in,
                                    LcpSearch search = LcpSearch::every_choice,
                                    LcpDecompositions* decompositions = nullptr);

// Whether the forces resolve_contact_forces gives with LcpSearch::first_consistent have no
// slipping contact and pass `still` (whether a body stays at rest), found trying fewer choices
// (first_consistent_is_still, engine/contact/contact_lcp.hpp).
bool first_consistent_forces_are_still(const PlanarForcesInput& in,
                                       const std::function<bool(const PlanarForces&)>& still,
                                       LcpDecompositions* decompositions);

}  // namespace blockfrag
