#include "engine/contact/planar_contact.hpp"

#include <cmath>
#include <cstddef>

#include "engine/contact/contact_lcp.hpp"

namespace blockfrag {

namespace {

BodyAcceleration free_acceleration(const PlanarForcesInput& in) {
  const Eigen::Vector3d free_q =
      BodyLoad{in.applied, in.applied_moment, in.inertia}.free_acceleration();
  return {free_q(0), free_q(1), free_q(2)};
}

LcpProblem contact_problem(const PlanarForcesInput& in, const BodyAcceleration& free) {
  LcpProblem problem{{}, in.inertia, in.friction, in.tolerance * in.g, in.length, in.must_move};
  for (const PlanarContact& c : in.contacts) {
    const ContactAcceleration y = contact_acceleration(c, in.velocity, free);
    const double u_t = contact_velocity(c, in.velocity).tangent;
    const int forced = std::abs(u_t) > in.slip_velocity ? (u_t > 0 ? 1 : -1) : 0;
    problem.contacts.push_back({contact_row(c, c.normal), contact_row(c, contact_tangent(c)),
                                y.normal, y.tangent, 0.0, forced, true});
  }
  return problem;
}

PlanarForces forces_of(const LcpSolution& s, const BodyAcceleration& free) {
  return {s.states,
          s.normal,
          s.tangent,
          {free.x_dd + s.change(0), free.y_dd + s.change(1), free.theta_dd + s.change(2)},
          s.determinacy,
          s.consistent_choices};
}

}  // namespace

PlanarForces resolve_contact_forces(const PlanarForcesInput& in, LcpSearch search,
                                    LcpDecompositions* decompositions) {
  const BodyAcceleration free = free_acceleration(in);
  return forces_of(solve_contact_lcp(contact_problem(in, free), search, decompositions), free);
}

bool first_consistent_forces_are_still(const PlanarForcesInput& in,
                                       const std::function<bool(const PlanarForces&)>& still,
                                       LcpDecompositions* decompositions) {
  const BodyAcceleration free = free_acceleration(in);
  return first_consistent_is_still(
      contact_problem(in, free), [&](const LcpSolution& s) { return still(forces_of(s, free)); },
      decompositions);
}

}  // namespace blockfrag
