// The adaptive Dormand-Prince 5(4) method with its fourth-order continuous extension: the
// production integrator, whose dense output lets events be located to tolerance, not to the step.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/integrate/ode_state.hpp"
#include "engine/tolerances.hpp"

namespace blockfrag {

// Follows Hairer, Norsett and Wanner's DOPRI5 (Solving ODEs I, sec. II.5 and II.6): local
// extrapolation (the fifth-order solution is kept), first same as last (a step's last stage is the
// next step's first), the PI step-size controller with Lund stabilisation, and Hairer's initial
// step heuristic. Allocation free: everything lives in std::array members.
//
// Cost: 6 right-hand-side evaluations per attempted step, plus 2 at the start and after every
// reset (the derivative at the start and the initial-step probe).
template <int N>
class DormandPrinceStepper {
 public:
  // tolerance is relative; the error of component i is measured against
  // tolerance * (scale[i] + max(|q0[i]|, |q1[i]|)), so scale[i] (> 0) is the size below which
  // component i is controlled absolutely.
  DormandPrinceStepper(double tolerance, OdeState<N> scale) : tolerance_(tolerance), scale_(scale) {
    if (!(tolerance > 0.0) || !std::isfinite(tolerance)) {
      throw ContractViolation("DormandPrinceStepper: tolerance must be positive and finite");
    }
    for (double s : scale) {
      if (!(s > 0.0) || !std::isfinite(s)) {
        throw ContractViolation("DormandPrinceStepper: every scale must be positive and finite");
      }
    }
  }

  // One accepted step from (t, q) of size <= h_max (h_max > 0, possibly infinite), retrying with
  // smaller steps as needed; overwrites t and q. A step cut short by h_max ends at exactly
  // t + h_max (in floating point) and leaves the controller's proposal for the next step intact.
  // With N = 0 there is nothing to control: the step is h_max, which must then be finite.
  // Throws StepSizeUnderflow when the controller asks for a step the time axis cannot resolve or
  // keeps rejecting; the stepper is then reset.
  template <class Rhs>
  requires OdeRhs<Rhs, N>
  void step(const Rhs& rhs, double& t, OdeState<N>& q, double h_max) {
    if (!(h_max > 0.0)) throw ContractViolation("DormandPrinceStepper::step: h_max must be > 0");
    if constexpr (N == 0) {
      if (!std::isfinite(h_max)) {
        throw ContractViolation("DormandPrinceStepper::step: h_max must be finite when N = 0");
      }
      advance_time(t, h_max);
    } else {
      step_state(rhs, t, q, h_max);
    }
  }

  // The fourth-order continuous extension (Hairer's CONTD5) of the last step; meant for t in
  // [step_start(), step_end()] (outside, it extrapolates the quartic). Costs no evaluation: it is
  // built from the stages the step already computed, the last one being f(t1, q1).
  OdeState<N> dense(double t) const {
    OdeState<N> y{};
    if constexpr (N > 0) {
      const double h = t1_ - t0_;
      if (h == 0.0) return q1_;
      const double theta = (t - t0_) / h;
      const double theta1 = 1.0 - theta;
      const auto& k = k_;
      for (int i = 0; i < N; ++i) {
        const double delta = q1_[i] - q0_[i];
        const double b = h * k[0][i] - delta;
        const double c = delta - h * k[6][i] - b;
        const double d = h * (kD1 * k[0][i] + kD3 * k[2][i] + kD4 * k[3][i] + kD5 * k[4][i] +
                              kD6 * k[5][i] + kD7 * k[6][i]);
        y[i] = q0_[i] + theta * (delta + theta1 * (b + theta * (c + theta1 * d)));
      }
    }
    return y;
  }

  // Whether component i of the dense output moves one way through the last step (a sufficient
  // test: false may still be monotone).
  bool moves_one_way(int i) const {
    const double h = t1_ - t0_;
    const auto& k = k_;
    const double delta = q1_[i] - q0_[i];
    const double b = h * k[0][i] - delta;
    const double c = delta - h * k[6][i] - b;
    const double d = h * (kD1 * k[0][i] + kD3 * k[2][i] + kD4 * k[3][i] + kD5 * k[4][i] +
                          kD6 * k[5][i] + kD7 * k[6][i]);
    return blockfrag::moves_one_way(delta, b, c, d);
  }

  double step_start() const { return t0_; }
  double step_end() const { return t1_; }

  // The state jumped or the right-hand side changed: the stored last stage is no longer the
  // derivative at the next start, and the step size is estimated afresh.
  void reset() { have_fsal_ = false; }

  long rhs_evaluations() const { return rhs_evaluations_; }
  long steps() const { return steps_; }
  long rejected_steps() const { return rejected_steps_; }

 private:
  // Controller constants of DOPRI5: safety factor, shrink at most by 5 and grow at most by 10 per
  // step, PI exponents (elementary exponent 1/5 lowered by 0.75 beta, Lund's beta = 0.04).
  static constexpr double kSafety = 0.9;
  static constexpr double kMaxShrink = 5.0;
  static constexpr double kMaxGrow = 10.0;
  static constexpr double kBeta = 0.04;
  static constexpr double kExponent = 0.2 - 0.75 * kBeta;
  static constexpr double kLogMinErrorMemory = -9.210340371976184;  // ln(1e-4), as DOPRI5

  static constexpr double kC2 = 1.0 / 5.0, kC3 = 3.0 / 10.0, kC4 = 4.0 / 5.0, kC5 = 8.0 / 9.0;
  static constexpr double kA21 = 1.0 / 5.0;
  static constexpr double kA31 = 3.0 / 40.0, kA32 = 9.0 / 40.0;
  static constexpr double kA41 = 44.0 / 45.0, kA42 = -56.0 / 15.0, kA43 = 32.0 / 9.0;
  static constexpr double kA51 = 19372.0 / 6561.0, kA52 = -25360.0 / 2187.0,
                          kA53 = 64448.0 / 6561.0, kA54 = -212.0 / 729.0;
  static constexpr double kA61 = 9017.0 / 3168.0, kA62 = -355.0 / 33.0, kA63 = 46732.0 / 5247.0,
                          kA64 = 49.0 / 176.0, kA65 = -5103.0 / 18656.0;
  static constexpr double kA71 = 35.0 / 384.0, kA73 = 500.0 / 1113.0, kA74 = 125.0 / 192.0,
                          kA75 = -2187.0 / 6784.0, kA76 = 11.0 / 84.0;
  // Fifth- minus fourth-order weights: the error estimate.
  static constexpr double kE1 = 71.0 / 57600.0, kE3 = -71.0 / 16695.0, kE4 = 71.0 / 1920.0,
                          kE5 = -17253.0 / 339200.0, kE6 = 22.0 / 525.0, kE7 = -1.0 / 40.0;
  // The quartic term of the continuous extension (Hairer's d coefficients).
  static constexpr double kD1 = -12715105075.0 / 11282082432.0, kD3 = 87487479700.0 / 32700410799.0,
                          kD4 = -10690763975.0 / 1880347072.0,
                          kD5 = 701980252875.0 / 199316789632.0, kD6 = -1453857185.0 / 822651844.0,
                          kD7 = 69997945.0 / 29380423.0;

  void advance_time(double& t, double h) {
    const double t_end = t + h;
    if (t_end == t) throw StepSizeUnderflow(t, h, "the step does not advance t");
    t0_ = t;
    t1_ = t_end;
    t = t_end;
    ++steps_;
  }

  template <class Rhs>
  void step_state(const Rhs& rhs, double& t, OdeState<N>& q, double h_max) {
    // Restarting anywhere but at the end of the last step (an interpolated event time, a jump)
    // invalidates the stored last stage just as reset() does.
    if (have_fsal_ && t == t1_ && q == q1_) {
      k_[0] = k_[6];
    } else {
      rhs(t, q, k_[0]);
      ++rhs_evaluations_;
      h_proposed_ = initial_step(rhs, t, q, h_max);
      log_error_memory_ = kLogMinErrorMemory;
    }
    have_fsal_ = false;  // until a step is accepted, k_[6] is a trial stage
    q0_ = q;
    t0_ = t;

    double h_trial = h_proposed_;
    bool rejected = false;
    for (int rejections = 0;; ++rejections) {
      const bool clipped = h_max < h_trial;
      const double h = clipped ? h_max : h_trial;
      if (!clipped && h < kMinStepUlps * std::numeric_limits<double>::epsilon() * std::abs(t)) {
        fail(t, h, "the error control needs a step below the resolution of t");
      }
      const double t_end = t + h;
      if (t_end == t) fail(t, h, "the step does not advance t");
      const double err = attempt(rhs, t, t_end - t, t_end);
      // Powers of err through one log and one exp: two calls to pow cost as much as the rest of
      // a step with a cheap right-hand side.
      const double log_err = std::log(err);  // -inf when err = 0, which the clamp turns into growth
      if (err <= 1.0) {
        const double fac = std::exp(kExponent * log_err - kBeta * log_error_memory_) / kSafety;
        double h_next = h / std::clamp(fac, 1.0 / kMaxGrow, kMaxShrink);
        if (rejected) h_next = std::min(h_next, h);
        if (clipped && h_next >= h) {
          // A breakpoint cut the step short and the controller did not ask to shrink it:
          // keep the controller's proposal and memory for the next, unconstrained step.
          h_proposed_ = std::max(h_trial, h_next);
        } else {
          h_proposed_ = h_next;
          log_error_memory_ = std::max(log_err, kLogMinErrorMemory);
        }
        t1_ = t_end;
        t = t_end;
        q = q1_;
        have_fsal_ = true;
        ++steps_;
        return;
      }
      ++rejected_steps_;
      rejected = true;
      // A non-finite error (the right-hand side blew up at a trial point) shrinks at the maximum.
      const double shrink = std::exp(kExponent * log_err) / kSafety;
      h_trial = h / (std::isfinite(err) ? std::min(kMaxShrink, shrink) : kMaxShrink);
      if (rejections + 1 >= kMaxConsecutiveRejections) {
        fail(t, h_trial, "too many consecutive rejected steps");
      }
    }
  }

  // One trial step of size h from (t0_, q0_) with k_[0] = f(t0_, q0_): the fifth-order solution in
  // q1_, all stages in k_, and the scaled RMS norm of the error estimate returned.
  template <class Rhs>
  double attempt(const Rhs& rhs, double t, double h, double t_end) {
    auto& k = k_;
    OdeState<N> y;
    for (int i = 0; i < N; ++i) y[i] = q0_[i] + h * kA21 * k[0][i];
    rhs(t + kC2 * h, y, k[1]);
    for (int i = 0; i < N; ++i) y[i] = q0_[i] + h * (kA31 * k[0][i] + kA32 * k[1][i]);
    rhs(t + kC3 * h, y, k[2]);
    for (int i = 0; i < N; ++i) {
      y[i] = q0_[i] + h * (kA41 * k[0][i] + kA42 * k[1][i] + kA43 * k[2][i]);
    }
    rhs(t + kC4 * h, y, k[3]);
    for (int i = 0; i < N; ++i) {
      y[i] = q0_[i] + h * (kA51 * k[0][i] + kA52 * k[1][i] + kA53 * k[2][i] + kA54 * k[3][i]);
    }
    rhs(t + kC5 * h, y, k[4]);
    for (int i = 0; i < N; ++i) {
      y[i] = q0_[i] + h * (kA61 * k[0][i] + kA62 * k[1][i] + kA63 * k[2][i] + kA64 * k[3][i] +
                           kA65 * k[4][i]);
    }
    rhs(t_end, y, k[5]);
    for (int i = 0; i < N; ++i) {
      q1_[i] = q0_[i] + h * (kA71 * k[0][i] + kA73 * k[2][i] + kA74 * k[3][i] + kA75 * k[4][i] +
                             kA76 * k[5][i]);
    }
    rhs(t_end, q1_, k[6]);
    rhs_evaluations_ += 6;

    double sum = 0.0;
    for (int i = 0; i < N; ++i) {
      const double e = h * (kE1 * k[0][i] + kE3 * k[2][i] + kE4 * k[3][i] + kE5 * k[4][i] +
                            kE6 * k[5][i] + kE7 * k[6][i]);
      const double sk = tolerance_ * (scale_[i] + std::max(std::abs(q0_[i]), std::abs(q1_[i])));
      sum += (e / sk) * (e / sk);
    }
    return std::sqrt(sum / N);
  }

  // Hairer's HINIT for a method of order 5: a first guess from |q| / |f|, refined by an Euler probe
  // that estimates the second derivative; k_[0] holds f(t, q). Costs one evaluation. The probe
  // stays within h_max (past a breakpoint the right-hand side may change), but the estimate is not
  // bounded by it: a breakpoint just after a reset clips that step, not the proposal after it.
  template <class Rhs>
  double initial_step(const Rhs& rhs, double t, const OdeState<N>& q, double h_max) {
    OdeState<N> sk;
    double dnf = 0.0;
    double dny = 0.0;
    for (int i = 0; i < N; ++i) {
      sk[i] = tolerance_ * (scale_[i] + std::abs(q[i]));
      dnf += (k_[0][i] / sk[i]) * (k_[0][i] / sk[i]);
      dny += (q[i] / sk[i]) * (q[i] / sk[i]);
    }
    const double h0 = (dnf <= 1e-10 || dny <= 1e-10) ? 1e-6 : 0.01 * std::sqrt(dny / dnf);

    const double probe = std::min(h0, h_max);
    OdeState<N> y;
    for (int i = 0; i < N; ++i) y[i] = q[i] + probe * k_[0][i];
    OdeState<N> f;
    rhs(t + probe, y, f);
    ++rhs_evaluations_;
    double der2 = 0.0;
    for (int i = 0; i < N; ++i) der2 += ((f[i] - k_[0][i]) / sk[i]) * ((f[i] - k_[0][i]) / sk[i]);
    der2 = std::sqrt(der2) / probe;
    const double der12 = std::max(der2, std::sqrt(dnf));
    const double h1 = der12 <= 1e-15 ? std::max(1e-6, h0 * 1e-3) : std::pow(0.01 / der12, 0.2);
    return std::min(100.0 * h0, h1);
  }

  [[noreturn]] void fail(double t, double h, const char* why) {
    have_fsal_ = false;
    t0_ = t1_ = t;
    q1_ = q0_;
    throw StepSizeUnderflow(t, h, why);
  }

  double tolerance_;
  OdeState<N> scale_;
  double h_proposed_ = 0.0;
  double log_error_memory_ = kLogMinErrorMemory;  // ln(previous accepted error): the PI memory
  double t0_ = 0.0;
  double t1_ = 0.0;
  OdeState<N> q0_{};
  OdeState<N> q1_{};
  std::array<OdeState<N>, 7> k_{};  // the stages of the last step; k_[6] = f(t1, q1)
  bool have_fsal_ = false;
  long rhs_evaluations_ = 0;
  long steps_ = 0;
  long rejected_steps_ = 0;
};

}  // namespace blockfrag
