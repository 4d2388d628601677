// The closed set of contact modes. Each mode that integrates an ODE is a small system: its
// coordinates (chosen so its constraints hold exactly), right-hand side, guard functions (positive
// while the mode holds; the mode ends where one reaches zero), the event each guard's crossing is,
// the scale of each coordinate for error control, and the map back to the full state. Guards are
// dimensionless (lengths over R, forces over M g, velocities over sqrt(g R)).
#pragma once

#include <array>
#include <cmath>
#include <numbers>
#include <variant>

#include "engine/contact/contact_dynamics.hpp"
#include "engine/integrate/ode_state.hpp"
#include "engine/motion/ground_motion.hpp"
#include "engine/scene/block_state.hpp"
#include "engine/summary.hpp"
#include "engine/tolerances.hpp"

namespace blockfrag {

struct RestMode {
  static constexpr ModeKind kind = ModeKind::rest;
};
struct SlideMode {
  static constexpr ModeKind kind = ModeKind::slide;
  int slip_sign;
};
struct RockMode {
  static constexpr ModeKind kind = ModeKind::rock;
  Corner pivot;
  double pivot_x;
};
struct SlideRockMode {
  static constexpr ModeKind kind = ModeKind::slide_rock;
  Corner pivot;
  int slip_sign;
};
struct FlightMode {
  static constexpr ModeKind kind = ModeKind::flight;
};
using Mode = std::variant<RestMode, SlideMode, RockMode, SlideRockMode, FlightMode>;

inline ModeKind mode_kind(const Mode& mode) {
  return std::visit([](const auto& m) { return m.kind; }, mode);
}

// What a guard reaching zero means: the event that ends the mode.
enum class GuardEvent {
  lift_off,           // the contact's normal force V reaches zero
  friction_limit,     // a sticking corner's friction reaches mu V
  slip_stops,         // the slip velocity reaches zero
  corner_lands,       // another corner reaches the ground
  overturns,          // the block lies on another face
  painleve_boundary,  // slide-rock reaches the Painleve boundary
  load_lost,          // the ground falls faster than g: nothing presses the block on it
};

// Events that depend on the ground's current acceleration: at a motion piece's boundary a mode
// goes on only if these guards still hold under the next piece.
constexpr bool depends_on_ground_motion(GuardEvent event) {
  return event == GuardEvent::lift_off || event == GuardEvent::friction_limit ||
         event == GuardEvent::load_lost;
}

// What every system shares: the block, the contact, the ground motion pieces being integrated.
// The geometry and the pieces remember their last rotation and lambda, so a system (const while
// it integrates) reaches them through non-const pointers; the simulation owns them.
struct SystemContext {
  BlockGeometry* geometry;
  MotionPiece* piece;     // horizontal: lambda
  MotionPiece* vertical;  // lambda_v
  double g, mu;
  // Gravity in the ground's frame over g: 1 + lambda_v. With it, each contact mode's equations are
  // the horizontal-only ones with g_v = g (1 + lambda_v) for g and lambda g / g_v for lambda (an
  // exact identity when lambda_v = 0).
  double gravity_factor(double t) const {
    const double factor = 1.0 + vertical->lambda(t);
    return factor == 0.0 ? kLostLoadGravityFactor : factor;
  }
  double length_scale() const { return geometry->size(); }
  // A base corner relative to the centre of mass, in the world frame.
  Vec2 arm(double theta, Corner corner) const { return geometry->base_corner_at(corner, theta); }
  // Both base corners at once (guards need both; one sine and cosine serve them).
  struct Arms {
    Vec2 pivot, other;
  };
  Arms arms(double theta, Corner pivot) const {
    const Rotation turn = geometry->rotation(theta);
    return {rotate(geometry->base_corner(pivot), turn),
            rotate(geometry->base_corner(blockfrag::other(pivot)), turn)};
  }
  double velocity_scale() const { return std::sqrt(g * geometry->size()); }
  // For guards whose least value over a step is at one of its ends when theta moves one way
  // through it: the other base corner's height over R is +-W sin(theta) / R for a base of width W
  // (its corners are level in the body), monotone while |theta| < pi/2. (The overturning margin,
  // concave in theta, needs only theta moving one way.)
  static bool upright(double theta0, double theta1) {
    constexpr double kQuarterTurn = std::numbers::pi / 2;
    return std::abs(theta0) < kQuarterTurn && std::abs(theta1) < kQuarterTurn;
  }
  // The guard that stops the run: the block lies on another face (|theta| = pi/2 for a rectangle).
  double overturn_margin(double theta) const { return geometry->overturn_margin(theta); }
};

struct ContactForces {
  double friction, normal;  // per unit mass
};

// Flat on the base, slipping with sign s: x'' = (lambda - s mu (1 + lambda_v)) g.  q = (x, vx).
// Ends when the slip stops or the ground falls away faster than g (the load vanishes).
struct SlideSystem {
  static constexpr int N = 2;
  enum Guard { slip_velocity, gravity, kGuards };
  static constexpr std::array<GuardEvent, kGuards> kEvents = {GuardEvent::slip_stops,
                                                              GuardEvent::load_lost};
  SystemContext c;
  int s;

  OdeState<N> scale() const { return {c.length_scale(), c.velocity_scale()}; }

  void operator()(double t, const OdeState<N>& q, OdeState<N>& dq) const {
    dq[0] = q[1];
    dq[1] = (c.piece->lambda(t) - s * c.mu * c.gravity_factor(t)) * c.g;
  }
  std::array<double, kGuards> guards(double t, const OdeState<N>& q) const {
    return {s * q[1] / c.velocity_scale(), c.gravity_factor(t)};
  }
  BlockState full(double, const OdeState<N>& q) const {
    return {q[0], c.geometry->rest_height(), 0.0, q[1], 0.0, 0.0};
  }
  ContactForces forces(double t, const OdeState<N>&) const {
    const double normal = c.g * c.gravity_factor(t);
    return {-s * c.mu * normal, normal};
  }
  OdeState<N> coordinates(const BlockState& b) const { return {b.x, b.vx}; }
  // The slip velocity's guard is the velocity itself.
  template <class OneWay>
  std::array<bool, kGuards> least_at_ends(const OdeState<N>&, const OdeState<N>&,
                                          const OneWay& one_way) const {
    return {one_way(1), false};
  }
};

// Rocking about a sticking corner.  q = (theta, omega); the pivot stays at (pivot_x, 0).
struct RockSystem {
  static constexpr int N = 2;
  enum Guard { normal_force, friction_cone, other_corner_height, overturn_margin, kGuards };
  static constexpr std::array<GuardEvent, kGuards> kEvents = {
      GuardEvent::lift_off, GuardEvent::friction_limit, GuardEvent::corner_lands,
      GuardEvent::overturns};
  SystemContext c;
  Corner pivot;
  double pivot_x;

  OdeState<N> scale() const { return {1.0, std::sqrt(c.g / c.length_scale())}; }

  Vec2 arm(double theta, Corner corner) const { return c.arm(theta, corner); }
  CornerContact contact(double t, const OdeState<N>& q) const {
    return contact_at(t, q, arm(q[0], pivot));
  }
  CornerContact contact_at(double t, const OdeState<N>& q, Vec2 r) const {
    const double factor = c.gravity_factor(t);
    return sticking_corner(r, q[1], c.piece->lambda(t) / factor, c.g * factor,
                           c.geometry->inertia_per_mass());
  }
  void operator()(double t, const OdeState<N>& q, OdeState<N>& dq) const {
    dq[0] = q[1];
    dq[1] = contact(t, q).theta_dd;
  }
  std::array<double, kGuards> guards(double t, const OdeState<N>& q) const {
    const auto [r, r_other] = c.arms(q[0], pivot);
    const CornerContact k = contact_at(t, q, r);
    return {k.normal / c.g, (c.mu * k.normal - std::abs(k.friction)) / c.g,
            (r_other.y - r.y) / c.length_scale(), c.overturn_margin(q[0])};
  }
  BlockState full(double, const OdeState<N>& q) const {
    const Vec2 r = arm(q[0], pivot);
    return {pivot_x - r.x, -r.y, q[0], q[1] * r.y, -q[1] * r.x, q[1]};
  }
  ContactForces forces(double t, const OdeState<N>& q) const {
    const CornerContact k = contact(t, q);
    return {k.friction, k.normal};
  }
  OdeState<N> coordinates(const BlockState& b) const { return {b.theta, b.omega}; }
  // Which guards' least value over a step from q0 to q1 is at one of its ends (so no sample inside
  // can find it lower): one_way(i) says whether coordinate i of the dense output moves one way.
  template <class OneWay>
  std::array<bool, kGuards> least_at_ends(const OdeState<N>& q0, const OdeState<N>& q1,
                                          const OneWay& one_way) const {
    const bool turning_one_way = one_way(0);
    return {false, false, turning_one_way && SystemContext::upright(q0[0], q1[0]), turning_one_way};
  }
};

// Housner's rocking block: rocks on a corner that never slips or lifts (so no contact-force
// guards); the other corner's landing and overturning end the mode.  q = (theta, omega).
struct HousnerRockSystem {
  static constexpr int N = 2;
  enum Guard { other_corner_height, overturn_margin, kGuards };
  static constexpr std::array<GuardEvent, kGuards> kEvents = {GuardEvent::corner_lands,
                                                              GuardEvent::overturns};
  RockSystem rock;

  OdeState<N> scale() const { return rock.scale(); }

  void operator()(double t, const OdeState<N>& q, OdeState<N>& dq) const { rock(t, q, dq); }
  std::array<double, kGuards> guards(double, const OdeState<N>& q) const {
    const auto [r, r_other] = rock.c.arms(q[0], rock.pivot);
    return {(r_other.y - r.y) / rock.c.length_scale(), rock.c.overturn_margin(q[0])};
  }
  BlockState full(double t, const OdeState<N>& q) const { return rock.full(t, q); }
  ContactForces forces(double t, const OdeState<N>& q) const { return rock.forces(t, q); }
  OdeState<N> coordinates(const BlockState& b) const { return rock.coordinates(b); }
  template <class OneWay>
  std::array<bool, kGuards> least_at_ends(const OdeState<N>& q0, const OdeState<N>& q1,
                                          const OneWay& one_way) const {
    const auto rock_ends = rock.least_at_ends(q0, q1, one_way);
    return {rock_ends[RockSystem::other_corner_height], rock_ends[RockSystem::overturn_margin]};
  }
};

// Rocking about a slipping corner.  q = (theta, omega, pivot x, pivot x velocity).
struct SlideRockSystem {
  static constexpr int N = 4;
  enum Guard {
    normal_force,
    slip_velocity,
    other_corner_height,
    overturn_margin,
    painleve_distance,
    kGuards
  };
  static constexpr std::array<GuardEvent, kGuards> kEvents = {
      GuardEvent::lift_off, GuardEvent::slip_stops, GuardEvent::corner_lands, GuardEvent::overturns,
      GuardEvent::painleve_boundary};
  SystemContext c;
  Corner pivot;
  int s;

  OdeState<N> scale() const {
    const double R = c.length_scale();
    return {1.0, std::sqrt(c.g / R), R, c.velocity_scale()};
  }

  Vec2 arm(double theta, Corner corner) const { return c.arm(theta, corner); }
  CornerContact contact(double t, const OdeState<N>& q) const {
    return contact_at(t, q, arm(q[0], pivot));
  }
  CornerContact contact_at(double t, const OdeState<N>& q, Vec2 r) const {
    const double factor = c.gravity_factor(t);
    return slipping_corner(r, q[1], s, c.piece->lambda(t) / factor, c.g * factor, c.mu,
                           c.geometry->inertia_per_mass());
  }
  void operator()(double t, const OdeState<N>& q, OdeState<N>& dq) const {
    const CornerContact k = contact(t, q);
    dq = {q[1], k.theta_dd, q[3], k.corner_dd};
  }
  std::array<double, kGuards> guards(double t, const OdeState<N>& q) const {
    const double R = c.length_scale(), k2 = c.geometry->inertia_per_mass();
    const auto [r, r_other] = c.arms(q[0], pivot);
    const double d = slide_rock_denominator(r, s, c.mu, k2) / k2 - kPainleveMargin;
    return {contact_at(t, q, r).normal / c.g, s * q[3] / c.velocity_scale(), (r_other.y - r.y) / R,
            c.overturn_margin(q[0]), d};
  }
  BlockState full(double, const OdeState<N>& q) const {
    const Vec2 r = arm(q[0], pivot);
    return {q[2] - r.x, -r.y, q[0], q[3] + q[1] * r.y, -q[1] * r.x, q[1]};
  }
  ContactForces forces(double t, const OdeState<N>& q) const {
    const CornerContact k = contact(t, q);
    return {k.friction, k.normal};
  }
  OdeState<N> coordinates(const BlockState& b) const {
    const Vec2 r = arm(b.theta, pivot);
    return {b.theta, b.omega, b.x + r.x, b.vx - b.omega * r.y};
  }
  template <class OneWay>
  std::array<bool, kGuards> least_at_ends(const OdeState<N>& q0, const OdeState<N>& q1,
                                          const OneWay& one_way) const {
    const bool turning_one_way = one_way(0);
    return {false, one_way(3), turning_one_way && SystemContext::upright(q0[0], q1[0]),
            turning_one_way, false};
  }
};

// Free flight under vertical ground motion: the height above the ground feels g (1 + lambda_v), so
// it is integrated with x; theta turns at its constant rate.  q = (x, vx, y, vy).
struct FlightSystem {
  static constexpr int N = 4;
  enum Guard { lowest_corner_height, overturn_margin, kGuards };
  static constexpr std::array<GuardEvent, kGuards> kEvents = {GuardEvent::corner_lands,
                                                              GuardEvent::overturns};
  SystemContext c;
  double t0, theta0, omega;

  OdeState<N> scale() const {
    const double R = c.length_scale();
    return {R, c.velocity_scale(), R, c.velocity_scale()};
  }

  double theta(double t) const { return theta0 + omega * (t - t0); }
  void operator()(double t, const OdeState<N>& q, OdeState<N>& dq) const {
    dq = {q[1], c.piece->lambda(t) * c.g, q[3], -c.g * (1.0 + c.vertical->lambda(t))};
  }
  // Within the overturning range only a base corner can be lowest.
  std::array<double, kGuards> guards(double t, const OdeState<N>& q) const {
    const double th = theta(t);
    const double lowest = std::min(c.arm(th, Corner::left).y, c.arm(th, Corner::right).y);
    return {(q[2] + lowest) / c.length_scale(), c.overturn_margin(th)};
  }
  BlockState full(double t, const OdeState<N>& q) const {
    return {q[0], q[2], theta(t), q[1], q[3], omega};
  }
  ContactForces forces(double, const OdeState<N>&) const { return {0.0, 0.0}; }
  OdeState<N> coordinates(const BlockState& b) const { return {b.x, b.vx, b.y, b.vy}; }
  // theta is linear in time: the overturning margin, concave in it, is least at an end.
  template <class OneWay>
  std::array<bool, kGuards> least_at_ends(const OdeState<N>&, const OdeState<N>&,
                                          const OneWay&) const {
    return {false, true};
  }
};

}  // namespace blockfrag
