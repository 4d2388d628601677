// The state vector of a mode's ODE, the shape of its right-hand side, and the integrators' errors.
#pragma once

#include <array>
#include <concepts>
#include <cstdio>
#include <string>

#include "engine/errors.hpp"

namespace blockfrag {

// A fixed-size state: no heap, copied by value. N may be 0 (a mode with no ODE, such as rest).
// std::array's size is a std::size_t, so a function template that deduces the size from its
// argument must declare it std::size_t: `template <int N> f(const OdeState<N>&)` cannot deduce it.
template <int N>
using OdeState = std::array<double, N>;

// dq = f(t, q), written into dq (which holds garbage on entry).
template <class Rhs, int N>
concept OdeRhs = requires(const Rhs& rhs, double t, const OdeState<N>& q, OdeState<N>& dq) {
  { rhs(t, q, dq) } -> std::same_as<void>;
};

// The adaptive integrator could not meet its tolerance with a step the time axis can still resolve
// (or kept rejecting): a singularity, a non-finite right-hand side, or a tolerance below round-off.
class StepSizeUnderflow : public SimulationFailure {
 public:
  StepSizeUnderflow(double t, double h, const std::string& why)
      : SimulationFailure(message(t, h, why)), t_(t), h_(h) {}
  double time() const { return t_; }
  double step_size() const { return h_; }

 private:
  static std::string message(double t, double h, const std::string& why) {
    char where[96];
    std::snprintf(where, sizeof where, "step size underflow at t = %.17g s (h = %.3g s): ", t, h);
    return where + why;
  }

  double t_;
  double h_;
};

}  // namespace blockfrag
