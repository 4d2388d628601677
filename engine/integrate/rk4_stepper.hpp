// The classical fixed-step fourth-order Runge-Kutta method (the paper's), with cubic Hermite
// dense output for event location.
#pragma once

#include <algorithm>
#include <cmath>

#include "engine/integrate/ode_state.hpp"

namespace blockfrag {

// Steps of size dt, cut short by the caller's h_max (a breakpoint, an end time, a located event).
// The derivative at the end of a step serves both the Hermite interpolant and the next step's first
// stage, so a run costs 4 right-hand-side evaluations per step plus 1 at the start and after every
// reset. Allocation free: everything lives in std::array members.
template <int N>
class Rk4Stepper {
 public:
  static constexpr bool kFixedStep = true;  // no error control: its caller checks events itself

  explicit Rk4Stepper(double dt) : dt_(dt) {
    if (!(dt > 0.0) || !std::isfinite(dt)) {
      throw ContractViolation("Rk4Stepper: dt must be positive and finite");
    }
  }

  // One step from (t, q) of size min(dt, h_max); overwrites t and q. h_max must be > 0 (it may be
  // infinite). The step ends at exactly t + h_max (in floating point) when h_max < dt.
  template <class Rhs>
  requires OdeRhs<Rhs, N>
  void step(const Rhs& rhs, double& t, OdeState<N>& q, double h_max) {
    if (!(h_max > 0.0)) throw ContractViolation("Rk4Stepper::step: h_max must be > 0");
    const double h = std::min(dt_, h_max);
    const double t_end = t + h;
    if (t_end == t) throw StepSizeUnderflow(t, h, "the step does not advance t");

    if constexpr (N > 0) {
      // The cached end derivative is only valid if the caller continues from where the last step
      // ended; restarting anywhere else (an interpolated event time, a jump) recomputes it.
      if (!(have_f1_ && t == t1_ && q == q1_)) {
        rhs(t, q, f1_);
        ++rhs_evaluations_;
      }
      q0_ = q;
      f0_ = f1_;

      const double half = 0.5 * h;
      OdeState<N> y;
      OdeState<N> k2;
      OdeState<N> k3;
      OdeState<N> k4;
      for (int i = 0; i < N; ++i) y[i] = q0_[i] + half * f0_[i];
      rhs(t + half, y, k2);
      for (int i = 0; i < N; ++i) y[i] = q0_[i] + half * k2[i];
      rhs(t + half, y, k3);
      for (int i = 0; i < N; ++i) y[i] = q0_[i] + h * k3[i];
      rhs(t_end, y, k4);
      const double sixth = h / 6.0;
      for (int i = 0; i < N; ++i) q[i] = q0_[i] + sixth * (f0_[i] + 2.0 * (k2[i] + k3[i]) + k4[i]);
      rhs(t_end, q, f1_);
      rhs_evaluations_ += 4;
      q1_ = q;
      have_f1_ = true;
    }
    t0_ = t;
    t1_ = t_end;
    t = t_end;
    ++steps_;
  }

  // The cubic Hermite interpolant through (t0, q0, f0) and (t1, q1, f1) of the last step; meant for
  // t in [step_start(), step_end()] (outside, it extrapolates the cubic).
  OdeState<N> dense(double t) const {
    OdeState<N> y{};
    if constexpr (N > 0) {
      const double h = t1_ - t0_;
      if (h == 0.0) return q1_;
      const double theta = (t - t0_) / h;
      const double theta1 = 1.0 - theta;
      for (int i = 0; i < N; ++i) {
        // Hairer's form of the Hermite cubic: exact at both ends, no cancellation inside.
        const double delta = q1_[i] - q0_[i];
        const double b = h * f0_[i] - delta;
        const double c = delta - h * f1_[i] - b;
        y[i] = q0_[i] + theta * (delta + theta1 * (b + theta * c));
      }
    }
    return y;
  }

  // Whether component i of the dense output moves one way through the last step (a sufficient
  // test: false may still be monotone).
  bool moves_one_way(int i) const {
    const double h = t1_ - t0_;
    const double delta = q1_[i] - q0_[i];
    const double b = h * f0_[i] - delta;
    return blockfrag::moves_one_way(delta, b, delta - h * f1_[i] - b, 0.0);
  }

  // How far component i of the dense output strays from the chord between its ends: it departs
  // from it by theta (1 - theta) (b + theta c), theta (1 - theta) <= 1/4 and b + theta c between
  // b and b + c.
  double dense_spread(int i) const {
    const double h = t1_ - t0_;
    const double delta = q1_[i] - q0_[i];
    return 0.25 * std::max(std::abs(h * f0_[i] - delta), std::abs(delta - h * f1_[i]));
  }

  double step_start() const { return t0_; }
  double step_end() const { return t1_; }

  // The state jumped or the right-hand side changed (impact, mode change): the cached derivative
  // no longer belongs to the state the next step starts from.
  void reset() { have_f1_ = false; }

  double dt() const { return dt_; }
  long rhs_evaluations() const { return rhs_evaluations_; }
  long steps() const { return steps_; }

 private:
  double dt_;
  double t0_ = 0.0;
  double t1_ = 0.0;
  OdeState<N> q0_{};
  OdeState<N> q1_{};
  OdeState<N> f0_{};
  OdeState<N> f1_{};
  bool have_f1_ = false;
  long rhs_evaluations_ = 0;
  long steps_ = 0;
};

}  // namespace blockfrag
