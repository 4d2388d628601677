#include "engine/contact/planar_impact.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "engine/contact/contact_lcp.hpp"
#include "engine/tolerances.hpp"

namespace blockfrag {

namespace {

double kinetic(const RigidVelocity& v, const BodyInertia& inertia) {
  return 0.5 * inertia.twice_kinetic(v);
}

ContactState leaving_state(const CornerImpulse& p, double u_t) {
  if (p.p_y <= 0.0) return ContactState::off;
  if (p.regime == ImpactRegime::stick || p.regime == ImpactRegime::slip_then_stick) {
    return ContactState::stick;
  }
  return u_t > 0.0 ? ContactState::slip_positive : ContactState::slip_negative;
}

PlanarImpact newton_impact(const PlanarImpactInput& in, double e) {
  double fastest = 0.0;
  for (const PlanarContact& c : in.contacts) {
    const ContactVelocity u = contact_velocity(c, in.velocity);
    fastest = std::max({fastest, std::abs(u.normal), std::abs(u.tangent)});
  }
  LcpProblem problem{{}, in.inertia, in.friction, kImpactVelocityTolerance * fastest, in.length};
  for (const PlanarContact& c : in.contacts) {
    const ContactVelocity u = contact_velocity(c, in.velocity);
    problem.contacts.push_back({contact_row(c, c.normal), contact_row(c, contact_tangent(c)),
                                u.normal, u.tangent, -e * std::min(u.normal, 0.0), 0, false});
  }
  const LcpSolution s = solve_contact_lcp(problem);
  const RigidVelocity after{in.velocity.vx + s.change(0), in.velocity.vy + s.change(1),
                            in.velocity.omega + s.change(2)};
  return {after, s.states, s.normal, s.tangent, false, s.determinacy};
}

// The one-corner law at contact c of a block without added mass: the impulse in the contact's
// frame and the velocity after.
struct CornerImpact {
  CornerImpulse impulse;
  RigidVelocity after;
};
CornerImpact corner_impact_at(const PlanarContact& c, const RigidVelocity& velocity,
                              const BodyInertia& inertia, double friction, double restitution) {
  const Vec2 t = contact_tangent(c);
  const ContactVelocity u = contact_velocity(c, velocity);
  // The contact's frame (t, n) is right-handed (t x n = 1), so theta and omega keep their sense.
  const CornerImpulse p = corner_impact({1.0, inertia.k2, t.x * c.r.x + t.y * c.r.y,
                                         c.normal.x * c.r.x + c.normal.y * c.r.y, u.tangent,
                                         u.normal, friction, restitution});
  const double p_x = p.p_x * t.x + p.p_y * c.normal.x;
  const double p_y = p.p_x * t.y + p.p_y * c.normal.y;
  return {p,
          {velocity.vx + p_x, velocity.vy + p_y,
           velocity.omega + (c.r.x * p_y - c.r.y * p_x) / inertia.k2}};
}

}  // namespace

PlanarImpact simultaneous_impact(const PlanarImpactInput& in) {
  const double before = kinetic(in.velocity, in.inertia);
  const auto safe = [&](const PlanarImpact& impact) {
    return impact.determinacy != Determinacy::inconsistent &&
           kinetic(impact.after, in.inertia) <= before;
  };
  PlanarImpact impact = newton_impact(in, in.restitution);
  if (safe(impact) || in.restitution == 0.0) return impact;
  double low = 0.0, high = in.restitution;
  for (int i = 0; i < kRestitutionHalvings; ++i) {
    const double middle = 0.5 * (low + high);
    (safe(newton_impact(in, middle)) ? low : high) = middle;
  }
  PlanarImpact capped = newton_impact(in, low);
  capped.energy_capped = true;
  return capped;
}

PlanarImpact resolve_contact_impact(const PlanarImpactInput& in) {
  // The one-corner law knows a block alone; with an added mass the general problem takes it.
  if (in.contacts.size() != 1 || in.inertia.coupled()) return simultaneous_impact(in);
  const PlanarContact& c = in.contacts.front();
  const CornerImpact impact =
      corner_impact_at(c, in.velocity, in.inertia, in.friction, in.restitution);
  const CornerImpulse& p = impact.impulse;
  PlanarImpact out;
  out.after = impact.after;
  out.states = {leaving_state(p, contact_velocity(c, impact.after).tangent)};
  out.normal = {p.p_y};
  out.tangent = {p.p_x};
  out.energy_capped = p.energy_capped;
  return out;
}

RigidVelocity velocity_after_impact(const PlanarContact& c, const RigidVelocity& velocity,
                                    const BodyInertia& inertia, double friction, double restitution,
                                    double length) {
  if (inertia.coupled()) {
    return resolve_contact_impact({{c}, velocity, inertia, friction, restitution, length}).after;
  }
  return corner_impact_at(c, velocity, inertia, friction, restitution).after;
}

}  // namespace blockfrag
