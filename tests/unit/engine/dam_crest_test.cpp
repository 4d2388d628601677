// The dam crest filter: the period estimate against a hand computation, the Nigam-Jennings
// recurrence against the closed-form responses of a damped oscillator to a step and to a ramp,
// energy conservation without damping, and the crest's jump where the foundation jumps.
#include "engine/motion/dam_crest.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <gtest/gtest.h>

#include "engine/errors.hpp"
#include "tests/support/paper_block.hpp"

namespace blockfrag {
namespace {

using testing::kGravity;
using testing::pi;

DamCrest dam_with(double period, double zeta, double participation = 1.0) {
  DamCrest dam;
  dam.stiffness = DamPeriod{period};
  dam.damping = zeta;
  dam.participation = participation;
  return dam;
}

TEST(DamPeriod, FenvesChopraEstimateMatchesAHandComputation) {
  // By hand: H = 100 m / 0.3048 = 328.08 ft; E = 25e9 Pa / 6894.76 = 3.6259e6 psi, whose root is
  // 1904.2; T1 = 1.4 * 328.08 / 1904.2 = 0.2412 s.
  EXPECT_NEAR(fenves_chopra_period(100.0, 25e9), 0.2412, 1e-4);
  DamCrest dam;
  dam.stiffness = DamSize{100.0, 25e9};
  EXPECT_EQ(dam_period(dam), fenves_chopra_period(100.0, 25e9));
  // T1 grows with H and falls with sqrt(E): doubling H and quadrupling E leaves it unchanged.
  EXPECT_NEAR(fenves_chopra_period(200.0, 100e9), fenves_chopra_period(100.0, 25e9), 1e-15);
  EXPECT_EQ(dam_period(dam_with(0.3, 0.05)), 0.3);
}

// A foundation acceleration that is a0 from t = 0 on (a rectangular pulse outlasting the scene):
//   q(t) = -(a0 / w^2) [1 - e^{-z w t} (cos wd t + z / sqrt(1 - z^2) sin wd t)]
//   q'(t) = -(a0 / wd) e^{-z w t} sin wd t
TEST(NigamJennings, StepResponseMatchesTheClosedForm) {
  for (const double zeta : {0.0, 0.05, 0.3}) {
    const double period = 0.3, w = 2 * pi / period, wd = w * std::sqrt(1 - zeta * zeta);
    const double lambda = 0.4, a0 = -lambda * kGravity;
    const GroundMotionPieces foundation(RectangularPulse{lambda, 10.0});
    const CrestHistory h = dam_crest_history(foundation, dam_with(period, zeta), 3.0, kGravity);
    ASSERT_GT(h.times.size(), 900u);
    for (std::size_t i = 0; i < h.times.size(); ++i) {
      const double t = h.times[i], decay = std::exp(-zeta * w * t);
      const double q =
          -(a0 / (w * w)) *
          (1 - decay * (std::cos(wd * t) + zeta / std::sqrt(1 - zeta * zeta) * std::sin(wd * t)));
      const double v = -(a0 / wd) * decay * std::sin(wd * t);
      EXPECT_NEAR(h.modal[i].q, q, 1e-10 * std::abs(a0) / (w * w)) << "zeta " << zeta << " t " << t;
      EXPECT_NEAR(h.modal[i].v, v, 1e-10 * std::abs(a0) / w) << "zeta " << zeta << " t " << t;
    }
  }
}

// a(t) = r t: q = -(r / w^2)(t - 2 z / w) + e^{-z w t}(c1 cos wd t + c2 sin wd t), from rest.
TEST(NigamJennings, RampResponseMatchesTheClosedForm) {
  const double zeta = 0.05, period = 0.25, w = 2 * pi / period, wd = w * std::sqrt(1 - zeta * zeta);
  const double end = 2.0, lambda_end = 0.5, r = -lambda_end * kGravity / end;  // a = -lambda g
  const GroundMotionPieces foundation(std::vector<double>{0.0, end},
                                      std::vector<double>{0.0, lambda_end});
  const CrestHistory h = dam_crest_history(foundation, dam_with(period, zeta), end, kGravity);
  const double c1 = -2 * zeta * r / (w * w * w), c2 = (r / (w * w) + zeta * w * c1) / wd;
  for (std::size_t i = 0; i < h.times.size(); ++i) {
    const double t = h.times[i], decay = std::exp(-zeta * w * t);
    const double C = std::cos(wd * t), S = std::sin(wd * t);
    const double q = -(r / (w * w)) * (t - 2 * zeta / w) + decay * (c1 * C + c2 * S);
    const double v =
        -r / (w * w) + decay * ((wd * c2 - zeta * w * c1) * C - (wd * c1 + zeta * w * c2) * S);
    EXPECT_NEAR(h.modal[i].q, q, 1e-10 * std::abs(r * end) / (w * w)) << t;
    EXPECT_NEAR(h.modal[i].v, v, 1e-10 * std::abs(r * end) / w) << t;
  }
}

// Steps too short for the closed-form coefficients take the Taylor path: same step response.
TEST(NigamJennings, ShortStepsFollowTheStepResponse) {
  const double zeta = 0.05, w = 20.0, wd = w * std::sqrt(1 - zeta * zeta), a0 = 2.0;
  const double h = 1e-7;  // w h = 2e-6
  const NigamJenningsStep step(w, zeta, h);
  OscillatorState s;
  for (int i = 0; i < 20000; ++i) s = step(s, a0, a0);
  const double t = 20000 * h, decay = std::exp(-zeta * w * t);
  const double q =
      -(a0 / (w * w)) *
      (1 - decay * (std::cos(wd * t) + zeta / std::sqrt(1 - zeta * zeta) * std::sin(wd * t)));
  EXPECT_NEAR(s.q, q, 1e-10 * a0 / (w * w));
  EXPECT_NEAR(s.v, -(a0 / wd) * decay * std::sin(wd * t), 1e-10 * a0 / w);
}

// Without damping the oscillator's energy is constant while the input is: after the pulse
// v^2/2 + w^2 q^2/2, during it the same about the shifted equilibrium q = -a0 / w^2.
TEST(NigamJennings, ZeroDampingConservesEnergyBetweenInputs) {
  const double period = 0.2, w = 2 * pi / period, pulse_end = 0.53, lambda = 0.3;
  const GroundMotionPieces foundation(RectangularPulse{lambda, pulse_end});
  const CrestHistory h = dam_crest_history(foundation, dam_with(period, 0.0), 4.0, kGravity);
  auto energy = [&](std::size_t i, double a) {
    const double shifted = h.modal[i].q + a / (w * w);
    return 0.5 * h.modal[i].v * h.modal[i].v + 0.5 * w * w * shifted * shifted;
  };
  const double a0 = -lambda * kGravity, during = energy(0, a0);
  EXPECT_GT(during, 0.0);
  std::size_t after = 0, checked_during = 0;
  for (std::size_t i = 0; i < h.times.size(); ++i) {
    if (h.times[i] < pulse_end) {
      EXPECT_NEAR(energy(i, a0), during, 1e-12 * during);
      ++checked_during;
    } else if (h.foundation_acceleration[i] == 0.0) {
      if (after == 0) after = i;
      EXPECT_NEAR(energy(i, 0.0), energy(after, 0.0), 1e-12 * energy(after, 0.0)) << h.times[i];
    }
  }
  EXPECT_GT(checked_during, 200u);
  ASSERT_GT(after, 0u);
  EXPECT_GT(energy(after, 0.0), 0.0);  // the dam rings after the pulse
}

// With one mode the crest's acceleration jumps by (1 - Gamma phi) times the foundation's jump
// (the modal coordinate and its rate do not jump): at the pulse's start and at its end.
TEST(DamCrestMotion, JumpsWhereTheFoundationJumpsUnlessTheParticipationIsOne) {
  const double lambda = 0.3, pulse_end = 0.7;
  const GroundMotionPieces foundation(RectangularPulse{lambda, pulse_end});
  for (const double gamma_phi : {1.0, 1.6}) {
    GroundMotionPieces crest =
        dam_crest_motion(foundation, dam_with(0.25, 0.05, gamma_phi), 2.0, kGravity);
    EXPECT_NEAR(crest.lambda(0.0), (1 - gamma_phi) * lambda, 1e-15);
    const double before = crest.lambda(std::nextafter(pulse_end, 0.0));
    const double after = crest.lambda(pulse_end);
    EXPECT_NEAR(after - before, (1 - gamma_phi) * (0.0 - lambda), 1e-9) << gamma_phi;
    EXPECT_EQ(crest.lambda(2.0 + 1e-9), 0.0);  // nothing after the scene's duration
  }
}

// The dam rings on after the foundation stops, up to the scene's duration.
TEST(DamCrestMotion, KeepsRingingAfterTheFoundationStops) {
  const GroundMotionPieces foundation(SinePulse{0.2, 0.25, 2.0});
  const CrestHistory h = dam_crest_history(foundation, dam_with(0.25, 0.05), 3.0, kGravity);
  EXPECT_EQ(h.times.back(), 3.0);
  double late_peak = 0.0;
  for (std::size_t i = 0; i < h.times.size(); ++i) {
    if (h.times[i] > 2.5) late_peak = std::max(late_peak, std::abs(h.crest_lambda[i]));
  }
  EXPECT_GT(late_peak, 0.05);
}

TEST(DamCrestMotion, RefusesAGridTooFineForTheDuration) {
  const GroundMotionPieces foundation(SinePulse{0.2, 1.0, 1.0});
  EXPECT_THROW(dam_crest_history(foundation, dam_with(1e-6, 0.05), 100.0, kGravity), InvalidInput);
}

}  // namespace
}  // namespace blockfrag
