// Orders of convergence of the integrators, measured on nonlinear problems with closed forms:
// the slope of log(error) against log(step) over a halving sequence of steps.
#include <array>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "engine/integrate/dormand_prince_stepper.hpp"
#include "engine/integrate/rk4_stepper.hpp"

namespace blockfrag {
namespace {

// The pendulum theta'' = -sin(theta) on its separatrix: theta = 4 atan(e^t) - pi,
// theta' = 2 sech(t). Strongly nonlinear: theta sweeps most of (-pi, pi) over t in [-2, 2].
struct Pendulum {
  static constexpr int kN = 2;
  static constexpr double kStart = -2.0;
  static constexpr double kEnd = 2.0;
  void operator()(double, const OdeState<2>& q, OdeState<2>& dq) const {
    dq[0] = q[1];
    dq[1] = -std::sin(q[0]);
  }
  static OdeState<2> exact(double t) {
    return {4.0 * std::atan(std::exp(t)) - std::numbers::pi, 2.0 / std::cosh(t)};
  }
};

// A nonlinear, non-autonomous scalar problem (it exercises the stages' times):
// q' = -2 t q^2, q = 1 / (1 + t^2). It starts away from t = 0, where q' = 0 would make the
// adaptive stepper's first step tiny.
struct Riccati {
  static constexpr int kN = 1;
  static constexpr double kStart = 0.5;
  static constexpr double kEnd = 2.5;
  void operator()(double t, const OdeState<1>& q, OdeState<1>& dq) const {
    dq[0] = -2.0 * t * q[0] * q[0];
  }
  static OdeState<1> exact(double t) { return {1.0 / (1.0 + t * t)}; }
};

// std::size_t, not int: an int N cannot be deduced through the OdeState alias.
template <std::size_t N>
double max_error(const std::array<double, N>& a, const std::array<double, N>& b) {
  double e = 0.0;
  for (std::size_t i = 0; i < N; ++i) e = std::max(e, std::abs(a[i] - b[i]));
  return e;
}

// Least-squares slope of log(error) against log(h).
double fitted_order(const std::vector<double>& h, const std::vector<double>& error) {
  double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
  const double n = static_cast<double>(h.size());
  for (std::size_t i = 0; i < h.size(); ++i) {
    const double x = std::log(h[i]);
    const double y = std::log(error[i]);
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

template <class Problem>
double rk4_global_error(double dt) {
  Rk4Stepper<Problem::kN> stepper(dt);
  double t = Problem::kStart;
  OdeState<Problem::kN> q = Problem::exact(t);
  while (t < Problem::kEnd) stepper.step(Problem{}, t, q, Problem::kEnd - t);
  EXPECT_EQ(t, Problem::kEnd);
  return max_error(q, Problem::exact(t));
}

// One step of size h from the exact state at t0, by either stepper, with the error at the step's
// end and of the dense output at theta = 1/2 (the interior point where interpolation errs most).
struct LocalErrors {
  double end;
  double middle;
};
template <class Problem, class Stepper>
LocalErrors local_errors(Stepper stepper, double t0, double h) {
  double t = t0;
  OdeState<Problem::kN> q = Problem::exact(t0);
  stepper.step(Problem{}, t, q, h);
  // The order can only be read off if the step really had size h (the adaptive stepper's proposal
  // must not have cut it).
  EXPECT_NEAR(stepper.step_end() - stepper.step_start(), h, 1e-15);
  const double middle = t0 + 0.5 * h;
  return {max_error(q, Problem::exact(t)),
          max_error(stepper.dense(middle), Problem::exact(middle))};
}

// A Dormand-Prince stepper whose error control never intervenes: a tolerance this loose accepts
// every step the tests ask for, so it takes exactly the steps h_max prescribes.
template <int N>
DormandPrinceStepper<N> uncontrolled_dopri() {
  OdeState<N> scale;
  scale.fill(1.0);
  return DormandPrinceStepper<N>(1.0, scale);
}

template <class Problem>
double dopri_fixed_step_global_error(double h) {
  auto stepper = uncontrolled_dopri<Problem::kN>();
  double t = Problem::kStart;
  OdeState<Problem::kN> q = Problem::exact(t);
  const int n = static_cast<int>(std::lround((Problem::kEnd - Problem::kStart) / h));
  for (int i = 0; i < n; ++i) {
    const double t_next = i + 1 == n ? Problem::kEnd : Problem::kStart + (i + 1) * h;
    stepper.step(Problem{}, t, q, t_next - t);
    EXPECT_EQ(t, t_next) << "the controller cut a step short";
  }
  EXPECT_EQ(stepper.rejected_steps(), 0);
  EXPECT_EQ(stepper.steps(), n);
  EXPECT_EQ(t, Problem::kEnd);
  return max_error(q, Problem::exact(t));
}

template <class Problem>
void expect_rk4_global_order_4() {
  const std::vector<double> dts{0.04, 0.02, 0.01, 0.005};
  std::vector<double> errors;
  for (double dt : dts) errors.push_back(rk4_global_error<Problem>(dt));
  EXPECT_NEAR(fitted_order(dts, errors), 4.0, 0.15);
}

TEST(ConvergenceOrder, Rk4GlobalErrorFallsAsDtToTheFourth) {
  expect_rk4_global_order_4<Pendulum>();
  expect_rk4_global_order_4<Riccati>();
}

template <class Problem>
void expect_rk4_hermite_order_4(double t0) {
  const std::vector<double> hs{0.08, 0.04, 0.02, 0.01};
  std::vector<double> end_errors;
  std::vector<double> middle_errors;
  for (double h : hs) {
    const LocalErrors e = local_errors<Problem>(Rk4Stepper<Problem::kN>(h), t0, h);
    end_errors.push_back(e.end);
    middle_errors.push_back(e.middle);
  }
  // RK4's local error is O(h^5); the cubic Hermite interpolant's is O(h^4), so the interpolation
  // error dominates in the interior.
  EXPECT_NEAR(fitted_order(hs, end_errors), 5.0, 0.2);
  EXPECT_NEAR(fitted_order(hs, middle_errors), 4.0, 0.15);
}

TEST(ConvergenceOrder, Rk4HermiteDenseOutputErrsAsHToTheFourthInside) {
  expect_rk4_hermite_order_4<Pendulum>(-0.5);
  expect_rk4_hermite_order_4<Riccati>(1.0);
}

template <class Problem>
void expect_dopri_local_orders(double t0) {
  const std::vector<double> hs{0.2, 0.1, 0.05, 0.025};
  std::vector<double> end_errors;
  std::vector<double> middle_errors;
  for (double h : hs) {
    const LocalErrors e = local_errors<Problem>(uncontrolled_dopri<Problem::kN>(), t0, h);
    end_errors.push_back(e.end);
    middle_errors.push_back(e.middle);
  }
  // A fifth-order method with local extrapolation: the step's local error is O(h^6) (its
  // embedded fourth-order estimate is O(h^5)); the fourth-order continuous extension errs O(h^5)
  // inside the step. The usable range of h is narrow for a sixth power (the largest steps are
  // not yet asymptotic, the smallest near round-off: 1e-13 at h = 0.025), hence +/- 0.5, which
  // still tells 6 from the 5 of a step that kept the fourth-order solution.
  EXPECT_NEAR(fitted_order(hs, end_errors), 6.0, 0.5);
  EXPECT_NEAR(fitted_order(hs, middle_errors), 5.0, 0.25);
}

TEST(ConvergenceOrder, DormandPrinceLocalErrorsFallAsHToTheSixthAndFifth) {
  expect_dopri_local_orders<Pendulum>(-0.5);
  expect_dopri_local_orders<Riccati>(1.0);
}

TEST(ConvergenceOrder, DormandPrinceGlobalErrorFallsAsHToTheFifth) {
  // The pendulum only: on the Riccati problem the sixth-order term still dominates at these steps
  // (slopes 5.9, 5.5, 5.3, 5.2 down to h = 0.0125, then round-off), while its local orders above
  // already check the stage times of a non-autonomous problem.
  const std::vector<double> hs{0.1, 0.05, 0.025, 0.0125};
  std::vector<double> errors;
  for (double h : hs) errors.push_back(dopri_fixed_step_global_error<Pendulum>(h));
  EXPECT_NEAR(fitted_order(hs, errors), 5.0, 0.2);
}

}  // namespace
}  // namespace blockfrag
