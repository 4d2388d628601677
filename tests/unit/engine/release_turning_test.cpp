// A block released turning (`initial.omega`): free rocking from an angular velocity about the
// corner the turning keeps down, against Housner's energy integral (no ground motion, the corner
// sticking): omega0^2 / (2 p^2) = cos(alpha - theta_max) - cos(alpha), p = sqrt(3 g / (4 R)) for a
// rectangle, so the first swing peaks at theta_max and the block overturns from rest on its corner
// iff omega0 >= p sqrt(2 (1 - cos(alpha))) (Housner 1963). The flat ground, a flat seat and
// Housner's reduced model must agree.
#include <cmath>

#include <gtest/gtest.h>

#include "engine/errors.hpp"
#include "engine/simulate.hpp"

namespace blockfrag {
namespace {

constexpr double kReleaseA = 0.5, kReleaseB = 1.0, kReleaseG = 9.81;

double release_frequency_parameter() {
  return std::sqrt(3 * kReleaseG / (4 * std::hypot(kReleaseA, kReleaseB)));
}
double release_alpha() { return std::atan(kReleaseA / kReleaseB); }
double release_overturning_omega() {
  return release_frequency_parameter() * std::sqrt(2 * (1 - std::cos(release_alpha())));
}
double release_first_peak(double omega) {
  const double p = release_frequency_parameter();
  return release_alpha() - std::acos(std::cos(release_alpha()) + omega * omega / (2 * p * p));
}

// Plastic impacts (e = 0) and friction far above the rocking need: the first swing is free rocking.
Scene released_turning(double omega, double theta = 0.0) {
  Scene scene;
  scene.block = {kReleaseA, kReleaseB, 1.0};
  scene.contact = {2.0, 0.0};
  scene.initial = {theta, omega};
  scene.duration = 5.0;
  scene.solver.tolerance = 1e-11;
  return scene;
}

TEST(ReleaseTurning, TheFirstSwingPeaksWhereHousnersEnergyIntegralSays) {
  for (const double fraction : {0.3, 0.7, 0.99}) {
    for (const double sign : {1.0, -1.0}) {
      const double omega = sign * fraction * release_overturning_omega();
      const Summary s = simulate(released_turning(omega));
      ASSERT_EQ(s.status, Status::ok);
      EXPECT_FALSE(s.overturned) << omega;
      EXPECT_NEAR(s.max_abs_theta, release_first_peak(omega), 1e-8) << omega;
      ASSERT_TRUE(s.rock_start_time.has_value());
      EXPECT_EQ(*s.rock_start_time, 0.0);
    }
  }
}

TEST(ReleaseTurning, OverturnsJustAboveTheEnergyThresholdEitherWay) {
  for (const double sign : {1.0, -1.0}) {
    EXPECT_TRUE(simulate(released_turning(sign * 1.001 * release_overturning_omega())).overturned)
        << sign;
    EXPECT_FALSE(simulate(released_turning(sign * 0.999 * release_overturning_omega())).overturned)
        << sign;
  }
}

TEST(ReleaseTurning, TiltedAndTurningBackTheFirstImpactComesFirst) {
  // Tilted onto the left corner (theta > 0) and turning back (omega < 0): it lands flat first, at
  // the time the energy integral gives, before any swing to the right; the peak is the release.
  const Summary s = simulate(released_turning(-0.5, 0.2));
  ASSERT_TRUE(s.first_impact_time.has_value());
  EXPECT_NEAR(s.max_abs_theta, 0.2, 1e-12);
}

TEST(ReleaseTurning, AFlatSeatAndHousnersModelAgreeWithTheFlatGround) {
  const double omega = -0.8 * release_overturning_omega();
  const Summary flat = simulate(released_turning(omega));
  Scene on_seat = released_turning(omega);
  on_seat.seat = Seat{{{-3.0, -kReleaseB}, {3.0, -kReleaseB}}};
  const Summary seat = simulate(on_seat);
  EXPECT_NEAR(seat.max_abs_theta, flat.max_abs_theta, 1e-9);
  EXPECT_EQ(seat.overturned, flat.overturned);
  Scene housner = released_turning(omega);
  housner.effects = Effects{false, true, false, true, false, false};
  const Summary reduced = simulate(housner);
  EXPECT_EQ(reduced.model, Model::housner_rocking);
  EXPECT_NEAR(reduced.max_abs_theta, flat.max_abs_theta, 1e-9);
}

TEST(ReleaseTurning, NewmarksSlidingBlockCannotStartTurning) {
  Scene scene = released_turning(0.5);
  scene.effects = Effects{false, false, true, false, false, false};
  EXPECT_THROW(simulate(scene), InvalidInput);
}

}  // namespace
}  // namespace blockfrag
