// The two ODE integrators against closed forms: accuracy, dense output, evaluation counts, resets,
// breakpoints, N = 0, error control and its failure mode. No heap allocation while stepping.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <new>
#include <numbers>

#include <gtest/gtest.h>

#include "engine/errors.hpp"
#include "engine/integrate/dormand_prince_stepper.hpp"
#include "engine/integrate/rk4_stepper.hpp"

namespace {
std::atomic<long> g_allocations{0};
}  // namespace

// Counting replacements for the global allocation functions of this test executable: the steppers
// must not allocate, and the count over a stepping loop proves it. Not inlined, or GCC pairs the
// inlined free() with new-expressions and warns of a mismatch (-Wmismatched-new-delete).
[[gnu::noinline]] void* operator new(std::size_t size) {
  ++g_allocations;
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
[[gnu::noinline]] void operator delete(void* p) noexcept { std::free(p); }
[[gnu::noinline]] void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace blockfrag {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

struct Decay {  // q' = -q, q = q0 exp(-t)
  void operator()(double, const OdeState<1>& q, OdeState<1>& dq) const { dq[0] = -q[0]; }
};

struct Oscillator {  // q'' = -q from (1, 0): q = cos t, q' = -sin t
  void operator()(double, const OdeState<2>& q, OdeState<2>& dq) const {
    dq[0] = q[1];
    dq[1] = -q[0];
  }
  static OdeState<2> exact(double t) { return {std::cos(t), -std::sin(t)}; }
};

// Counts its calls independently of the stepper's own count.
template <class Rhs, int N>
struct Counted {
  Rhs rhs;
  long* calls;
  void operator()(double t, const OdeState<N>& q, OdeState<N>& dq) const {
    ++*calls;
    rhs(t, q, dq);
  }
};

double max_error(const OdeState<2>& a, const OdeState<2>& b) {
  return std::max(std::abs(a[0] - b[0]), std::abs(a[1] - b[1]));
}

// ---------------------------------------------------------------------------------------------
// RK4

TEST(Rk4Stepper, DecayEqualsTheSchemesClosedFormAndIsFourthOrderAccurate) {
  // On q' = -q one RK4 step multiplies q by the degree-4 Taylor polynomial R(z) of exp(z), z = -dt.
  const double dt = 0.01;
  Rk4Stepper<1> stepper(dt);
  double t = 0.0;
  OdeState<1> q{1.0};
  for (int n = 0; n < 100; ++n) stepper.step(Decay{}, t, q, kInf);
  const double z = -dt;
  const double r = 1.0 + z + z * z / 2.0 + z * z * z / 6.0 + z * z * z * z / 24.0;
  EXPECT_NEAR(q[0], std::pow(r, 100), 1e-15);
  // Per step R(z) - exp(z) = -z^5 / 120 + O(z^6), so after n steps q - exp(-t) ~ n dt^5 / 120 e^-t.
  const double predicted = 100 * std::pow(dt, 5) / 120.0 * std::exp(-1.0);
  EXPECT_NEAR(q[0] - std::exp(-t), predicted, 0.05 * predicted);
  EXPECT_NEAR(t, 1.0, 1e-13);
}

TEST(Rk4Stepper, OscillatorPhaseErrorMatchesTheory) {
  // RK4 on the oscillator lags by dt^5 / 120 rad per step (the amplitude error is O(dt^6)), so
  // after time T the error is T dt^4 / 120.
  const double dt = 0.01;
  Rk4Stepper<2> stepper(dt);
  double t = 0.0;
  OdeState<2> q = Oscillator::exact(0.0);
  for (int n = 0; n < 1000; ++n) stepper.step(Oscillator{}, t, q, kInf);
  const double predicted = t * std::pow(dt, 4) / 120.0;
  const double error = max_error(q, Oscillator::exact(t));
  EXPECT_GT(error, 0.8 * predicted);
  EXPECT_LT(error, 1.2 * predicted);
  EXPECT_EQ(stepper.steps(), 1000);
}

TEST(Rk4Stepper, DenseOutputIsTheHermiteCubicOfTheStep) {
  const double dt = 0.1;
  Rk4Stepper<2> stepper(dt);
  double t = 0.0;
  OdeState<2> q = Oscillator::exact(0.0);
  for (int n = 0; n < 20; ++n) {
    const OdeState<2> q_start = q;
    stepper.step(Oscillator{}, t, q, kInf);
    EXPECT_EQ(stepper.dense(stepper.step_start()), q_start);
    EXPECT_EQ(stepper.dense(stepper.step_end()), q);
    // The Hermite error of a function whose fourth derivative is bounded by 1 is at most
    // dt^4 / 384; the integration error carried in by the step's ends is at most
    // t_end dt^4 / 120 (see the phase error test above).
    const double bound = std::pow(dt, 4) / 384.0 + stepper.step_end() * std::pow(dt, 4) / 120.0;
    for (double theta : {0.25, 0.5, 0.75}) {
      const double s = stepper.step_start() + theta * dt;
      EXPECT_LT(max_error(stepper.dense(s), Oscillator::exact(s)), bound) << "t = " << s;
    }
  }
}

// The dense output stays within dense_spread of the range between a step's ends, and comes close
// to that bound where the component turns inside the step (the oscillator over steps of 0.1 to 3
// rad from random phases): the seat's flight claims rest on it.
TEST(Rk4Stepper, DenseOutputStaysWithinItsSpreadOfTheChord) {
  double closest = 0.0;  // of the largest stray to its bound
  for (int n = 0; n < 200; ++n) {
    const double t0 = 0.37 * n, h = 0.1 + 2.9 * ((n * 7919) % 200) / 200.0;
    Rk4Stepper<2> stepper(h);
    double t = t0;
    OdeState<2> q = Oscillator::exact(t0);
    const OdeState<2> start = q;
    stepper.step(Oscillator{}, t, q, kInf);
    for (int i = 0; i < 2; ++i) {
      const double lo = std::min(start[i], q[i]), hi = std::max(start[i], q[i]);
      const double spread = stepper.dense_spread(i);
      for (int k = 0; k <= 200; ++k) {
        const double y = stepper.dense(t0 + h * k / 200)[i];
        const double strays = std::max(lo - y, y - hi);
        EXPECT_LE(strays, spread * (1 + 1e-12) + 1e-15) << "step " << n << " component " << i;
        if (spread > 1e-3) closest = std::max(closest, strays / spread);
      }
    }
  }
  EXPECT_GT(closest, 0.5);
}

TEST(Rk4Stepper, CountsEveryEvaluationAndReusesTheEndDerivative) {
  long calls = 0;
  const Counted<Oscillator, 2> rhs{Oscillator{}, &calls};
  Rk4Stepper<2> stepper(0.01);
  double t = 0.0;
  OdeState<2> q = Oscillator::exact(0.0);
  stepper.step(rhs, t, q, kInf);
  EXPECT_EQ(calls, 5);  // f(t0), three inner stages, f(t1) which is the next step's first stage
  for (int n = 0; n < 9; ++n) stepper.step(rhs, t, q, kInf);
  EXPECT_EQ(calls, 5 + 4 * 9);
  stepper.reset();
  stepper.step(rhs, t, q, kInf);
  EXPECT_EQ(calls, 5 + 4 * 9 + 5);
  // Restarting from an interpolated point (an event time) must not reuse f(t1).
  t = 0.5 * (stepper.step_start() + stepper.step_end());
  q = stepper.dense(t);
  stepper.step(rhs, t, q, kInf);
  EXPECT_EQ(calls, 5 + 4 * 9 + 5 + 5);
  EXPECT_EQ(stepper.rhs_evaluations(), calls);
  EXPECT_EQ(stepper.steps(), 12);
}

TEST(Rk4Stepper, ResetDropsTheCachedDerivativeAfterAJump) {
  // A mode change keeps (t, q) but changes the right-hand side: without reset() the first stage
  // would be the old mode's derivative.
  struct Push {  // q' = c
    double c;
    void operator()(double, const OdeState<1>&, OdeState<1>& dq) const { dq[0] = c; }
  };
  Rk4Stepper<1> stepper(0.1);
  double t = 0.0;
  OdeState<1> q{0.0};
  stepper.step(Push{1.0}, t, q, kInf);
  EXPECT_DOUBLE_EQ(q[0], 0.1);
  stepper.reset();
  stepper.step(Push{-2.0}, t, q, kInf);
  EXPECT_NEAR(q[0], 0.1 - 0.2, 1e-15);
  // The Hermite cubic of the new step is the straight line of the new mode.
  EXPECT_NEAR(stepper.dense(0.15)[0], 0.1 - 0.1, 1e-15);
}

TEST(Rk4Stepper, HonoursHmaxExactlyWithoutChangingDt) {
  Rk4Stepper<2> stepper(0.01);
  double t = 0.3;
  OdeState<2> q = Oscillator::exact(t);
  stepper.step(Oscillator{}, t, q, 0.0037);
  EXPECT_EQ(t, 0.3 + 0.0037);
  EXPECT_EQ(stepper.step_start(), 0.3);
  EXPECT_EQ(stepper.step_end(), 0.3 + 0.0037);
  const double t_before = t;
  stepper.step(Oscillator{}, t, q, 1.0);
  EXPECT_EQ(t, t_before + 0.01);
  EXPECT_LT(max_error(q, Oscillator::exact(t)), 1e-12);
}

TEST(Rk4Stepper, WorksWithoutAnOde) {
  long calls = 0;
  struct Nothing {
    long* calls;
    void operator()(double, const OdeState<0>&, OdeState<0>&) const { ++*calls; }
  };
  Rk4Stepper<0> stepper(0.25);
  double t = 1.0;
  OdeState<0> q{};
  stepper.step(Nothing{&calls}, t, q, kInf);
  stepper.step(Nothing{&calls}, t, q, 0.1);
  EXPECT_EQ(t, 1.0 + 0.25 + 0.1);
  EXPECT_EQ(stepper.step_start(), 1.25);
  EXPECT_EQ(stepper.dense(1.3).size(), 0u);
  EXPECT_EQ(stepper.steps(), 2);
  EXPECT_EQ(stepper.rhs_evaluations(), 0);
  EXPECT_EQ(calls, 0);
}

TEST(Rk4Stepper, RefusesBadArguments) {
  EXPECT_THROW(Rk4Stepper<1>(0.0), ContractViolation);
  EXPECT_THROW(Rk4Stepper<1>(-1e-3), ContractViolation);
  EXPECT_THROW(Rk4Stepper<1>(std::nan("")), ContractViolation);
  Rk4Stepper<1> stepper(0.1);
  double t = 0.0;
  OdeState<1> q{1.0};
  EXPECT_THROW(stepper.step(Decay{}, t, q, 0.0), ContractViolation);
  EXPECT_THROW(stepper.step(Decay{}, t, q, std::nan("")), ContractViolation);
  t = 1e20;  // dt is below half an ulp of t: the step would not move
  EXPECT_THROW(stepper.step(Decay{}, t, q, kInf), StepSizeUnderflow);
}

// ---------------------------------------------------------------------------------------------
// Dormand-Prince

// Integrates the oscillator from 0 to t_end (landing on it with h_max) and returns the largest
// error at the step ends and, separately, of the dense output at points inside the steps.
struct AdaptiveRun {
  double end_error = 0.0;
  double dense_error = 0.0;
  long steps = 0;
};
AdaptiveRun run_oscillator(double tolerance, double t_end) {
  DormandPrinceStepper<2> stepper(tolerance, {1.0, 1.0});
  AdaptiveRun run;
  double t = 0.0;
  OdeState<2> q = Oscillator::exact(0.0);
  while (t < t_end) {
    stepper.step(Oscillator{}, t, q, t_end - t);
    run.end_error = std::max(run.end_error, max_error(q, Oscillator::exact(t)));
    for (double theta : {0.2, 0.5, 0.8}) {
      const double s = stepper.step_start() + theta * (stepper.step_end() - stepper.step_start());
      run.dense_error =
          std::max(run.dense_error, max_error(stepper.dense(s), Oscillator::exact(s)));
    }
  }
  EXPECT_EQ(t, t_end);
  run.steps = stepper.steps();
  return run;
}

TEST(DormandPrinceStepper, DecayMatchesClosedForm) {
  DormandPrinceStepper<1> stepper(1e-10, {1.0});
  double t = 0.0;
  OdeState<1> q{1.0};
  while (t < 5.0) stepper.step(Decay{}, t, q, 5.0 - t);
  EXPECT_EQ(t, 5.0);
  // The error relative to scale + |q| ~ 1 stays within a small multiple of the tolerance.
  EXPECT_NEAR(q[0], std::exp(-5.0), 1e-9);
}

TEST(DormandPrinceStepper, GlobalErrorScalesWithTolerance) {
  // One period of the oscillator. With local extrapolation DOPRI5's global error is close to
  // proportional to the tolerance: 1e4 apart in tolerance should give about 1e4 in error.
  const double t_end = 2.0 * std::numbers::pi;
  const AdaptiveRun loose = run_oscillator(1e-6, t_end);
  const AdaptiveRun tight = run_oscillator(1e-10, t_end);
  // A small multiple of the tolerance: each step's error is measured against
  // tolerance * (1 + |q|), up to 2 tolerance, and the phase error accumulates over the period.
  EXPECT_LT(loose.end_error, 5 * 1e-6);
  EXPECT_LT(tight.end_error, 5 * 1e-10);
  const double ratio = loose.end_error / tight.end_error;
  EXPECT_GT(ratio, 0.5e4);
  EXPECT_LT(ratio, 2e4);
  // The steps follow tolerance^(-1/5): 1e4 in tolerance is 10^(4/5) = 6.3 in step count.
  const double step_ratio = static_cast<double>(tight.steps) / static_cast<double>(loose.steps);
  EXPECT_NEAR(step_ratio, std::pow(10.0, 0.8), 1.0);
}

TEST(DormandPrinceStepper, DenseOutputIsAsAccurateAsTheSteps) {
  const double t_end = 4.0 * std::numbers::pi;
  for (double tolerance : {1e-6, 1e-9}) {
    const AdaptiveRun run = run_oscillator(tolerance, t_end);
    // The continuous extension is of order 4 against the steps' 5: between the ends it may lose
    // a little, but stays within a small multiple of the tolerance.
    EXPECT_LT(run.dense_error, 20 * tolerance) << "tolerance " << tolerance;
    EXPECT_LT(run.dense_error, 5 * run.end_error + 10 * tolerance) << "tolerance " << tolerance;
  }
}

TEST(DormandPrinceStepper, DenseOutputIsExactAtTheEndsOfTheStep) {
  DormandPrinceStepper<2> stepper(1e-8, {1.0, 1.0});
  double t = 0.0;
  OdeState<2> q = Oscillator::exact(0.0);
  for (int n = 0; n < 5; ++n) {
    const OdeState<2> q_start = q;
    stepper.step(Oscillator{}, t, q, kInf);
    EXPECT_EQ(stepper.dense(stepper.step_start()), q_start);
    const OdeState<2> at_end = stepper.dense(stepper.step_end());
    EXPECT_NEAR(at_end[0], q[0], 1e-15);
    EXPECT_NEAR(at_end[1], q[1], 1e-15);
  }
}

TEST(DormandPrinceStepper, CountsEveryEvaluationWithFirstSameAsLast) {
  long calls = 0;
  const Counted<Oscillator, 2> rhs{Oscillator{}, &calls};
  DormandPrinceStepper<2> stepper(1e-8, {1.0, 1.0});
  double t = 0.0;
  OdeState<2> q = Oscillator::exact(0.0);
  stepper.step(rhs, t, q, kInf);
  // f(t0), the initial-step probe, then six stages (the seventh is f(t1)); no rejection expected
  // on this smooth problem.
  EXPECT_EQ(stepper.rejected_steps(), 0);
  EXPECT_EQ(calls, 8);
  for (int n = 0; n < 20; ++n) stepper.step(rhs, t, q, kInf);
  EXPECT_EQ(stepper.rejected_steps(), 0);
  EXPECT_EQ(calls, 8 + 6 * 20);
  const long before_reset = calls;
  stepper.reset();
  stepper.step(rhs, t, q, kInf);
  EXPECT_EQ(calls, before_reset + 8);
  // Restarting from an interpolated point (an event time) must not reuse f(t1) as the first stage.
  const long before_restart = calls;
  t = 0.5 * (stepper.step_start() + stepper.step_end());
  q = stepper.dense(t);
  stepper.step(rhs, t, q, kInf);
  EXPECT_EQ(calls, before_restart + 8);
  EXPECT_LT(max_error(q, Oscillator::exact(t)), 1e-7);
  EXPECT_EQ(stepper.rhs_evaluations(), calls);
  EXPECT_EQ(stepper.steps(), 23);
  EXPECT_EQ(stepper.rejected_steps(), 0);
}

TEST(DormandPrinceStepper, CountsRejectedAttempts) {
  // A forcing that switches on at t = 1 (an event the caller did not locate): the controller must
  // reject steps across the jump and still meet the tolerance.
  struct Switched {
    long* calls;
    void operator()(double t, const OdeState<1>&, OdeState<1>& dq) const {
      ++*calls;
      dq[0] = t < 1.0 ? 0.0 : 1.0;
    }
  };
  long calls = 0;
  DormandPrinceStepper<1> stepper(1e-8, {1.0});
  double t = 0.0;
  OdeState<1> q{0.0};
  while (t < 2.0) stepper.step(Switched{&calls}, t, q, 2.0 - t);
  EXPECT_GT(stepper.rejected_steps(), 0);
  EXPECT_EQ(calls, 2 + 6 * (stepper.steps() + stepper.rejected_steps()));
  EXPECT_EQ(stepper.rhs_evaluations(), calls);
  // Across a jump the error estimate is not asymptotically right, so the error is a larger
  // multiple of the tolerance than on smooth problems (about 40 here), yet still small.
  EXPECT_NEAR(q[0], 1.0, 100 * 1e-8);
}

TEST(DormandPrinceStepper, ResetRestartsFromTheNewRightHandSide) {
  struct Push {  // q' = c
    double c;
    void operator()(double, const OdeState<1>&, OdeState<1>& dq) const { dq[0] = c; }
  };
  DormandPrinceStepper<1> stepper(1e-8, {1.0});
  double t = 0.0;
  OdeState<1> q{0.0};
  // From q = 0 the initial-step heuristic starts small (1e-4 here) and the controller grows it.
  while (t < 0.5) stepper.step(Push{1.0}, t, q, 0.5 - t);
  EXPECT_EQ(t, 0.5);
  EXPECT_NEAR(q[0], 0.5, 1e-15);
  stepper.reset();
  const long steps_before = stepper.steps();
  stepper.step(Push{-2.0}, t, q, 0.25);
  // Had the stored last stage (+1) been reused, this first step would already be off.
  EXPECT_NEAR(q[0], 0.5 - 2.0 * (t - 0.5), 1e-15);
  while (t < 0.75) stepper.step(Push{-2.0}, t, q, 0.75 - t);
  EXPECT_NEAR(q[0], 0.5 - 0.5, 1e-15);
  EXPECT_GT(stepper.steps() - steps_before, 1);  // the step size was estimated afresh
  const double mid = 0.5 * (stepper.step_start() + stepper.step_end());
  EXPECT_NEAR(stepper.dense(mid)[0], 0.5 - 2.0 * (mid - 0.5), 1e-15);
}

TEST(DormandPrinceStepper, HonoursHmaxExactlyAndKeepsItsProposal) {
  // Two runs of the same problem; the second is cut by a breakpoint 1e-4 after its third step.
  // The step after the breakpoint must be about as long as the undisturbed run's step, not grown
  // back from 1e-4 at most tenfold per step.
  const double tolerance = 1e-7;
  DormandPrinceStepper<2> free_run(tolerance, {1.0, 1.0});
  DormandPrinceStepper<2> cut_run(tolerance, {1.0, 1.0});
  double t_free = 0.0;
  double t_cut = 0.0;
  OdeState<2> q_free = Oscillator::exact(0.0);
  OdeState<2> q_cut = q_free;
  for (int n = 0; n < 3; ++n) {
    free_run.step(Oscillator{}, t_free, q_free, kInf);
    cut_run.step(Oscillator{}, t_cut, q_cut, kInf);
  }
  free_run.step(Oscillator{}, t_free, q_free, kInf);
  const double free_step = free_run.step_end() - free_run.step_start();

  const double start = t_cut;
  cut_run.step(Oscillator{}, t_cut, q_cut, 1e-4);
  EXPECT_EQ(t_cut, start + 1e-4);
  EXPECT_EQ(cut_run.step_end(), start + 1e-4);
  EXPECT_LT(max_error(q_cut, Oscillator::exact(t_cut)), 10 * tolerance);
  cut_run.step(Oscillator{}, t_cut, q_cut, kInf);
  const double next_step = cut_run.step_end() - cut_run.step_start();
  EXPECT_GT(free_step, 100 * 1e-4);
  EXPECT_NEAR(next_step, free_step, 0.2 * free_step);
  EXPECT_EQ(cut_run.rejected_steps(), 0);
}

TEST(DormandPrinceStepper, ABreakpointRightAfterAResetDoesNotShrinkTheInitialEstimate) {
  DormandPrinceStepper<2> free_run(1e-8, {1.0, 1.0});
  DormandPrinceStepper<2> cut_run(1e-8, {1.0, 1.0});
  double t_free = 0.0;
  double t_cut = 0.0;
  OdeState<2> q_free = Oscillator::exact(0.0);
  OdeState<2> q_cut = q_free;
  free_run.step(Oscillator{}, t_free, q_free, kInf);
  cut_run.step(Oscillator{}, t_cut, q_cut, 1e-6);
  EXPECT_EQ(t_cut, 1e-6);
  cut_run.step(Oscillator{}, t_cut, q_cut, kInf);
  // Both proposals are the initial estimate at t = 0; grown from 1e-6 it would be at most 1e-5.
  const double free_step = free_run.step_end() - free_run.step_start();
  EXPECT_GT(free_step, 1e-3);
  EXPECT_NEAR(cut_run.step_end() - cut_run.step_start(), free_step, 1e-12 * free_step);
  EXPECT_EQ(cut_run.rejected_steps(), 0);
}

TEST(DormandPrinceStepper, WorksWithoutAnOde) {
  long calls = 0;
  struct Nothing {
    long* calls;
    void operator()(double, const OdeState<0>&, OdeState<0>&) const { ++*calls; }
  };
  DormandPrinceStepper<0> stepper(1e-8, {});
  double t = 2.0;
  OdeState<0> q{};
  stepper.step(Nothing{&calls}, t, q, 0.5);
  stepper.step(Nothing{&calls}, t, q, 0.125);
  EXPECT_EQ(t, 2.625);
  EXPECT_EQ(stepper.step_start(), 2.5);
  EXPECT_EQ(stepper.step_end(), 2.625);
  EXPECT_EQ(stepper.dense(2.6).size(), 0u);
  EXPECT_EQ(stepper.steps(), 2);
  EXPECT_EQ(stepper.rhs_evaluations(), 0);
  EXPECT_EQ(calls, 0);
  EXPECT_THROW(stepper.step(Nothing{&calls}, t, q, kInf), ContractViolation);
}

TEST(DormandPrinceStepper, ThrowsOnStepSizeUnderflowAtABlowUp) {
  // q' = q^2 from q(0) = 1 is 1 / (1 - t): the steps shrink towards t = 1 until they cannot.
  struct BlowUp {
    void operator()(double, const OdeState<1>& q, OdeState<1>& dq) const { dq[0] = q[0] * q[0]; }
  };
  DormandPrinceStepper<1> stepper(1e-8, {1.0});
  double t = 0.0;
  OdeState<1> q{1.0};
  bool threw = false;
  try {
    for (int n = 0; n < 1'000'000; ++n) stepper.step(BlowUp{}, t, q, kInf);
  } catch (const StepSizeUnderflow& e) {
    threw = true;
    EXPECT_NEAR(e.time(), 1.0, 1e-6);
    EXPECT_LT(e.step_size(), 1e-6);
  }
  EXPECT_TRUE(threw);
  // The numerical solution blows up within the tolerance's reach of t = 1, and the stepper gives
  // up after a few hundred steps, not after the loop's million.
  EXPECT_NEAR(t, 1.0, 1e-6);
  EXPECT_GT(q[0], 1e6);
  EXPECT_LT(stepper.steps(), 10'000);
}

TEST(DormandPrinceStepper, ThrowsWhenTheRightHandSideIsNotFinite) {
  struct Broken {
    void operator()(double t, const OdeState<1>& q, OdeState<1>& dq) const {
      dq[0] = t < 0.5 ? -q[0] : std::nan("");
    }
  };
  DormandPrinceStepper<1> stepper(1e-8, {1.0});
  double t = 0.0;
  OdeState<1> q{1.0};
  EXPECT_THROW(for (int n = 0; n < 1'000'000; ++n) stepper.step(Broken{}, t, q, kInf),
               StepSizeUnderflow);
  EXPECT_LT(t, 0.5);
  EXPECT_TRUE(std::isfinite(q[0]));
}

TEST(DormandPrinceStepper, RefusesBadArguments) {
  EXPECT_THROW(DormandPrinceStepper<1>(0.0, {1.0}), ContractViolation);
  EXPECT_THROW(DormandPrinceStepper<1>(std::nan(""), {1.0}), ContractViolation);
  EXPECT_THROW(DormandPrinceStepper<2>(1e-6, {1.0, 0.0}), ContractViolation);
  DormandPrinceStepper<1> stepper(1e-6, {1.0});
  double t = 0.0;
  OdeState<1> q{1.0};
  EXPECT_THROW(stepper.step(Decay{}, t, q, -1.0), ContractViolation);
}

TEST(Steppers, DoNotAllocateWhileStepping) {
  Rk4Stepper<2> rk4(0.01);
  DormandPrinceStepper<2> dopri(1e-9, {1.0, 1.0});
  double t_rk4 = 0.0;
  double t_dopri = 0.0;
  OdeState<2> q_rk4 = Oscillator::exact(0.0);
  OdeState<2> q_dopri = q_rk4;
  double sink = 0.0;
  const long before = g_allocations.load();
  for (int n = 0; n < 200; ++n) {
    rk4.step(Oscillator{}, t_rk4, q_rk4, kInf);
    dopri.step(Oscillator{}, t_dopri, q_dopri, 0.5);
    sink += rk4.dense(t_rk4)[0] + dopri.dense(t_dopri)[1];
    if (n % 50 == 0) {
      rk4.reset();
      dopri.reset();
    }
  }
  EXPECT_EQ(g_allocations.load(), before);
  EXPECT_TRUE(std::isfinite(sink));
}

// Whether the dense output moves one way: cos t falls all through (0.3, 0.8) and turns at pi, so a
// step across pi does not move one way (a sufficient test may miss a step that does, never claim
// one that turns).
TEST(DenseOutput, MovesOneWayOnlyWhereTheComponentDoesNotTurn) {
  const auto check = [](auto stepper, double t0) {
    double t = t0;
    OdeState<2> q = Oscillator::exact(t0);
    stepper.step(Oscillator{}, t, q, 0.5);
    const bool turns = t0 < std::numbers::pi && t > std::numbers::pi;
    EXPECT_EQ(stepper.moves_one_way(0), !turns) << t0 << " to " << t;
  };
  for (const double t0 : {0.3, 2.9}) {
    check(DormandPrinceStepper<2>(1e-8, {1.0, 1.0}), t0);
    check(Rk4Stepper<2>(0.5), t0);
  }
}

}  // namespace
}  // namespace blockfrag
