#include "engine/contact/contact_resolution.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "engine/contact/contact_dynamics.hpp"
#include "engine/contact/impact.hpp"
#include "engine/contact/rocking_restitution.hpp"
#include "engine/contact/settling.hpp"
#include "engine/errors.hpp"
#include "engine/tolerances.hpp"

namespace blockfrag {

namespace {

int sign_of(double v) { return v > 0 ? 1 : -1; }

// Solves the 3x3 system A z = b by Gaussian elimination with partial pivoting.
bool solve3(std::array<std::array<double, 4>, 3> m, std::array<double, 3>& z) {
  for (int col = 0; col < 3; ++col) {
    int pivot = col;
    for (int row = col + 1; row < 3; ++row) {
      if (std::abs(m[row][col]) > std::abs(m[pivot][col])) pivot = row;
    }
    if (std::abs(m[pivot][col]) < kSingularPivot) return false;
    std::swap(m[col], m[pivot]);
    for (int row = col + 1; row < 3; ++row) {
      const double f = m[row][col] / m[col][col];
      for (int k = col; k < 4; ++k) m[row][k] -= f * m[col][k];
    }
  }
  for (int row = 2; row >= 0; --row) {
    double v = m[row][3];
    for (int k = row + 1; k < 3; ++k) v -= m[row][k] * z[k];
    z[row] = v / m[row][row];
  }
  return true;
}

// The relative kinetic-energy change of one velocity change at the event (an impact round, a
// laying), kept if it is the largest.
void note_energy_change(double before, double after, ContactOutcome& out) {
  if (before > 0)
    out.impact_energy_gain = std::max(out.impact_energy_gain, (after - before) / before);
}

// The flat impact's system for z = (Py_left, Py_right, Px) under one active set and friction
// state (0: the base sticks, else its slip direction): Newton's law at an active corner, no
// impulse at the other; the base's slip stopped, or Coulomb's impulse against it.
template <class NormalRow>
std::array<std::array<double, 4>, 3> flat_impact_system(const std::array<bool, 2>& active,
                                                        int friction, const NormalRow& normal_row,
                                                        const std::array<double, 2>& target,
                                                        const std::array<double, 2>& u_y,
                                                        const std::array<double, 3>& tangent_row,
                                                        double u_x, double mu) {
  std::array<std::array<double, 4>, 3> m{};
  for (int j = 0; j < 2; ++j) {
    if (active[j]) {
      const auto row = normal_row(j);
      m[j] = {row[0], row[1], row[2], target[j] - u_y[j]};
    } else {
      m[j] = {0, 0, 0, 0};
      m[j][j] = 1.0;
    }
  }
  if (friction == 0) {
    m[2] = {tangent_row[0], tangent_row[1], tangent_row[2], -u_x};
  } else {
    m[2] = {friction * mu, friction * mu, 1.0, 0.0};
  }
  return m;
}

}  // namespace

ContactResolver::ContactResolver(BlockGeometry& geometry, const Contact& contact, double g)
    : geometry_(geometry),
      mu_(contact.friction),
      e_(contact.restitution),
      rocking_(contact.rocking_restitution),
      g_(g),
      height_tol_(kContactHeight * geometry.size()),
      velocity_tol_(resting_speed(g, geometry.size())) {}

// Drops the rotation and bounce and keeps the base's slip velocity (a sticking base stays stuck)
// where that adds no kinetic energy (keeps_slip); otherwise the centre's horizontal velocity, the
// least change in the kinetic metric that zeroes both corners' normal velocities.
void ContactResolver::lay_flat(BlockState& s, double settle_velocity) const {
  const double slip = 0.5 * (corner_kinematics(geometry_, s, Corner::left).u_x +
                             corner_kinematics(geometry_, s, Corner::right).u_x);
  BlockState with_slip = s;
  with_slip.vx = slip;
  with_slip.vy = 0.0;
  with_slip.omega = 0.0;
  if (keeps_slip(kinetic_energy_per_mass(geometry_, s),
                 kinetic_energy_per_mass(geometry_, with_slip))) {
    s.vx = slip;
  }
  // A slip slower than the settling speed ends with the landing, as a seat ends it: below that
  // speed the rules end every motion of the corners (left going, friction stopped it within a
  // microsecond at the cross-check's mu, and its start was counted as the run's slide onset).
  if (std::abs(s.vx) <= settle_velocity) s.vx = 0.0;
  s.theta = 0.0;
  s.y = geometry_.rest_height();
  s.vy = 0.0;
  s.omega = 0.0;
}

// Both base corners touch: one impulse per corner and one friction impulse for the base (both
// corners share their tangential velocity when flat), Newton's law at each approaching corner,
// complementarity at each corner, Coulomb on the total. Tries each active set and friction state
// and takes the first consistent one.
bool ContactResolver::flat_impact(BlockState& s, double e) const {
  const double M = 1.0, I = geometry_.inertia_per_mass();  // per unit mass
  const CornerKinematics kl = corner_kinematics(geometry_, s, Corner::left);
  const CornerKinematics kr = corner_kinematics(geometry_, s, Corner::right);
  const double ry = 0.5 * (kl.r.y + kr.r.y);
  const std::array<double, 2> rx = {kl.r.x, kr.r.x};
  const std::array<double, 2> target = {kl.u_y < 0 ? -e * kl.u_y : 0.0,
                                        kr.u_y < 0 ? -e * kr.u_y : 0.0};
  const double eps = kImpactRounding * (std::abs(kl.u_y) + std::abs(kr.u_y) + std::abs(kl.u_x));

  // Post-impact velocities are affine in z = (Py_left, Py_right, Px).
  const auto velocities = [&](const std::array<double, 3>& z) {
    BlockState after = s;
    after.vx += z[2] / M;
    after.vy += (z[0] + z[1]) / M;
    after.omega += (rx[0] * z[0] + rx[1] * z[1] - ry * z[2]) / I;
    return after;
  };
  // Rows: d(u_y at corner j)/dz and d(u_x)/dz.
  const auto normal_row = [&](int j) {
    return std::array<double, 3>{1 / M + rx[j] * rx[0] / I, 1 / M + rx[j] * rx[1] / I,
                                 -rx[j] * ry / I};
  };
  const std::array<double, 3> tangent_row = {-ry * rx[0] / I, -ry * rx[1] / I, 1 / M + ry * ry / I};
  const std::array<double, 2> u_y = {kl.u_y, kr.u_y};
  const double u_x = 0.5 * (kl.u_x + kr.u_x);

  for (const std::array<bool, 2> active :
       {std::array{true, false}, std::array{false, true}, std::array{true, true}}) {
    for (const int friction : {0, 1, -1}) {  // 0: stick, else slip direction
      const auto m =
          flat_impact_system(active, friction, normal_row, target, u_y, tangent_row, u_x, mu_);
      std::array<double, 3> z{};
      if (!solve3(m, z)) continue;
      if (z[0] < -eps * M || z[1] < -eps * M) continue;
      const BlockState after = velocities(z);
      const CornerKinematics al = corner_kinematics(geometry_, after, Corner::left);
      const CornerKinematics ar = corner_kinematics(geometry_, after, Corner::right);
      if (!active[0] && al.u_y < target[0] - eps) continue;
      if (!active[1] && ar.u_y < target[1] - eps) continue;
      const double total_normal = z[0] + z[1];
      if (friction == 0 && std::abs(z[2]) > mu_ * total_normal * (1 + kImpactRounding) + eps * M) {
        continue;
      }
      if (friction != 0 && friction * 0.5 * (al.u_x + ar.u_x) < -eps) continue;
      s = after;
      return true;
    }
  }
  return false;
}

bool ContactResolver::resolve_impacts(BlockState& s, double settle_velocity,
                                      ContactOutcome& out) const {
  const double M = 1.0, I = geometry_.inertia_per_mass();  // per unit mass
  for (int round = 0; round < kMaxImpactRounds; ++round) {
    const CornerKinematics kl = corner_kinematics(geometry_, s, Corner::left);
    const CornerKinematics kr = corner_kinematics(geometry_, s, Corner::right);
    const bool left_hits = touches(kl) && kl.u_y < -velocity_tol_;
    const bool right_hits = touches(kr) && kr.u_y < -velocity_tol_;
    if (!left_hits && !right_hits) return true;

    out.impact = true;
    const double before = kinetic_energy(velocity_of(s), M, I);
    const bool flat = touches(kl) && touches(kr);
    const double fastest = std::min(left_hits ? kl.u_y : 0.0, right_hits ? kr.u_y : 0.0);
    if (flat && -fastest < settle_velocity) {
      lay_flat(s, settle_velocity);
      note_energy_change(before, kinetic_energy(velocity_of(s), M, I), out);
      return true;
    }
    if (rocking_ && flat && left_hits != right_hits) {
      const std::size_t landing = left_hits ? 0 : 1;
      if (const auto rocking = rocking_impact({{{kl.r, {0.0, 1.0}}, {kr.r, {0.0, 1.0}}},
                                               landing,
                                               velocity_of(s),
                                               I,
                                               mu_,
                                               velocity_tol_,
                                               *rocking_})) {
        set_velocity(s, rocking->after);
        note_energy_change(before, kinetic_energy(velocity_of(s), M, I), out);
        continue;
      }
    }
    // A bounce that would leave slower than the settling speed is one the rules above end at
    // its next landing: the landing is plastic at once.
    const double e = landing_restitution(e_, fastest, settle_velocity);
    const BlockState start = s;
    // The paper's law at the corner that hits; when the block is flat and that would drive the
    // other corner into the ground (a flat landing), both corners take their impulses together.
    const bool left_first = left_hits && (!right_hits || kl.u_y <= kr.u_y);
    const CornerKinematics& k = left_first ? kl : kr;
    const CornerImpulse p = corner_impact({M, I, k.r.x, k.r.y, k.u_x, k.u_y, mu_, e});
    set_velocity(s, apply_impulse(velocity_of(s), M, I, k.r.x, k.r.y, p));
    const Corner other_corner = left_first ? Corner::right : Corner::left;
    if (flat && corner_kinematics(geometry_, s, other_corner).u_y < -velocity_tol_) {
      BlockState together = start;
      if (flat_impact(together, e)) {
        // Newton's law at two corners with friction can gain energy: then no bounce.
        const double gained = kinetic_energy(velocity_of(together), M, I) - before;
        if (gained > kImpactRounding * before) {
          together = start;
          if (!flat_impact(together, 0.0)) lay_flat(together, settle_velocity);
        }
        s = together;
      }
    }
    note_energy_change(before, kinetic_energy(velocity_of(s), M, I), out);
  }
  return false;
}

bool ContactResolver::can_rock(const BlockState& s, Corner pivot, double lambda, double gravity,
                               bool from_flat) const {
  const Vec2 r = geometry_.base_corner_at(pivot, s.theta);
  const CornerContact k =
      sticking_corner(r, s.omega, lambda, gravity, geometry_.inertia_per_mass());
  if (k.normal < 0 || std::abs(k.friction) > mu_ * k.normal) return false;
  if (!from_flat) return true;
  const Vec2 r_other = geometry_.base_corner_at(other(pivot), s.theta);
  return other_corner_lift_acceleration(r, r_other, s.omega, k.theta_dd) > 0;
}

bool ContactResolver::can_slide_rock(const BlockState& s, Corner pivot, int slip, double lambda,
                                     double gravity, bool from_flat) const {
  const Vec2 r = geometry_.base_corner_at(pivot, s.theta);
  const double k2 = geometry_.inertia_per_mass();
  if (!slide_rock_well_posed(r, slip, mu_, k2)) return false;
  const CornerContact k = slipping_corner(r, s.omega, slip, lambda, gravity, mu_, k2);
  if (k.normal < 0) return false;
  const double u_x = s.vx - s.omega * r.y;
  // Starting from stick, the corner must accelerate the way it is assumed to slip.
  if (std::abs(u_x) <= velocity_tol_ && slip * k.corner_dd <= 0) return false;
  if (!from_flat) return true;
  const Vec2 r_other = geometry_.base_corner_at(other(pivot), s.theta);
  return other_corner_lift_acceleration(r, r_other, s.omega, k.theta_dd) > 0;
}

Mode ContactResolver::classify_flat(BlockState& s, double lambda, double gravity,
                                    double settle_velocity) const {
  lay_flat(s, settle_velocity);
  if (std::abs(s.vx) > velocity_tol_) {
    const int slip = sign_of(s.vx);
    if (mu_ <= geometry_.flat_slide_friction_limit(slip)) return SlideMode{slip};
    const Corner leading = slip > 0 ? Corner::right : Corner::left;
    for (const Corner k : {leading, other(leading)}) {
      if (can_slide_rock(s, k, slip, lambda, gravity, true)) return SlideRockMode{k, slip};
    }
    return SlideMode{slip};
  }
  s.vx = 0.0;
  const bool friction_holds = std::abs(lambda) <= mu_;
  if (friction_holds && lambda <= geometry_.tip_threshold(Corner::right) &&
      -lambda <= geometry_.tip_threshold(Corner::left)) {
    return RestMode{};
  }
  const Corner k = lambda > 0 ? Corner::right : Corner::left;
  const int slip = sign_of(lambda);
  if (can_rock(s, k, lambda, gravity, true)) {
    return RockMode{k, s.x + geometry_.base_corner(k).x};
  }
  if (can_slide_rock(s, k, slip, lambda, gravity, true)) return SlideRockMode{k, slip};
  if (!friction_holds) return SlideMode{slip};
  return RestMode{};
}

Mode ContactResolver::classify_one_corner(BlockState& s, Corner pivot, double lambda,
                                          double gravity, ContactOutcome& out) const {
  const Vec2 r = geometry_.base_corner_at(pivot, s.theta);
  const double k2 = geometry_.inertia_per_mass();
  // Put the corner exactly on the ground with no normal velocity.
  s.y = -r.y;
  s.vy = -s.omega * r.x;
  double u_x = s.vx - s.omega * r.y;

  if (std::abs(u_x) > velocity_tol_) {
    const int slip = sign_of(u_x);
    if (slide_rock_well_posed(r, slip, mu_, k2)) {
      if (slipping_corner(r, s.omega, slip, lambda, gravity, mu_, k2).normal < 0)
        return FlightMode{};
      return SlideRockMode{pivot, slip};
    }
    // Within the margin of the boundary the jam's impulse may lie outside the cone by that
    // relative margin: take the friction that puts it on the boundary.
    const double jam_friction =
        std::max(mu_, (k2 + r.x * r.x) / std::max(-slip * r.x * r.y, kSingularPivot));
    const auto jump = painleve_stick_impulse(
        {1.0, geometry_.inertia_per_mass(), r.x, r.y, u_x, 0.0, jam_friction, 0.0});
    if (jump)
      set_velocity(
          s, apply_impulse(velocity_of(s), 1.0, geometry_.inertia_per_mass(), r.x, r.y, *jump));
    out.painleve = true;
    u_x = 0.0;
  }
  s.vx = s.omega * r.y;  // u_x = 0: the corner sticks for now
  if (can_rock(s, pivot, lambda, gravity, false)) return RockMode{pivot, s.x + r.x};
  // Slip the way friction cannot hold it first, then the other way (with V >= 0 either may be
  // the consistent one when sticking would need a pull from the ground).
  const CornerContact stick = sticking_corner(r, s.omega, lambda, gravity, k2);
  const int slip = stick.friction > 0 ? -1 : 1;
  for (const int direction : {slip, -slip}) {
    if (can_slide_rock(s, pivot, direction, lambda, gravity, false))
      return SlideRockMode{pivot, direction};
  }
  // Free, the corner would accelerate upward: it leaves the ground.
  const double free_lift = -gravity - s.omega * s.omega * r.y;
  if (free_lift >= 0) return FlightMode{};
  // With exact arithmetic one of the above holds (at most one slip direction is Painleve, and
  // then stick or the other slip is consistent). Rounding can break a tie at the cone's edge,
  // where stick needs exactly mu V and the slip that way starts with zero acceleration. Slip
  // then: if the corner does not go on slipping, the slip guard ends it at once and stick holds.
  const double cone_edge = kImpactRounding * (std::abs(stick.friction) + mu_ * stick.normal);
  if (stick.normal >= 0 && std::abs(stick.friction) - mu_ * stick.normal <= cone_edge &&
      slide_rock_well_posed(r, slip, mu_, k2) &&
      slipping_corner(r, s.omega, slip, lambda, gravity, mu_, k2).normal >= 0) {
    return SlideRockMode{pivot, slip};
  }
  // Otherwise none holds only within the well-posedness margin of slide-rock, where a slip
  // reaches the Painleve boundary together with free_lift = 0 (the singular point of Genot &
  // Brogliato 1999), each option breaking its law by a hair. Lift off: no contact force, so none
  // outside the cone. Past the singular point either the corner rises (lift-off was consistent)
  // or it comes back within the contact tolerance and lands slower than the settle velocity,
  // where stick or slip is consistent again. Sticking instead can leave friction outside the cone
  // for as long as the rock mode lasts.
  out.painleve = true;
  return FlightMode{};
}

ContactOutcome ContactResolver::resolve(const BlockState& state, double lambda,
                                        double gravity_factor) const {
  ContactOutcome out;
  out.state = state;
  BlockState& s = out.state;
  const double settle_velocity = settling_speed(g_ * gravity_factor, geometry_.size());
  if (!resolve_impacts(s, settle_velocity, out)) {
    const bool flat = touches(corner_kinematics(geometry_, s, Corner::left)) &&
                      touches(corner_kinematics(geometry_, s, Corner::right));
    if (!flat) {
      throw SimulationFailure("impacts did not end after " + std::to_string(kMaxImpactRounds) +
                              " rounds");
    }
    const double before = kinetic_energy_per_mass(geometry_, s);
    lay_flat(s, settle_velocity);
    note_energy_change(before, kinetic_energy_per_mass(geometry_, s), out);
  }
  const CornerKinematics kl = corner_kinematics(geometry_, s, Corner::left);
  const CornerKinematics kr = corner_kinematics(geometry_, s, Corner::right);
  // A flat block whose corners barely move off the ground would rock in ever smaller, ever faster
  // swings (Zeno): lay it flat, as the impacts below the settle velocity do.
  const bool settles =
      touches(kl) && touches(kr) && std::max(std::abs(kl.u_y), std::abs(kr.u_y)) < settle_velocity;
  const bool left = settles || (touches(kl) && kl.u_y <= velocity_tol_);
  const bool right = settles || (touches(kr) && kr.u_y <= velocity_tol_);
  // The ground falling faster than g carries no load: nothing holds the block to it.
  if (gravity_factor <= 0) {
    out.mode = FlightMode{};
    return out;
  }
  const double effective_lambda = lambda / gravity_factor, gravity = g_ * gravity_factor;
  if (left && right) {
    const double before = kinetic_energy_per_mass(geometry_, s);
    out.mode = classify_flat(s, effective_lambda, gravity, settle_velocity);
    note_energy_change(before, kinetic_energy_per_mass(geometry_, s), out);
  } else if (left || right) {
    out.mode =
        classify_one_corner(s, left ? Corner::left : Corner::right, effective_lambda, gravity, out);
  } else {
    out.mode = FlightMode{};
  }
  return out;
}

}  // namespace blockfrag
