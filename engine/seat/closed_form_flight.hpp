// A seat's flight without vertical ground motion in closed form, as the flat ground flies it
// (engine/modes/flight.hpp, engine/motion/ground_drift.hpp), in place of a stepper: each "step" is
// a stretch the guards are watched over, its end and its dense output exact. Integrated, a chain of
// small bounces on a flat seat took 451 steps where the flat ground takes 65 for its other modes,
// and each flight's landing came from the integrator's x instead of the exact one.
#pragma once

#include <limits>

#include "engine/integrate/ode_state.hpp"
#include "engine/modes/flight.hpp"
#include "engine/motion/ground_drift.hpp"
#include "engine/scene/block_state.hpp"

namespace blockfrag {

// The coordinates are FlightChart's: q = (x, vx, y, vy) from its origin; `start` is the flight's
// start in them, `pose` its start.
class ClosedFormFlight {
 public:
  ClosedFormFlight(const OdeState<4>& start, const BlockState& pose, const MotionPiece& piece,
                   double t0, double g)
      : start_{start[2], pose.theta, start[3], pose.omega},
        drift_(piece, t0),
        t0_(t0),
        x0_(start[0]),
        vx0_(start[1]),
        g_(g),
        max_x_acceleration_(g * piece.max_abs_lambda()) {}

  template <class Ode>
  void step(const Ode&, double& t, OdeState<4>& q, double h_max) {
    step_start_ = t;
    t += h_max;
    step_end_ = t;
    q = dense(t);
  }
  OdeState<4> dense(double t) const {
    const BlockState s = flight_pose(start_, g_, t - t0_);
    const GroundDrift::Integrals ground = drift_.at(t);
    return {x0_ + vx0_ * (t - t0_) + g_ * ground.second, vx0_ + g_ * ground.first, s.y, s.vy};
  }
  // No integration: no steps or right-hand sides to count.
  long steps() const { return 0; }
  long rhs_evaluations() const { return 0; }
  bool moves_one_way(int) const { return false; }
  // How far x (i = 0) or y (i = 2) strays over the last step from the chord between its ends: a
  // function whose second derivative is at most a in size strays by at most a h^2 / 8 (x'' is
  // lambda g, y'' is -g). The rates' are not bounded.
  double dense_spread(int i) const {
    const double h = step_end_ - step_start_;
    if (i == 0) return 0.125 * max_x_acceleration_ * h * h;
    if (i == 2) return 0.125 * g_ * h * h;
    return std::numeric_limits<double>::infinity();
  }

 private:
  FlightStart start_;
  GroundDrift drift_;
  double t0_, x0_, vx0_, g_;
  double max_x_acceleration_;  // m/s^2: |x''| over the piece at most
  double step_start_ = 0.0, step_end_ = 0.0;
};

}  // namespace blockfrag
