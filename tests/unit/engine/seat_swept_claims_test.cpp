// Which clearances a step in flight cannot bring to zero (engine/seat/seat_swept_claims.cpp): over
// random RK4 steps of the type B block flying low over its seat, every clearance claimed stays
// positive at 200 points of the step's dense output (what the guard watch would have sampled); and
// the claims are made for most clearances the watch would otherwise sample.
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "engine/integrate/rk4_stepper.hpp"
#include "engine/seat/closed_form_flight.hpp"
#include "engine/seat/seat_ode.hpp"
#include "engine/seat/seat_system.hpp"
#include "tests/support/fixed_uniforms.hpp"
#include "tests/support/type_b_seat_system.hpp"

namespace blockfrag {
namespace {

using testing::FixedUniforms;
using testing::kEveryGuard;
using testing::TypeBSeat;

constexpr int kDensePoints = 200;

// A flight's omega: slow as a block bouncing on its seat mostly, fast enough for a step to turn
// it by up to a radian otherwise.
double spin(FixedUniforms& u) { return u(0, 1) < 0.7 ? u(-0.5, 0.5) : u(-20, 20); }

// The block flying over its seat, every vertex and seat point watched.
struct FlyingTypeB {
  TypeBSeat seat;
  SeatSystem system = seat.system({}, {0, 1, 2, 3, 4, 5}, {0, 1, 2});
};

// Steps from a random pose within `lift` of resting on the seat; returns how many clearances near
// zero (those the watch samples) were claimed, and counts them in `near`.
template <class Chart, class Start>
int check_random_flights(const FlyingTypeB& flying, SeatSystem& system, int seed,
                         const Start& start, int& near) {
  FixedUniforms u(static_cast<std::uint64_t>(seed));
  const double R = flying.seat.geometry.size();
  int claimed = 0;
  for (int n = 0; n < 400; ++n) {
    const auto [chart, q0, t0] = start(u);
    const SeatOde<Chart> ode(system, chart);
    Rk4Stepper<Chart::N> stepper(u(1e-4, 0.05));
    double t = t0;
    auto q = q0;
    stepper.step(ode, t, q, 1.0);
    const auto at_start = ode.guards(t0, q0), at_end = ode.guards(t, q);
    GuardClaims claims = system.unused_guards();
    ode.claim_swept_clear(
        t0, t, q0, q, [&](int i) { return stepper.dense_spread(i); }, at_start, kEveryGuard,
        claims);
    for (int i = kFirstClearanceGuard; i < kSeatGuards; ++i) {
      const auto g = static_cast<std::size_t>(i);
      if (system.event(i) != SeatEvent::touches) continue;
      const bool sampled =
          std::min(at_start[g], at_end[g]) < kNearZero && std::min(at_start[g], at_end[g]) > 0;
      near += sampled;
      claimed += sampled && claims[g];
      if (!claims[g]) continue;
      for (int k = 0; k <= kDensePoints; ++k) {
        const double x = t0 + (t - t0) * k / kDensePoints;
        EXPECT_GT(ode.guard(i, x, stepper.dense(x)), 0.0)
            << "flight " << n << " guard " << i << " at " << k << " of a step of " << t - t0
            << " s, R " << R;
      }
    }
  }
  return claimed;
}

// FreeChart: x, y and theta integrated, their dense output a cubic.
TEST(SeatSweptClaims, FreeFlightClaimsStayPositiveOnTheDenseOutput) {
  FlyingTypeB flying;
  const Vec2 rest = flying.seat.contacts.rest_centre();
  int near = 0;
  const int claimed = check_random_flights<FreeChart>(
      flying, flying.system, 41,
      [&](FixedUniforms& u) {
        return std::tuple{
            FreeChart{rest},
            OdeState<6>{u(-1, 8), u(0, 0.6), u(-0.03, 0.03), u(-3, 3), u(-3, 3), spin(u)}, 0.0};
      },
      near);
  EXPECT_GT(near, 500);
  EXPECT_GT(claimed, near / 3);
}

// FlightChart: theta linear in time.
TEST(SeatSweptClaims, FlightChartClaimsStayPositiveOnTheDenseOutput) {
  FlyingTypeB flying;
  const Vec2 rest = flying.seat.contacts.rest_centre();
  int near = 0;
  const int claimed = check_random_flights<FlightChart>(
      flying, flying.system, 42,
      [&](FixedUniforms& u) {
        const FlightChart chart{rest, u(0, 2), u(-0.03, 0.03), spin(u)};
        return std::tuple{chart, OdeState<4>{u(-1, 8), u(-3, 3), u(0, 0.6), u(-3, 3)},
                          chart.t0 + u(0, 0.1)};
      },
      near);
  EXPECT_GT(near, 500);
  EXPECT_GT(claimed, near / 3);
}

// The heel turning through its lowest mid-step, 0.05 m under the seat's flat part there and clear
// of it at both ends: the tilt's range takes it lower than either end, and it is not claimed.
TEST(SeatSweptClaims, AVertexTurningThroughItsLowestInsideTheStepIsNotClaimed) {
  FlyingTypeB flying;
  const Vec2 b = flying.seat.contacts.body_vertex(0);
  const double r = std::sqrt(b.x * b.x + b.y * b.y), g = flying.seat.context.g;
  const double omega = 10.0, h = 0.04;
  const double theta_mid =
      -0.5 * std::numbers::pi - std::atan2(b.y, b.x);  // the heel straight down
  // The centre's parabola peaks mid-step, where the heel is 0.05 m under the seat (at y = 0).
  const double y_mid = r - 0.05;
  const FlightChart chart{{0.0, 0.0}, 0.0, theta_mid - 0.5 * omega * h, omega};
  const SeatOde<FlightChart> ode(flying.system, chart);
  Rk4Stepper<4> stepper(h);
  double t = 0.0;
  const OdeState<4> q0{3.0, 0.0, y_mid - g * h * h / 8, 0.5 * g * h};
  OdeState<4> q = q0;
  stepper.step(ode, t, q, h);
  const int heel = kFirstClearanceGuard;
  const auto at_start = ode.guards(0.0, q0);
  EXPECT_GT(at_start[heel], 0.1 / flying.seat.geometry.size());
  EXPECT_GT(ode.guard(heel, t, q), 0.1 / flying.seat.geometry.size());
  EXPECT_LT(ode.guard(heel, 0.5 * h, stepper.dense(0.5 * h)), 0.0);
  GuardClaims claims = flying.system.unused_guards();
  ode.claim_swept_clear(
      0.0, t, q0, q, [&](int i) { return stepper.dense_spread(i); }, at_start, kEveryGuard, claims);
  EXPECT_FALSE(claims[heel]);
}

// The closed-form flight's x and y stay within their spread of the chord over steps of random
// length under each shape of ground motion, and y's parabola is its bound above the chord at
// mid-step.
TEST(SeatSweptClaims, ClosedFormFlightStaysWithinItsSpreadOfTheChord) {
  using Shape = MotionPiece::Shape;
  FixedUniforms u(43);
  double closest_x = 0.0;
  for (int n = 0; n < 400; ++n) {
    MotionPiece::Formula formula;
    formula.shape = std::array{Shape::linear, Shape::sine, Shape::cosine, Shape::ricker,
                               Shape::mavroeidis_papageorgiou}[static_cast<std::size_t>(n % 5)];
    formula.amplitude = u(-0.8, 0.8);
    // The Ricker wavelet's drift is found from exp(-v^2) at the start: kept within |v| < 20.
    formula.angular_frequency = formula.shape == Shape::ricker ? u(2, 8) : u(2, 40);
    formula.phase = u(-3, 3);
    formula.origin = u(0, 2);
    formula.slope = u(-5, 5);
    formula.modulation = u(0.2, 0.9);
    const MotionPiece piece(formula, 0.0, 3.0);
    const double t0 = u(0, 1);
    ClosedFormFlight flight({u(-1, 1), u(-2, 2), u(0, 1), u(-2, 2)},
                            BlockState{0.0, 0.0, u(-0.1, 0.1), 0.0, 0.0, u(-1, 1)}, piece, t0,
                            9.81);
    double t = t0 + u(0, 0.5);
    OdeState<4> q = flight.dense(t);
    const OdeState<4> start = q;
    const double h = u(1e-3, 1.0);
    flight.step(0, t, q, h);
    for (const int i : {0, 2}) {
      const double lo = std::min(start[i], q[i]), hi = std::max(start[i], q[i]);
      const double spread = flight.dense_spread(i);
      for (int k = 0; k <= kDensePoints; ++k) {
        const double y = flight.dense(t - h + h * k / kDensePoints)[static_cast<std::size_t>(i)];
        const double strays = std::max(lo - y, y - hi);
        EXPECT_LE(strays, spread + 1e-12) << "step " << n << " coordinate " << i;
        if (i == 0 && spread > 1e-3) closest_x = std::max(closest_x, strays / spread);
        if (i == 2 && k == kDensePoints / 2) {
          const double chord = 0.5 * (start[2] + q[2]);
          EXPECT_NEAR(y - chord, spread, 1e-9 * (1 + spread)) << "step " << n;
        }
      }
    }
  }
  EXPECT_GT(closest_x, 0.3);
}

}  // namespace
}  // namespace blockfrag
