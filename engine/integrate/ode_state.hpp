// The state vector of a mode's ODE, the shape of its right-hand side, and the integrators' errors.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
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

// Whether a dense output q0 + s (delta + (1 - s) (b + s (c + (1 - s) d))) over s in [0, 1]
// (Hairer's form of the Runge-Kutta continuous extensions; d = 0 for the Hermite cubic) moves one
// way. Its slope is a1 + 2 a2 s + 3 a3 s^2 + 4 a4 s^3 (the monomial coefficients below): the
// quadratic part's range over [0, 1] is at its ends or its vertex, and the cubic term adds at most
// 4 |a4|; the slope keeps its sign if that range stays clear of zero by more.
inline bool moves_one_way(double delta, double b, double c, double d) {
  const double a1 = delta + b, a2 = c + d - b, a3 = -(c + 2.0 * d), a4 = d;
  const double at_end = a1 + 2.0 * a2 + 3.0 * a3;
  double low = std::min(a1, at_end), high = std::max(a1, at_end);
  if (a3 != 0.0) {
    const double vertex = -a2 / (3.0 * a3);
    if (vertex > 0.0 && vertex < 1.0) {
      const double at_vertex = a1 + vertex * (2.0 * a2 + 3.0 * a3 * vertex);
      low = std::min(low, at_vertex);
      high = std::max(high, at_vertex);
    }
  }
  const double cubic = 4.0 * std::abs(a4);
  return low > cubic || high < -cubic;
}

}  // namespace blockfrag
