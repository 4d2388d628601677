// The intensity measures against computations that share nothing with them: hand integrals of the
// pulses, the shock spectrum of a rectangular pulse, the closed-form response of an oscillator to
// a sine, fine trapezoid rules on lambda(t) alone and a fixed-step RK4 of the oscillator.
#include "engine/motion/intensity_measures.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <numbers>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "engine/errors.hpp"
#include "tests/support/paper_block.hpp"

namespace blockfrag {
namespace {

using testing::kGravity;
using testing::pi;

GroundMotionPieces record_motion(const std::vector<double>& times, const std::vector<double>& a_g,
                                 double scale = 1.0) {
  return GroundMotionPieces(RecordedMotion{
      "r.csv", scale, std::make_shared<const Accelerogram>(Accelerogram{times, a_g})});
}

// a(t) in g of a record, linear between samples and zero outside them: written here, not taken
// from GroundMotionPieces.
double interpolate(const std::vector<double>& times, const std::vector<double>& a_g, double t) {
  if (t < times.front() || t > times.back()) return 0.0;
  const auto it = std::upper_bound(times.begin(), times.end(), t);
  if (it == times.end()) return a_g.back();
  const std::size_t i = static_cast<std::size_t>(it - times.begin()) - 1;
  const double w = (t - times[i]) / (times[i + 1] - times[i]);
  return a_g[i] + w * (a_g[i + 1] - a_g[i]);
}

// lambda(t) up to the end of the motion, where it takes the last piece's left limit: a pulse that
// ends with a jump would otherwise lose half a step of its value at the end.
std::function<double(double)> left_limits(GroundMotionPieces& motion) {
  MotionPiece& last = motion.piece_at(std::nextafter(motion.end_of_motion(), 0.0));
  return [&motion, &last](double t) { return t < last.end() ? motion.lambda(t) : last.lambda(t); };
}

// max |v| by the trapezoid rule on n steps of lambda over [0, end]: v = -g integral of lambda.
double trapezoid_pgv(const std::function<double(double)>& lambda, double end, long n) {
  const double h = end / static_cast<double>(n);
  double v = 0.0, peak = 0.0, previous = lambda(0.0);
  for (long i = 1; i <= n; ++i) {
    const double next = lambda(static_cast<double>(i) * h);
    v -= kGravity * 0.5 * h * (previous + next);
    peak = std::max(peak, std::abs(v));
    previous = next;
  }
  return peak;
}

// D5-95 by the trapezoid rule on n steps of lambda^2, each crossing placed by linear interpolation
// inside the step where the running integral passes it.
double trapezoid_d5_95(const std::function<double(double)>& lambda, double end, long n) {
  const double h = end / static_cast<double>(n);
  std::vector<double> running(static_cast<std::size_t>(n) + 1, 0.0);
  double previous = lambda(0.0);
  for (long i = 1; i <= n; ++i) {
    const double next = lambda(static_cast<double>(i) * h);
    running[i] = running[i - 1] + 0.5 * h * (previous * previous + next * next);
    previous = next;
  }
  const auto crossing = [&](double fraction) {
    const double target = fraction * running.back();
    const auto it = std::lower_bound(running.begin(), running.end(), target);
    const std::size_t i = static_cast<std::size_t>(it - running.begin());
    const double w = (target - running[i - 1]) / (running[i] - running[i - 1]);
    return (static_cast<double>(i - 1) + w) * h;
  };
  return crossing(0.95) - crossing(0.05);
}

// Sa in g by the classical RK4 with fixed steps h of u'' = -a - 2 zeta w u' - w^2 u (a in g), from
// rest over [0, end], max |u| at the steps' ends. With w h <= 6.3e-4 its truncation error is below
// 1e-10 of the response, and a step's end misses a peak of u by at most (w h)^2 / 8 < 5e-8 of it.
double rk4_sa(const std::function<double(double)>& a, double end, double period, double zeta,
              double h = 1e-5) {
  const double w = 2.0 * pi / period;
  const auto rate = [&](double t, double u, double v) {
    return -a(t) - 2.0 * zeta * w * v - w * w * u;
  };
  const long n = std::lround(end / h);
  double u = 0.0, v = 0.0, peak = 0.0;
  for (long i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) * h;
    const double k1u = v, k1v = rate(t, u, v);
    const double k2u = v + 0.5 * h * k1v, k2v = rate(t + 0.5 * h, u + 0.5 * h * k1u, k2u);
    const double k3u = v + 0.5 * h * k2v, k3v = rate(t + 0.5 * h, u + 0.5 * h * k2u, k3u);
    const double k4u = v + h * k3v, k4v = rate(t + h, u + h * k3u, k4u);
    u += h / 6.0 * (k1u + 2.0 * k2u + 2.0 * k3u + k4u);
    v += h / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
    peak = std::max(peak, std::abs(u));
  }
  return w * w * peak;
}

// Samples every dt over [0, duration] of a random acceleration in [-0.5, 0.5] g, zero at both ends
// so that a(t) has no jump for RK4 to step across.
void random_record(unsigned seed, double dt, int samples, std::vector<double>& times,
                   std::vector<double>& a_g) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> value(-0.5, 0.5);
  times.clear();
  a_g.clear();
  for (int i = 0; i < samples; ++i) {
    times.push_back(i * dt);
    a_g.push_back(i == 0 || i == samples - 1 ? 0.0 : value(rng));
  }
}

// --- PGA -----------------------------------------------------------------------------------------

TEST(PeakGroundAcceleration, IsThePulseAmplitudeOrTheRecordsLargestSample) {
  EXPECT_NEAR(peak_ground_acceleration_g(GroundMotionPieces(SinePulse{0.3, 0.5, 2.0})), 0.3, 1e-15);
  EXPECT_NEAR(peak_ground_acceleration_g(GroundMotionPieces(SinePulse{-0.7, 1.3, 1.0})), 0.7,
              1e-15);
  // The largest sample is negative: PGA is its magnitude.
  EXPECT_NEAR(peak_ground_acceleration_g(
                  record_motion({0.0, 0.01, 0.02, 0.03, 0.04}, {0.1, -0.45, 0.3, 0.44, 0.0})),
              0.45, 1e-15);
}

// --- PGV -----------------------------------------------------------------------------------------

// lambda = A sin(w t), w = 2 pi / T, one cycle: v = -g A (1 - cos w t) / w, whose largest
// magnitude 2 g A / w = g A T / pi is at t = T / 2.
TEST(PeakGroundVelocity, OfOneSineCycleIsAgTOverPi) {
  const double A = 0.4, T = 0.8;
  EXPECT_NEAR(peak_ground_velocity(GroundMotionPieces(SinePulse{A, T, 1.0}), kGravity),
              A * kGravity * T / pi, 1e-13);
}

// lambda = A cos(w t), one cycle: v = -g A sin(w t) / w, peak g A / w = g A T / (2 pi).
TEST(PeakGroundVelocity, OfOneCosineCycleIsAgTOverTwoPi) {
  const double A = 0.25, T = 1.7;
  EXPECT_NEAR(peak_ground_velocity(GroundMotionPieces(CosinePulse{A, T, 1.0}), kGravity),
              A * kGravity * T / (2.0 * pi), 1e-13);
}

TEST(PeakGroundVelocity, OfARectangularPulseIsAgTimesItsLength) {
  EXPECT_NEAR(peak_ground_velocity(GroundMotionPieces(RectangularPulse{-0.3, 0.45}), kGravity),
              0.3 * kGravity * 0.45, 1e-14);
}

// One linear piece from 0.2 g at 0.5 s to 0.5 g at 1.5 s (zero before and after): a keeps its
// sign, so the velocity's largest magnitude is its last, the trapezoid g (0.2 + 0.5) / 2 x 1 s.
TEST(PeakGroundVelocity, OfTwoSamplesIsTheirTrapezoid) {
  EXPECT_NEAR(peak_ground_velocity(record_motion({0.5, 1.5}, {0.2, 0.5}), kGravity),
              kGravity * 0.35, 1e-14);
}

// Samples (0, 0), (1, 0.4), (2, -0.6), (3, 0.2), (4, 0) g. By hand, in g s: the velocity is 0.2 at
// 1 s, rises by 0.4 x 0.4 / 2 = 0.08 to 0.28 where a crosses zero at 1.4 s, falls by 0.18 to 0.1 at
// 2 s, falls by 0.6 x 0.75 / 2 = 0.225 to -0.125 where a crosses zero again at 2.75 s, then
// returns to 0 at 4 s. The peak, 0.28 g, lies inside a piece: the samples' largest is 0.2 g.
TEST(PeakGroundVelocity, FindsTheExtremeWhereAcrossesZeroInsideAPiece) {
  const std::vector<double> times{0, 1, 2, 3, 4}, a{0.0, 0.4, -0.6, 0.2, 0.0};
  const double pgv = peak_ground_velocity(record_motion(times, a), kGravity);
  EXPECT_NEAR(pgv, 0.28 * kGravity, 1e-14);
  const auto lambda = [&](double t) { return -interpolate(times, a, t); };
  EXPECT_NEAR(pgv, trapezoid_pgv(lambda, 4.0, 1'000'000), 1e-10);
}

// The Mavroeidis-Papageorgiou pulse is given by its velocity (Vp / 2)(1 + cos(2 pi (t - t0) /
// (gamma Tp))) cos(2 pi (t - t0) / Tp + nu): with nu = 0 its peak is Vp, at t0.
TEST(PeakGroundVelocity, OfAMavroeidisPapageorgiouPulseWithoutPhaseIsVp) {
  MavroeidisPapageorgiouPulse pulse;
  pulse.velocity_amplitude = 0.6;
  pulse.period = 0.9;
  pulse.gamma = 2.3;
  EXPECT_NEAR(peak_ground_velocity(GroundMotionPieces(pulse, kGravity), kGravity), 0.6, 1e-14);
}

// The shapes whose PGV has no hand value here, against the trapezoid rule on 2 million steps of
// their lambda (the rule errs by about h^2 max|a'| / 12 per unit time, below 1e-9 here).
TEST(PeakGroundVelocity, OfEveryPulseShapeMatchesAFineTrapezoidRule) {
  MavroeidisPapageorgiouPulse phased;
  phased.velocity_amplitude = 0.8;
  phased.period = 1.1;
  phased.gamma = 1.7;
  phased.phase = 1.1;
  phased.t0 = 1.5;  // starts at 0.565 s: a zero piece first
  RickerWavelet ricker;
  ricker.amplitude_g = 0.5;
  ricker.period = 0.6;
  const std::vector<GroundMotion> motions{SinePulse{0.3, 0.7, 2.5}, CosinePulse{-0.2, 0.4, 3.25},
                                          MakrisPulseC{0.35, 0.9, 2}, ricker, phased};
  for (std::size_t i = 0; i < motions.size(); ++i) {
    GroundMotionPieces motion(motions[i], kGravity);
    const double pgv = peak_ground_velocity(motion, kGravity);
    const auto lambda = left_limits(motion);
    EXPECT_NEAR(pgv, trapezoid_pgv(lambda, motion.end_of_motion(), 2'000'000), 1e-9 * pgv)
        << "motion " << i;
  }
  // Ricker: v = -(g A / w) u exp(-u^2) with w = pi / Tp, whose extremes are at u = +-1/sqrt(2).
  const double w = pi / ricker.period;
  EXPECT_NEAR(peak_ground_velocity(GroundMotionPieces(ricker), kGravity),
              kGravity * ricker.amplitude_g / w * std::exp(-0.5) / std::sqrt(2.0), 1e-8);
}

// --- D5-95 ---------------------------------------------------------------------------------------

// a = c on [t0, t0 + D]: the Arias integral grows as c^2 (t - t0), so it reaches 5 % at t0 +
// 0.05 D and 95 % at t0 + 0.95 D.
TEST(SignificantDuration, OfAConstantAccelerationIsNineTenthsOfItsLength) {
  EXPECT_NEAR(significant_duration(record_motion({1.5, 5.5}, {-0.3, -0.3})), 0.9 * 4.0, 1e-11);
  EXPECT_NEAR(significant_duration(GroundMotionPieces(RectangularPulse{0.7, 2.5})), 0.9 * 2.5,
              1e-11);
}

// a = s t on [0, D]: the integral is s^2 t^3 / 3, so the fraction f is reached at D f^(1/3).
TEST(SignificantDuration, OfARampSolvesTheCubic) {
  const double D = 7.0;
  EXPECT_NEAR(significant_duration(record_motion({0.0, D}, {0.0, 0.8})),
              D * (std::cbrt(0.95) - std::cbrt(0.05)), 1e-11);
  // The same ramp cut into pieces of unequal length: the crossings fall inside pieces.
  EXPECT_NEAR(significant_duration(record_motion(
                  {0.0, 1.0, 2.9, 5.0, D}, {0.0, 0.8 / D, 2.9 * 0.8 / D, 5.0 * 0.8 / D, 0.8})),
              D * (std::cbrt(0.95) - std::cbrt(0.05)), 1e-11);
}

TEST(SignificantDuration, OfEveryPulseShapeMatchesAFineTrapezoidRule) {
  MavroeidisPapageorgiouPulse phased;
  phased.velocity_amplitude = 0.8;
  phased.period = 1.1;
  phased.gamma = 1.7;
  phased.phase = 1.1;
  phased.t0 = 1.5;
  RickerWavelet ricker;
  ricker.amplitude_g = 0.5;
  ricker.period = 0.6;
  const std::vector<GroundMotion> motions{SinePulse{0.3, 0.7, 2.5}, CosinePulse{-0.2, 0.4, 3.25},
                                          MakrisPulseC{0.35, 0.9, 2}, ricker, phased};
  for (std::size_t i = 0; i < motions.size(); ++i) {
    GroundMotionPieces motion(motions[i], kGravity);
    const auto lambda = left_limits(motion);
    EXPECT_NEAR(significant_duration(motion),
                trapezoid_d5_95(lambda, motion.end_of_motion(), 2'000'000),
                1e-9 * motion.end_of_motion())
        << "motion " << i;
  }
}

TEST(SignificantDuration, OfNoMotionIsZero) {
  EXPECT_EQ(significant_duration(GroundMotionPieces(NoMotion{})), 0.0);
  EXPECT_EQ(significant_duration(record_motion({0.0, 1.0}, {0.0, 0.0})), 0.0);
}

// --- Sa ------------------------------------------------------------------------------------------

// An undamped oscillator under a = a0 from rest: u = -(a0 / w^2)(1 - cos w t), largest at t = T/2
// with 2 a0 / w^2. If the pulse lasts t_d >= T / 2 that peak is reached, and the free vibration
// after it has amplitude (a0 / w^2) sqrt(2 - 2 cos w t_d) <= 2 a0 / w^2: Sa = 2 a0. If t_d < T/2,
// u is still rising when the pulse ends and the free vibration's amplitude, 2 (a0 / w^2) sin(pi
// t_d / T), is the peak: Sa = 2 a0 sin(pi t_d / T), reached after the motion has ended.
TEST(SpectralAcceleration, OfARectangularPulseIsTheShockSpectrum) {
  const double a0 = 0.35, T = 0.4;
  for (const double t_d : {0.5 * T, 0.75 * T, 3.3 * T}) {
    EXPECT_NEAR(spectral_acceleration_g(GroundMotionPieces(RectangularPulse{a0, t_d}), T, 0.0),
                2.0 * a0, 1e-12)
        << t_d;
  }
  for (const double t_d : {0.07 * T, 0.2 * T, 0.45 * T}) {
    EXPECT_NEAR(spectral_acceleration_g(GroundMotionPieces(RectangularPulse{a0, t_d}), T, 0.0),
                2.0 * a0 * std::sin(pi * t_d / T), 1e-12)
        << t_d;
  }
}

// The oscillator under a = a0 sin(W t) from rest, W = 2 pi / Tf, in closed form. Steady state:
// u_p = C sin W t + D cos W t with C = -a0 (w^2 - W^2) / Q, D = 2 zeta w W a0 / Q,
// Q = (w^2 - W^2)^2 + (2 zeta w W)^2, of amplitude (a0 / w^2) / sqrt((1 - r^2)^2 + (2 zeta r)^2),
// r = W / w. Transient: e^(-zeta w t)(E cos wd t + F sin wd t) with E = -D and F = (zeta w E -
// W C) / wd from u(0) = u'(0) = 0. After the forcing ends the oscillator rings freely.
struct HarmonicResponse {
  double a0, w, zeta, W, t_end;
  double wd = w * std::sqrt(1.0 - zeta * zeta);
  double Q = std::pow(w * w - W * W, 2) + std::pow(2.0 * zeta * w * W, 2);
  double C = -a0 * (w * w - W * W) / Q, D = 2.0 * zeta * w * W * a0 / Q;
  double E = -D, F = (zeta * w * E - W * C) / wd;

  void forced(double t, double& u, double& v) const {
    const double decay = std::exp(-zeta * w * t), c = std::cos(wd * t), s = std::sin(wd * t);
    u = C * std::sin(W * t) + D * std::cos(W * t) + decay * (E * c + F * s);
    v = W * (C * std::cos(W * t) - D * std::sin(W * t)) +
        decay * ((wd * F - zeta * w * E) * c - (wd * E + zeta * w * F) * s);
  }
  double u(double t) const {
    double u_value, v_value;
    if (t <= t_end) {
      forced(t, u_value, v_value);
      return u_value;
    }
    forced(t_end, u_value, v_value);
    const double tau = t - t_end;
    return std::exp(-zeta * w * tau) * (u_value * std::cos(wd * tau) +
                                        (v_value + zeta * w * u_value) / wd * std::sin(wd * tau));
  }
  // max |u| on a grid of step h up to `until`: a grid point misses a peak by at most (w h)^2 / 8.
  double peak(double until, double h) const {
    double largest = 0.0;
    for (double t = 0.0; t <= until; t += h) largest = std::max(largest, std::abs(u(t)));
    return largest;
  }
};

// The record tabulates the sine at N = 2000 samples a cycle for 60 cycles: its chords shrink the
// fundamental by about (pi / N)^2 / 3 = 8e-7, the bound the comparisons allow (3e-6). At
// resonance the transient starts at -D and decays as exp(-zeta w t) (to 7e-9 after 60 cycles), so
// |u| grows towards the steady amplitude from below and Sa approaches a0 / (2 zeta); off resonance
// the transient can beat above the steady value, and the closed form includes it.
TEST(SpectralAcceleration, OfALongHarmonicRecordMatchesTheClosedFormResponse) {
  const double a0 = 0.3, Tf = 1.0, W = 2.0 * pi / Tf;
  const int per_cycle = 2000, cycles = 60;
  std::vector<double> times, a;
  for (int i = 0; i <= per_cycle * cycles; ++i) {
    times.push_back(Tf * i / per_cycle);
    a.push_back(a0 * std::sin(2.0 * pi * i / per_cycle));
  }
  const GroundMotionPieces motion = record_motion(times, a);
  const double t_end = Tf * cycles;
  struct Case {
    double r, zeta;
  };
  for (const Case c : {Case{1.0, 0.05}, Case{0.5, 0.05}, Case{2.0, 0.05}, Case{0.5, 0.0},
                       Case{1.7, 0.0}, Case{1.0, 0.2}}) {
    const double T = Tf * c.r, w = 2.0 * pi / T;  // r = W / w = T / Tf
    const double sa = spectral_acceleration_g(motion, T, c.zeta);
    const HarmonicResponse exact{a0, w, c.zeta, W, t_end};
    // The free ringing's first extremum comes within half a damped period of the end.
    const double closed_form = w * w * exact.peak(t_end + T, std::min(T, Tf) / 20000.0);
    EXPECT_NEAR(sa, closed_form, 3e-6 * closed_form) << "r " << c.r << " zeta " << c.zeta;
    if (c.zeta > 0.0) {
      const double steady =
          a0 / std::sqrt(std::pow(1.0 - c.r * c.r, 2) + std::pow(2.0 * c.zeta * c.r, 2));
      if (c.r == 1.0) {
        EXPECT_NEAR(sa, a0 / (2.0 * c.zeta), 3e-6 * sa) << "zeta " << c.zeta;
      } else {
        EXPECT_GE(sa, steady * (1.0 - 3e-6)) << "r " << c.r;  // the steady state is reached
      }
    }
  }
}

// An undamped oscillator (w = 2 pi, T = 1 s) under a = a0 + b t from rest:
//   u = -(a0 + b t) / w^2 + (a0 / w^2) cos w t - (c / w) sin w t,
//   u' = c (1 - cos w t) - (a0 / w) sin w t,  c = -b / w^2,
// and with half angles u' = 2 sin(w t / 2) [c sin(w t / 2) - (a0 / w) cos(w t / 2)]: zero at
// t = k T and where tan(w t / 2) = a0 / (w c). With a0 / (w c) = 0.01 the second zero follows
// t = 1 s by atan(0.01) / pi = 3.2 ms, inside the step [0.995, 1.0075] s, over whose ends u' keeps
// its sign: only u'' changing sign in between tells that u' dips through zero.
TEST(StepExtrema, FindsEveryZeroOfTheRateInsideAStep) {
  const double w = 2.0 * pi, b = -1.0, c = -b / (w * w), a0 = 0.01 * w * c;
  const auto state = [&](double t) {
    return OscillatorState{
        -(a0 + b * t) / (w * w) + a0 / (w * w) * std::cos(w * t) - c / w * std::sin(w * t),
        c * (1.0 - std::cos(w * t)) - a0 / w * std::sin(w * t)};
  };
  const auto extrema = [&](double t0, double t1) {
    return step_extrema(w, 0.0, t1 - t0, a0 + b * t0, a0 + b * t1, state(t0), state(t1));
  };
  const std::vector<double> two = extrema(0.995, 1.0075);
  ASSERT_EQ(two.size(), 2u);
  EXPECT_GT(state(0.995).v * state(1.0075).v, 0.0);
  EXPECT_NEAR(0.995 + two[0], 1.0, 1e-10);
  EXPECT_NEAR(0.995 + two[1], 1.0 + std::atan(0.01) / pi, 1e-10);
  // A step holding only the first: u' changes sign over it.
  const std::vector<double> one = extrema(0.995, 1.002);
  ASSERT_EQ(one.size(), 1u);
  EXPECT_NEAR(0.995 + one[0], 1.0, 1e-10);
  // Steps where u' turns without reaching zero, or runs monotonically.
  EXPECT_TRUE(extrema(1.01, 1.02).empty());
  EXPECT_TRUE(extrema(0.4, 0.41).empty());
}

// Sa by an RK4 of its own on the same record: within 1e-6, so Sa finds the peak between the
// Nigam-Jennings nodes (at h = T / 100 a node alone can miss it by 5e-4) and after the end (RK4
// runs on for 2 periods, past the first free extremum at these dampings: within T_d / 2).
TEST(SpectralAcceleration, OfARandomRecordMatchesAFineRk4) {
  std::vector<double> times, a;
  random_record(14, 0.01, 801, times, a);
  const GroundMotionPieces motion = record_motion(times, a);
  const auto a_of_t = [&](double t) { return interpolate(times, a, t); };
  for (const double T : {0.1, 0.37, 1.0, 3.0}) {
    for (const double zeta : {0.0, 0.05, 0.2}) {
      const double sa = spectral_acceleration_g(motion, T, zeta);
      const double reference = rk4_sa(a_of_t, times.back() + 2.0 * T, T, zeta);
      EXPECT_NEAR(sa, reference, 1e-6 * reference) << "T " << T << " zeta " << zeta;
    }
  }
  // Heavy damping: the ring after the end reaches its first extremum within T_d / 2 = 1.15 T, and
  // the closed-form free extremum must find it.
  const double T = 0.5, zeta = 0.9;
  const double sa = spectral_acceleration_g(motion, T, zeta);
  EXPECT_NEAR(sa, rk4_sa(a_of_t, times.back() + 10.0 * T, T, zeta), 1e-6 * sa);
}

// A smooth pulse is drawn linearly between nodes at most min(T, its time scale) / 100 apart:
// the drawn excitation errs by at most (2 pi / 100)^2 / 8 = 4.9e-4 of its peak, and Sa by about
// as much (allowed: 1e-3); RK4 here takes the pulse's own lambda.
TEST(SpectralAcceleration, OfSmoothPulsesMatchesRk4OfTheirFormulaToTheDrawingError) {
  MavroeidisPapageorgiouPulse mp;
  mp.velocity_amplitude = 0.5;
  mp.period = 0.8;
  mp.gamma = 2.0;
  mp.phase = 0.4;
  RickerWavelet ricker;
  ricker.amplitude_g = 0.5;
  ricker.period = 0.5;
  const std::vector<GroundMotion> motions{SinePulse{0.3, 0.7, 2.0}, ricker, mp};
  for (std::size_t i = 0; i < motions.size(); ++i) {
    GroundMotionPieces motion(motions[i], kGravity);
    const auto a_of_t = [&](double t) { return -motion.lambda(t); };
    for (const double T : {0.2, 0.7, 2.0}) {
      const double sa = spectral_acceleration_g(motion, T, 0.05);
      const double reference = rk4_sa(a_of_t, motion.end_of_motion() + 2.0 * T, T, 0.05);
      EXPECT_NEAR(sa, reference, 1e-3 * reference) << "motion " << i << " T " << T;
    }
  }
}

TEST(SpectralAcceleration, RefusesPeriodsAndDampingsOutsideTheirDomains) {
  const GroundMotionPieces motion = record_motion({0.0, 1.0, 2.0}, {0.0, 0.3, 0.0});
  for (const double period : {0.0, -1.0, 10.5, std::numeric_limits<double>::quiet_NaN()}) {
    EXPECT_THROW(spectral_acceleration_g(motion, period, 0.05), InvalidInput) << period;
  }
  for (const double zeta : {-0.01, 1.0, 1.5}) {
    EXPECT_THROW(spectral_acceleration_g(motion, 1.0, zeta), InvalidInput) << zeta;
  }
  EXPECT_GT(spectral_acceleration_g(motion, 10.0, 0.0), 0.0);
  EXPECT_GT(spectral_acceleration_g(motion, 1.0, 0.999999), 0.0);
  // 1e5 s of motion in steps of 1e-5 s: 1e10 steps, past the budget.
  EXPECT_THROW(spectral_acceleration_g(record_motion({0.0, 1e5}, {0.1, 0.1}), 1e-3, 0.05),
               InvalidInput);
  EXPECT_THROW(spectral_acceleration_g(record_motion({0.0, 1e5}, {0.1, 0.1}), 1e-9, 0.05),
               InvalidInput);
}

// --- All of them ---------------------------------------------------------------------------------

// Scaling a by k scales a, v and u by k: PGA, PGV and Sa by |k|; the Arias integral by k^2, which
// leaves the times of its fractions unchanged. The record's own entry point (lambda = -a) agrees
// with a scene's RecordedMotion.
TEST(IntensityMeasures, ScaleWithTheMotionAndKeepTheirDuration) {
  std::vector<double> times, a;
  random_record(7, 0.005, 1201, times, a);
  const std::vector<double> periods{0.15, 0.6, 2.4};
  const IntensityMeasures base =
      intensity_measures(Accelerogram{times, a}, periods, 0.05, kGravity);
  const IntensityMeasures same =
      intensity_measures(record_motion(times, a), periods, 0.05, kGravity);
  EXPECT_EQ(base.pga_g, same.pga_g);
  EXPECT_EQ(base.pgv, same.pgv);
  EXPECT_EQ(base.significant_duration, same.significant_duration);
  EXPECT_EQ(base.sa_g, same.sa_g);
  EXPECT_GT(base.pgv, 0.0);
  EXPECT_GT(base.significant_duration, 0.0);

  for (const double k : {-1.0, -2.5, 0.3}) {
    const IntensityMeasures scaled =
        intensity_measures(record_motion(times, a, k), periods, 0.05, kGravity);
    EXPECT_NEAR(scaled.pga_g, std::abs(k) * base.pga_g, 1e-14) << k;
    EXPECT_NEAR(scaled.pgv, std::abs(k) * base.pgv, 1e-13 * base.pgv) << k;
    EXPECT_NEAR(scaled.significant_duration, base.significant_duration, 1e-10) << k;
    ASSERT_EQ(scaled.sa_g.size(), periods.size());
    for (std::size_t i = 0; i < periods.size(); ++i) {
      EXPECT_NEAR(scaled.sa_g[i], std::abs(k) * base.sa_g[i], 1e-12 * base.sa_g[i]) << k;
    }
  }
}

TEST(IntensityMeasures, OfNoMotionAreZeroAndARecordIsChecked) {
  const IntensityMeasures none =
      intensity_measures(GroundMotionPieces(NoMotion{}), {1.0}, 0.05, kGravity);
  EXPECT_EQ(none.pga_g, 0.0);
  EXPECT_EQ(none.pgv, 0.0);
  EXPECT_EQ(none.significant_duration, 0.0);
  EXPECT_EQ(none.sa_g, std::vector<double>{0.0});
  EXPECT_THROW(intensity_measures(Accelerogram{{0.0, 0.0}, {0.1, 0.2}}, {1.0}, 0.05, kGravity),
               InvalidInput);
  EXPECT_THROW(intensity_measures(Accelerogram{{0.0, 1.0}, {0.1, 0.2}}, {1.0}, 0.05, 0.0),
               InvalidInput);
}

}  // namespace
}  // namespace blockfrag
