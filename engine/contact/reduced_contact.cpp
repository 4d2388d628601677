#include "engine/contact/reduced_contact.hpp"

#include <cmath>

#include "engine/contact/rocking_restitution.hpp"
#include "engine/contact/settling.hpp"
#include "engine/tolerances.hpp"

namespace blockfrag {

double housner_impact_ratio(const BlockGeometry& geometry, Corner old_pivot) {
  return angular_momentum_ratio(geometry.base_corner(old_pivot),
                                geometry.base_corner(other(old_pivot)),
                                geometry.inertia_per_mass());
}

HousnerRules::HousnerRules(BlockGeometry& geometry, bool impacts_lose_energy, double g,
                           std::optional<RockingRestitution> rocking)
    : geometry_(geometry),
      impacts_lose_energy_(impacts_lose_energy),
      settle_velocity_(settling_speed(g, geometry.size())),
      rocking_(rocking) {}

double HousnerRules::omega_after_impact(double omega, Corner pivot) const {
  if (!rocking_ || rocking_->housner) return omega * housner_impact_ratio(geometry_, pivot);
  const Vec2 r_old = geometry_.base_corner(pivot), r_new = geometry_.base_corner(other(pivot));
  const double k2 = geometry_.inertia_per_mass();
  const double energy = 0.5 * (k2 + r_old.x * r_old.x + r_old.y * r_old.y) * omega * omega;
  bool capped = false;
  return rocking_angular_velocity(rocking_->ratio, omega, energy,
                                  k2 + r_new.x * r_new.x + r_new.y * r_new.y, capped);
}

ContactOutcome HousnerRules::rock_on(BlockState s, Corner pivot) const {
  const Vec2 r = geometry_.base_corner_at(pivot, s.theta);
  s.y = -r.y;
  s.vx = s.omega * r.y;
  s.vy = -s.omega * r.x;
  ContactOutcome out;
  out.mode = RockMode{pivot, s.x + r.x};
  out.state = s;
  return out;
}

ContactOutcome HousnerRules::start(const BlockState& state, double lambda) const {
  if (state.theta != 0.0 || state.omega != 0.0) {
    return rock_on(state, release_pivot(state.theta, state.omega));
  }
  BlockState s = state;
  s.y = geometry_.rest_height();
  s.vx = s.vy = s.omega = 0.0;
  if (lambda > geometry_.tip_threshold(Corner::right)) return rock_on(s, Corner::right);
  if (-lambda > geometry_.tip_threshold(Corner::left)) return rock_on(s, Corner::left);
  ContactOutcome out;
  out.mode = RestMode{};
  out.state = s;
  return out;
}

ContactOutcome HousnerRules::impact(const BlockState& state, Corner pivot, double lambda) const {
  BlockState s = state;
  s.theta = 0.0;
  // Zeno: the impacts accumulate in finite time. As in the full model, a corner that lands, or
  // leaves the ground after the impact, slower than the settling speed lays the block flat.
  const double base_width =
      geometry_.base_corner(Corner::right).x - geometry_.base_corner(Corner::left).x;
  const auto settles = [&] { return std::abs(s.omega) * base_width < settle_velocity_; };
  if (!settles() && impacts_lose_energy_) s.omega = omega_after_impact(s.omega, pivot);
  ContactOutcome out;
  if (settles()) {
    s.omega = 0.0;
    out = start(s, lambda);
  } else {
    out = rock_on(s, other(pivot));
  }
  out.impact = impacts_lose_energy_;
  return out;
}

NewmarkRules::NewmarkRules(const BlockGeometry& geometry, double mu, double g)
    : mu_(mu), velocity_tol_(resting_speed(g, geometry.size())) {}

ContactOutcome NewmarkRules::resolve(const BlockState& state, double lambda) const {
  ContactOutcome out;
  out.state = state;
  if (std::abs(state.vx) > velocity_tol_) {
    out.mode = SlideMode{state.vx > 0 ? 1 : -1};
    return out;
  }
  out.state.vx = 0.0;
  out.mode = std::abs(lambda) > mu_ ? Mode{SlideMode{lambda > 0 ? 1 : -1}} : Mode{RestMode{}};
  return out;
}

}  // namespace blockfrag
