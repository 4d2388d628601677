// The coordinates a block on its seat is integrated in, chosen by its active contacts so that they
// hold exactly, as in the flat ground's modes (engine/modes/modes.hpp): pivoting on a sticking
// contact, (theta, omega); a vertex slipping along a segment, (theta, omega, s, s') with s its
// place along the segment's line; sliding on a line, (s, s'); flight, (x, x', y, y'). Other sets
// take (x, y, theta) and their rates, the contacts held by projection at events. Positions are
// measured from an origin, the flat ground's: under the block's centre of mass at its release, at
// the level of its base at rest. On a flat seat each chart is then the flat ground's mode's, with
// its scales and values: the adaptive integrator's error norm (an RMS over the coordinates, each
// against the tolerance times its scale plus its size) chooses the flat ground's steps. Integrated
// in (x, y, theta), a rocking block's norm counted six errors where the flat ground counts two,
// its steps differed, and its angles differed from the flat ground's by up to 10x the flat
// ground's own error.
#pragma once

#include <cmath>
#include <variant>

#include "engine/contact/planar_contact.hpp"
#include "engine/integrate/ode_state.hpp"
#include "engine/scene/block_geometry.hpp"
#include "engine/scene/block_state.hpp"
#include "engine/seat/seat_contacts.hpp"
#include "engine/seat/turn_cache.hpp"
#include "engine/sine_cosine.hpp"

namespace blockfrag {

namespace seat_chart_detail {
inline double along(Vec2 p, Vec2 direction) { return p.x * direction.x + p.y * direction.y; }

// body turned by theta.
inline Vec2 turned(Vec2 body, double theta) {
  const SineCosine turn = cached_turn(theta);
  return rotate(body, turn.cos, turn.sin);
}
}  // namespace seat_chart_detail

// No contact: theta turns at its constant rate.  q = (x, vx, y, vy) from the origin.
struct FlightChart {
  static constexpr int N = 4;
  Vec2 origin;
  double t0, theta0, omega;

  OdeState<N> scale(double R, double g) const {
    const double v = std::sqrt(g * R);
    return {R, v, R, v};
  }
  BlockState full(double t, const OdeState<N>& q) const {
    return {origin.x + q[0], origin.y + q[2], theta0 + omega * (t - t0), q[1], q[3], omega};
  }
  OdeState<N> coordinates(const BlockState& b) const {
    return {b.x - origin.x, b.vx, b.y - origin.y, b.vy};
  }
  OdeState<N> rates(const OdeState<N>& q, const BlockState&, const BodyAcceleration& a) const {
    return {q[1], a.x_dd, q[3], a.y_dd};
  }
};

// Turning about a sticking contact: the block's point `body` (from its centre of mass, body frame)
// stays at `point`.  q = (theta, omega).
struct PivotChart {
  static constexpr int N = 2;
  Vec2 point, body;

  PivotChart(Vec2 point_, Vec2 body_) : point(point_), body(body_) {}

  OdeState<N> scale(double R, double g) const { return {1.0, std::sqrt(g / R)}; }
  // The pivot less the centre of mass at theta.
  Vec2 arm(double theta) const { return seat_chart_detail::turned(body, theta); }
  // arm(theta) at a tilt not asked for before (a right-hand side's stage: fresh_turn).
  Vec2 fresh_arm(double theta) const {
    const SineCosine turn = fresh_turn(theta);
    return rotate(body, turn.cos, turn.sin);
  }
  BlockState full(double, const OdeState<N>& q) const { return full_at_arm(q, arm(q[0])); }
  // full() with the arm at q's tilt given: a right-hand side turns it once for the state and the
  // turning.
  BlockState full_at_arm(const OdeState<N>& q, Vec2 r) const {
    return {point.x - r.x, point.y - r.y, q[0], q[1] * r.y, -q[1] * r.x, q[1]};
  }
  OdeState<N> coordinates(const BlockState& b) const { return {b.theta, b.omega}; }
  OdeState<N> rates(const OdeState<N>& q, const BlockState&, const BodyAcceleration& a) const {
    return {q[1], a.theta_dd};
  }
};

// A block vertex (`body`) slipping along a seat segment's line.  q = (theta, omega, s, s'), the
// vertex at s along the line from the origin; `line`'s offset is from the origin too.
struct SlipChart {
  static constexpr int N = 4;
  Vec2 origin;
  SeatLine line;
  Vec2 body;

  SlipChart(Vec2 origin_, const SeatLine& line_, Vec2 body_)
      : origin(origin_), line(line_), body(body_) {}

  OdeState<N> scale(double R, double g) const {
    return {1.0, std::sqrt(g / R), R, std::sqrt(g * R)};
  }
  // The vertex less the centre of mass at theta.
  Vec2 arm(double theta) const { return seat_chart_detail::turned(body, theta); }
  // arm(theta) at a tilt not asked for before (a right-hand side's stage: fresh_turn).
  Vec2 fresh_arm(double theta) const {
    const SineCosine turn = fresh_turn(theta);
    return rotate(body, turn.cos, turn.sin);
  }
  BlockState full(double, const OdeState<N>& q) const { return full_at_arm(q, arm(q[0])); }
  // full() with the arm at q's tilt given: a right-hand side turns it once for the state and the
  // rates.
  BlockState full_at_arm(const OdeState<N>& q, Vec2 r) const {
    const Vec2 d = line.direction, n = line.normal;
    const Vec2 p{origin.x + q[2] * d.x + line.offset * n.x,
                 origin.y + q[2] * d.y + line.offset * n.y};
    return {p.x - r.x, p.y - r.y, q[0], q[3] * d.x + q[1] * r.y, q[3] * d.y - q[1] * r.x, q[1]};
  }
  OdeState<N> coordinates(const BlockState& b) const {
    const Vec2 r = seat_chart_detail::turned(body, b.theta);
    const Vec2 d = line.direction;
    const Vec2 p{b.x - origin.x + r.x, b.y - origin.y + r.y};
    return {b.theta, b.omega, seat_chart_detail::along(p, d),
            seat_chart_detail::along({b.vx - b.omega * r.y, b.vy + b.omega * r.x}, d)};
  }
  // The rates at q, the arm at q's tilt r.
  OdeState<N> rates_at_arm(const OdeState<N>& q, Vec2 r, const BodyAcceleration& a) const {
    const double w2 = q[1] * q[1];
    const Vec2 vertex{a.x_dd - a.theta_dd * r.y - w2 * r.x, a.y_dd + a.theta_dd * r.x - w2 * r.y};
    return {q[1], a.theta_dd, q[3], seat_chart_detail::along(vertex, line.direction)};
  }
};

// Sliding without turning on one line: the centre of mass at s along the line's direction from the
// origin, at `offset` along its normal.  q = (s, s').
struct SlideChart {
  static constexpr int N = 2;
  Vec2 origin;
  SeatLine line;
  double offset, theta;

  OdeState<N> scale(double R, double g) const { return {R, std::sqrt(g * R)}; }
  BlockState full(double, const OdeState<N>& q) const {
    const Vec2 d = line.direction, n = line.normal;
    return {origin.x + q[0] * d.x + offset * n.x,
            origin.y + q[0] * d.y + offset * n.y,
            theta,
            q[1] * d.x,
            q[1] * d.y,
            0.0};
  }
  OdeState<N> coordinates(const BlockState& b) const {
    return {seat_chart_detail::along({b.x - origin.x, b.y - origin.y}, line.direction),
            seat_chart_detail::along({b.vx, b.vy}, line.direction)};
  }
  OdeState<N> rates(const OdeState<N>& q, const BlockState&, const BodyAcceleration& a) const {
    return {q[1], seat_chart_detail::along({a.x_dd, a.y_dd}, line.direction)};
  }
};

// Any other set of contacts.  q = (x, y, theta, x', y', theta'), x and y from the origin.
struct FreeChart {
  static constexpr int N = 6;
  Vec2 origin;

  OdeState<N> scale(double R, double g) const {
    const double v = std::sqrt(g * R);
    return {R, R, 1.0, v, v, v / R};
  }
  BlockState full(double, const OdeState<N>& q) const {
    return {origin.x + q[0], origin.y + q[1], q[2], q[3], q[4], q[5]};
  }
  OdeState<N> coordinates(const BlockState& b) const {
    return {b.x - origin.x, b.y - origin.y, b.theta, b.vx, b.vy, b.omega};
  }
  OdeState<N> rates(const OdeState<N>& q, const BlockState&, const BodyAcceleration& a) const {
    return {q[3], q[4], q[5], a.x_dd, a.y_dd, a.theta_dd};
  }
};

using SeatChart = std::variant<FlightChart, PivotChart, SlipChart, SlideChart, FreeChart>;

}  // namespace blockfrag
