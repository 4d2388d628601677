#include "engine/contact/rocking_restitution.hpp"

#include <cmath>

#include "engine/contact/impact.hpp"
#include "engine/tolerances.hpp"

namespace blockfrag {

namespace {

// The sticking plastic impulse at the landing point, in its contact's frame as
// resolve_contact_impact (engine/contact/planar_impact.hpp) applies the paper's law; none where the
// point slips to the end of the impact. It conserves the angular momentum about the point.
std::optional<RigidVelocity> housner_velocity(const PlanarContact& c, const RigidVelocity& v,
                                              double k2, double mu) {
  const Vec2 t = contact_tangent(c);
  const ContactVelocity u = contact_velocity(c, v);
  const CornerImpulse p =
      corner_impact({1.0, k2, t.x * c.r.x + t.y * c.r.y, c.normal.x * c.r.x + c.normal.y * c.r.y,
                     u.tangent, u.normal, mu, 0.0});
  if (p.regime != ImpactRegime::stick && p.regime != ImpactRegime::slip_then_stick) {
    return std::nullopt;
  }
  const double p_x = p.p_x * t.x + p.p_y * c.normal.x;
  const double p_y = p.p_x * t.y + p.p_y * c.normal.y;
  return RigidVelocity{v.vx + p_x, v.vy + p_y, v.omega + (c.r.x * p_y - c.r.y * p_x) / k2};
}

// Turning at r omega- about the landing point, where the impulse that takes the block there, M
// times the change of its centre's velocity, lies in the landing point's friction cone.
std::optional<RockingImpact> scaled_velocity(const PlanarContact& c, const RigidVelocity& v,
                                             double k2, double mu, double ratio) {
  const double energy = 0.5 * (v.vx * v.vx + v.vy * v.vy + k2 * v.omega * v.omega);
  RockingImpact out;
  const double omega = rocking_angular_velocity(
      ratio, v.omega, energy, k2 + c.r.x * c.r.x + c.r.y * c.r.y, out.energy_capped);
  out.after = {omega * c.r.y, -omega * c.r.x, omega};
  const Vec2 t = contact_tangent(c);
  const double dvx = out.after.vx - v.vx, dvy = out.after.vy - v.vy;
  const double p_n = c.normal.x * dvx + c.normal.y * dvy;
  const double p_t = t.x * dvx + t.y * dvy;
  if (!(p_n > 0.0) || std::abs(p_t) > mu * p_n) return std::nullopt;
  return out;
}

}  // namespace

double angular_momentum_ratio(Vec2 pivot, Vec2 landing, double inertia_per_mass) {
  return (inertia_per_mass + landing.x * pivot.x + landing.y * pivot.y) /
         (inertia_per_mass + landing.x * landing.x + landing.y * landing.y);
}

double rocking_angular_velocity(double ratio, double omega_before, double energy_before,
                                double landing_inertia_per_mass, bool& capped) {
  const double omega = ratio * omega_before;
  // Within rounding of the energy before (r = 1 about corners equally far from the centre of
  // mass) the rate stands.
  capped = 0.5 * landing_inertia_per_mass * omega * omega > energy_before * (1.0 + kImpactRounding);
  if (!capped) return omega;
  return std::copysign(std::sqrt(2.0 * energy_before / landing_inertia_per_mass), omega);
}

std::optional<RockingImpact> rocking_impact(const RockingImpactInput& in) {
  const PlanarContact& landing = in.touching.at(in.landing);
  if (!(contact_velocity(landing, in.velocity).normal < 0.0)) return std::nullopt;
  bool turns_about_one = false;
  for (std::size_t i = 0; i < in.touching.size(); ++i) {
    if (i == in.landing) continue;
    const ContactVelocity u = contact_velocity(in.touching[i], in.velocity);
    turns_about_one = turns_about_one || (std::abs(u.tangent) <= in.still_speed &&
                                          std::abs(u.normal) <= in.still_speed);
  }
  if (!turns_about_one) return std::nullopt;

  std::optional<RockingImpact> impact;
  if (in.restitution.housner) {
    if (const auto after =
            housner_velocity(landing, in.velocity, in.inertia_per_mass, in.friction)) {
      impact = RockingImpact{*after, false};
    }
  } else {
    impact = scaled_velocity(landing, in.velocity, in.inertia_per_mass, in.friction,
                             in.restitution.ratio);
  }
  if (!impact) return std::nullopt;
  for (std::size_t i = 0; i < in.touching.size(); ++i) {
    if (i != in.landing && !(contact_velocity(in.touching[i], impact->after).normal > 0.0)) {
      return std::nullopt;
    }
  }
  return impact;
}

}  // namespace blockfrag
