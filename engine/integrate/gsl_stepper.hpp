// GSL's odeiv2 steppers behind the engine's stepper interface, as a well-known library's answer
// in the work-precision study. Step control is GSL's standard scaled control with the same
// tolerance and per-component scale as the Dormand-Prince stepper; the dense output used for event
// location is the cubic Hermite through the step's ends (GSL's explicit steppers have none).
#pragma once

#include <memory>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include "engine/integrate/ode_state.hpp"

namespace blockfrag {

enum class GslStepperKind { rkf45, rk8pd };

template <int N>
class GslStepper {
  static_assert(N > 0, "GSL has no zero-dimensional systems");

 public:
  GslStepper(GslStepperKind kind, double tolerance, const OdeState<N>& scale)
      : step_(gsl_odeiv2_step_alloc(
            kind == GslStepperKind::rkf45 ? gsl_odeiv2_step_rkf45 : gsl_odeiv2_step_rk8pd, N)),
        evolve_(gsl_odeiv2_evolve_alloc(N)) {
    // GSL's default handler aborts the process; its status codes are checked instead.
    gsl_set_error_handler_off();
    control_.reset(gsl_odeiv2_control_scaled_new(tolerance, tolerance, 1.0, 0.0, scale.data(), N));
  }

  template <class Rhs>
  void step(const Rhs& rhs, double& t, OdeState<N>& q, double h_max) {
    Callback<Rhs> callback{&rhs, this};
    gsl_odeiv2_system system{&Callback<Rhs>::call, nullptr, N, &callback};
    if (t != t1_ || q != q1_) reset();
    if (!have_f1_) {
      rhs(t, q, f1_);
      ++rhs_evaluations_;
    }
    t0_ = t;
    q0_ = q;
    f0_ = f1_;
    if (h_ <= 0 || h_ > h_max) h_ = h_max;
    double t_new = t;
    const int status = gsl_odeiv2_evolve_apply(evolve_.get(), control_.get(), step_.get(), &system,
                                               &t_new, t + h_max, &h_, q.data());
    if (status != GSL_SUCCESS || t_new == t) {
      reset();
      q = q0_;
      throw StepSizeUnderflow(t, h_, std::string("GSL odeiv2: ") + gsl_strerror(status));
    }
    t = t_new;
    rhs(t, q, f1_);
    ++rhs_evaluations_;
    t1_ = t;
    q1_ = q;
    have_f1_ = true;
    ++steps_;
  }

  OdeState<N> dense(double t) const {
    const double h = t1_ - t0_;
    const double s = h > 0 ? (t - t0_) / h : 1.0;
    const double h00 = (1 + 2 * s) * (1 - s) * (1 - s), h10 = s * (1 - s) * (1 - s);
    const double h01 = s * s * (3 - 2 * s), h11 = s * s * (s - 1);
    OdeState<N> q;
    for (int i = 0; i < N; ++i) {
      q[i] = h00 * q0_[i] + h10 * h * f0_[i] + h01 * q1_[i] + h11 * h * f1_[i];
    }
    return q;
  }

  // Whether component i of the dense output (the cubic Hermite interpolant) moves one way
  // through the last step (a sufficient test: false may still be monotone).
  bool moves_one_way(int i) const {
    const double h = t1_ - t0_;
    const double delta = q1_[i] - q0_[i];
    const double b = h * f0_[i] - delta;
    return blockfrag::moves_one_way(delta, b, delta - h * f1_[i] - b, 0.0);
  }

  double step_start() const { return t0_; }
  double step_end() const { return t1_; }
  void reset() {
    have_f1_ = false;
    gsl_odeiv2_step_reset(step_.get());
    gsl_odeiv2_evolve_reset(evolve_.get());
  }
  long rhs_evaluations() const { return rhs_evaluations_ + gsl_rhs_evaluations_; }
  long steps() const { return steps_; }

 private:
  template <class Rhs>
  struct Callback {
    const Rhs* rhs;
    GslStepper* owner;
    static int call(double t, const double y[], double dydt[], void* params) {
      auto* self = static_cast<Callback*>(params);
      OdeState<N> q, dq;
      for (int i = 0; i < N; ++i) q[i] = y[i];
      (*self->rhs)(t, q, dq);
      for (int i = 0; i < N; ++i) dydt[i] = dq[i];
      ++self->owner->gsl_rhs_evaluations_;
      return GSL_SUCCESS;
    }
  };
  struct StepDeleter {
    void operator()(gsl_odeiv2_step* s) const { gsl_odeiv2_step_free(s); }
  };
  struct ControlDeleter {
    void operator()(gsl_odeiv2_control* c) const { gsl_odeiv2_control_free(c); }
  };
  struct EvolveDeleter {
    void operator()(gsl_odeiv2_evolve* e) const { gsl_odeiv2_evolve_free(e); }
  };

  std::unique_ptr<gsl_odeiv2_step, StepDeleter> step_;
  std::unique_ptr<gsl_odeiv2_control, ControlDeleter> control_;
  std::unique_ptr<gsl_odeiv2_evolve, EvolveDeleter> evolve_;
  double h_ = 0.0;
  double t0_ = 0.0, t1_ = -1.0;
  OdeState<N> q0_{}, q1_{}, f0_{}, f1_{};
  bool have_f1_ = false;
  long rhs_evaluations_ = 0, gsl_rhs_evaluations_ = 0, steps_ = 0;
};

}  // namespace blockfrag
