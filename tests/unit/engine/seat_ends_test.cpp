// Which of a seat's guards are least at an end of a step (engine/seat/seat_ends.cpp): over random
// steps on the paper's type B block and seat, every guard claimed is sampled densely along a path
// that meets the claim's condition (the coordinates said to move one way do), and its least sample
// is at an end; and the claims that make the speed (a rocking block's clearances near zero) are
// made.
#include <algorithm>
#include <array>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "engine/seat/seat_ode.hpp"
#include "engine/seat/seat_system.hpp"
#include "engine/seat/sinusoid.hpp"
#include "engine/sine_cosine.hpp"
#include "tests/support/fixed_uniforms.hpp"
#include "tests/support/type_b_seat_system.hpp"

namespace blockfrag {
namespace {

using testing::kEveryGuard;
using testing::TypeBSeat;

using testing::FixedUniforms;

constexpr int kSamples = 400;

// For each guard claimed, its samples along state_at(f), f in [0, 1], are no lower than the lower
// of its ends (but for rounding). Returns how many guards watching a clearance were claimed.
template <class StateAt>
int check_claims(const SeatSystem& system, const GuardClaims& claims, const StateAt& guards_at) {
  const auto first = guards_at(0.0), last = guards_at(1.0);
  std::array<double, kSeatGuards> least{};
  for (std::size_t i = 0; i < least.size(); ++i) least[i] = std::min(first[i], last[i]);
  for (int k = 1; k < kSamples; ++k) {
    const auto inside = guards_at(static_cast<double>(k) / kSamples);
    for (std::size_t i = 0; i < least.size(); ++i) {
      if (claims[i]) {
        EXPECT_GE(inside[i], least[i] - 1e-12) << "guard " << i << " at " << k;
      }
    }
  }
  int clearances = 0;
  for (int i = kFirstClearanceGuard; i < kSeatGuards; ++i) {
    clearances += claims[static_cast<std::size_t>(i)] && system.event(i) == SeatEvent::touches;
  }
  return clearances;
}

// A step's range holds a sinusoid's minimum where dense samples find one inside it, and bounds the
// sinusoid's values over it.
TEST(SeatEnds, AStepHoldsASinusoidsMinimumWhereSamplesFindOne) {
  FixedUniforms u(36);
  int held = 0;
  for (int n = 0; n < 2000; ++n) {
    const Sinusoid f{u(-3, 3), u(-5, 5), u(-5, 5)};
    const double lo = u(-7, 7), hi = lo + u(0, 3);
    const ThetaStep step(lo, hi);
    double least = std::min(f.at(step.lo()), f.at(step.hi())), largest = least;
    bool dips = false;  // a sample clearly below both ends
    for (int k = 1; k < kSamples; ++k) {
      const double value = f.at(sine_cosine(lo + (hi - lo) * k / kSamples));
      dips = dips || value < std::min(f.at(step.lo()), f.at(step.hi())) - 1e-12;
      least = std::min(least, value);
      largest = std::max(largest, value);
    }
    if (dips) {
      EXPECT_TRUE(step.holds_minimum(f)) << n;
    }
    held += step.holds_minimum(f);
    EXPECT_LE(step.least(f), least + 1e-12);
    EXPECT_GE(step.largest(f), largest - 1e-12);
  }
  EXPECT_GT(held, 300);
  EXPECT_LT(held, 1700);
}

struct PivotCase {
  ActiveContact contact;
  Vec2 point, body;
  WatchedList vertices, points;
};

// Turning about the heel, the toe, and (the block moved 1 m downstream) the seat's fold on the
// block's base: theta moving one way from theta0 to theta1.
TEST(SeatEnds, PivotClaimsHoldOverRandomSteps) {
  const TypeBSeat seat;
  const SeatContacts& c = seat.contacts;
  const std::vector<PivotCase> cases = {{{{ContactKind::block_vertex, 0, 0}, ContactState::stick},
                                         c.seat_point(0),
                                         c.body_vertex(0),
                                         {1, 2, 3, 4, 5},
                                         {1, 2}},
                                        {{{ContactKind::block_vertex, 2, 1}, ContactState::stick},
                                         c.seat_point(2),
                                         c.body_vertex(2),
                                         {0, 1, 3, 4, 5},
                                         {0, 1}},
                                        {{{ContactKind::seat_point, 0, 1}, ContactState::stick},
                                         c.seat_point(1),
                                         {c.body_vertex(1).x - 1.0, c.body_vertex(1).y},
                                         {0, 1, 2, 3, 4, 5},
                                         {0, 2}}};
  FixedUniforms u(33);
  for (const PivotCase& p : cases) {
    SeatSystem system = seat.system({p.contact}, p.vertices, p.points);
    const PivotChart chart{p.point, p.body};
    PivotSweep sweep(system, chart);
    const SeatOde ode(system, chart, sweep);
    int claimed = 0;
    for (int n = 0; n < 300; ++n) {
      const double theta0 = u(-0.6, 0.6);
      const double theta1 = theta0 + (n % 2 == 0 ? u(-0.3, 0.3) : u(-1e-3, 1e-3));
      const auto claims = ode.guard_claims(
          0.0, 0.0, {theta0, 0.2}, {theta1, 0.2}, [](int) { return true; }, kEveryGuard);
      claimed += check_claims(system, claims, [&](double f) {
        return ode.guards(0.0, {theta0 + f * (theta1 - theta0), 0.2});
      });
    }
    // Most steps leave each watched vertex and point on one side of its lines.
    EXPECT_GT(claimed, 300 * static_cast<int>(p.vertices.size() + p.points.size()) / 3);
  }
}

// Turning about the heel from rest (theta = 0, where the fold's vertex and the fold's seat point
// are at zero clearance), the clearances that the guard watch samples are claimed once theta has
// left zero by more than the claims' margin.
TEST(SeatEnds, RockingOnTheHeelTheFoldsClearancesAreLeastAtAnEnd) {
  const TypeBSeat seat;
  const SeatContacts& c = seat.contacts;
  SeatSystem system = seat.system({{{ContactKind::block_vertex, 0, 0}, ContactState::stick}},
                                  {1, 2, 3, 4, 5}, {1, 2});
  const PivotChart chart{c.seat_point(0), c.body_vertex(0)};
  PivotSweep sweep(system, chart);
  const SeatOde ode(system, chart, sweep);
  for (const double theta : {1e-6, 1e-3, 0.1}) {
    const auto claims = ode.guard_claims(
        0.0, 0.0, {theta, 0.1}, {theta * 1.01, 0.1}, [](int) { return true; }, kEveryGuard);
    EXPECT_TRUE(claims[0]);                         // overturning
    EXPECT_TRUE(claims[kFirstClearanceGuard]);      // the fold's vertex over the seat
    EXPECT_TRUE(claims[kFirstClearanceGuard + 5]);  // the fold's seat point under the base
  }
  // theta not moving one way: nothing is claimed but the unused slots.
  const auto none = ode.guard_claims(
      0.0, 0.0, {0.1, 0.1}, {0.11, 0.1}, [](int) { return false; }, kEveryGuard);
  EXPECT_FALSE(none[0]);
  EXPECT_FALSE(none[kFirstClearanceGuard]);
  EXPECT_TRUE(none[kSeatGuards - 1]);
}

// Sliding on the flat segment (both base vertices slipping) and a vertex slipping along it: the
// place and rate along the line moving linearly from one end's values to the other's.
TEST(SeatEnds, SlideAndSlipClaimsHoldOverRandomSteps) {
  const TypeBSeat seat;
  const SeatContacts& c = seat.contacts;
  const SeatLine line = c.segment_line(0);
  SeatSystem sliding =
      seat.system({{{ContactKind::block_vertex, 0, 0}, ContactState::slip_positive},
                   {{ContactKind::block_vertex, 1, 0}, ContactState::slip_positive}},
                  {2, 3, 4, 5}, {1, 2});
  const SeatOde slide(sliding, SlideChart{{0.0, 0.0}, line, c.rest_centre().y, 0.0});
  SeatSystem slipping = seat.system(
      {{{ContactKind::block_vertex, 0, 0}, ContactState::slip_negative}}, {1, 2, 3, 4, 5}, {1, 2});
  const SeatOde slip(slipping, SlipChart{{0.0, 0.0}, line, c.body_vertex(0)});
  FixedUniforms u(34);
  int claimed = 0;
  for (int n = 0; n < 300; ++n) {
    const OdeState<2> a{c.rest_centre().x + u(-8, 8), u(-1, 1)};
    const OdeState<2> b{a[0] + u(-3, 3), u(-1, 1)};
    const auto claims = slide.guard_claims(
        0.0, 0.0, a, b, [](int) { return true; }, kEveryGuard);
    claimed += check_claims(sliding, claims, [&](double f) {
      return slide.guards(0.0, {a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1])});
    });
    const OdeState<4> p{u(0, 0.3), 0.2, u(-2, 8), u(-1, 0)};
    const OdeState<4> q{p[0] + u(-0.1, 0.1), 0.2, p[2] + u(-1, 1), u(-1, 0)};
    const auto slip_claims = slip.guard_claims(
        0.0, 0.0, p, q, [](int i) { return i >= 2; }, kEveryGuard);
    EXPECT_TRUE(slip_claims[3]);  // the slip's velocity
    EXPECT_TRUE(slip_claims[4]);  // its distance from its run's ends
    const auto slip_path = [&](double f) {
      const auto at = [&](std::size_t i) { return p[i] + f * (q[i] - p[i]); };
      return slip.guards(0.0, {at(0), at(1), at(2), at(3)});
    };
    check_claims(slipping, slip_claims, slip_path);
    // theta moving one way too (the overturning margin).
    check_claims(slipping,
                 slip.guard_claims(
                     0.0, 0.0, p, q, [](int) { return true; }, kEveryGuard),
                 slip_path);
  }
  EXPECT_GT(claimed, 300);
}

// The heel slipping along a long level seat: the other vertices' heights are sinusoids of theta
// alone, claimed least at an end of a step where theta and the place move one way and no minimum of
// theirs lies within the step's tilts (every vertex of the block tilted up off the seat), and only
// there.
TEST(SeatEnds, SlippingOnALevelSeatTheOtherVerticesClearancesAreLeastAtAnEnd) {
  const TypeBSeat level({{-1e4, 0.0}, {1e4, 0.0}});
  const SeatContacts& c = level.contacts;
  SeatSystem slipping = level.system(
      {{{ContactKind::block_vertex, 0, 0}, ContactState::slip_negative}}, {1, 2, 3, 4, 5}, {});
  const SeatOde slip(slipping, SlipChart{{0.0, 0.0}, c.segment_line(0), c.body_vertex(0)});
  FixedUniforms u(37);
  int tilted_up = 0;
  for (int n = 0; n < 600; ++n) {
    // Every other step at any tilt, its range holding some vertices' least heights.
    const bool anywhere = n % 2 == 1;
    const OdeState<4> p{anywhere ? u(-3, 3) : u(0.01, 0.5), 0.2, u(-20, 20), u(-1, 0)};
    const double turn = anywhere ? u(-0.5, 0.5) : u(-0.05, 0.05);
    const OdeState<4> q{p[0] + turn, 0.2, p[2] + u(-1, 1), u(-1, 0)};
    const auto claims = slip.guard_claims(
        0.0, 0.0, p, q, [](int) { return true; }, kEveryGuard);
    const int claimed = check_claims(slipping, claims, [&](double f) {
      const auto at = [&](std::size_t i) { return p[i] + f * (q[i] - p[i]); };
      return slip.guards(0.0, {at(0), at(1), at(2), at(3)});
    });
    if (!anywhere) tilted_up += claimed;
    for (const int still : {0, 2}) {
      const auto none = slip.guard_claims(
          0.0, 0.0, p, q, [&](int i) { return i != still; }, kEveryGuard);
      EXPECT_FALSE(none[kFirstClearanceGuard]) << n;
    }
  }
  EXPECT_EQ(tilted_up, 300 * 5);
}

// Sliding down the inclined segment under a sine: the ground's inertia has a part across the line,
// so the contacts' normal forces are affine in lambda, and their lift-off guards are claimed over a
// step where lambda moves one way, and only there (where lambda turns inside the step, one of the
// forces turns with it, below both its ends).
TEST(SeatEnds, ASlidesLiftOffsAreClaimedWhereLambdaMovesOneWay) {
  const TypeBSeat seat;
  const SeatContacts& c = seat.contacts;
  MotionPiece shaking{{.shape = MotionPiece::Shape::sine,
                       .amplitude = 0.4,
                       .angular_frequency = 2.0 * std::numbers::pi},
                      0.0,
                      1e3};
  SeatSystemContext context = seat.context;
  context.piece = &shaking;
  SeatSystem sliding(context,
                     {{{ContactKind::block_vertex, 1, 1}, ContactState::slip_positive},
                      {{ContactKind::block_vertex, 2, 1}, ContactState::slip_positive}},
                     {0, 3, 4, 5}, {0});
  const SeatLine line = c.segment_line(1);
  const Vec2 fold = c.seat_point(1), centre = c.rest_centre();
  const Vec2 from_fold{centre.x - fold.x, centre.y - fold.y};
  const double along = from_fold.x * line.direction.x + from_fold.y * line.direction.y;
  const double offset = from_fold.x * line.normal.x + from_fold.y * line.normal.y;
  const SeatOde slide(sliding, SlideChart{fold, line, offset, 0.0});
  FixedUniforms u(37);
  int one_way = 0;
  for (int n = 0; n < 300; ++n) {
    const OdeState<2> a{along + u(-3, 3), u(-1, 1)};
    const OdeState<2> b{a[0] + u(-3, 3), u(-1, 1)};
    const double t0 = u(0, 2), t1 = t0 + u(0, 0.6);
    const auto claims = slide.guard_claims(
        t0, t1, a, b, [](int) { return true; }, kEveryGuard);
    const bool lambda_one_way = shaking.extrema_between(t0, t1).empty();
    EXPECT_EQ(claims[2], lambda_one_way) << n;
    EXPECT_EQ(claims[2 + kSeatContactGuards], lambda_one_way) << n;
    check_claims(sliding, claims, [&](double f) {
      return slide.guards(t0 + f * (t1 - t0), {a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1])});
    });
    one_way += lambda_one_way;
  }
  EXPECT_GT(one_way, 100);
  EXPECT_LT(one_way, 250);
}

// In flight theta is linear in time: the overturning margin is least at an end while x moves one
// way and stays on one side of the seat's ends.
TEST(SeatEnds, FlightClaimsHoldOverRandomSteps) {
  const TypeBSeat seat;
  SeatSystem flying = seat.system({}, {0, 1, 2, 3, 4, 5}, {0, 1, 2});
  FixedUniforms u(35);
  int claimed = 0;
  for (int n = 0; n < 300; ++n) {
    const FlightChart chart{{0.0, 0.0}, 0.0, u(-1.5, 1.5), u(-3, 3)};
    const SeatOde ode(flying, chart);
    const OdeState<4> a{u(-3, 16), u(-2, 2), u(10, 12), 0.0};
    const double h = u(0.01, 0.5);
    const OdeState<4> b{a[0] + h * a[1], a[1], a[2], 0.0};
    const auto claims = ode.guard_claims(
        0.0, 0.0, a, b, [](int i) { return i == 0; }, kEveryGuard);
    claimed += claims[0];
    check_claims(flying, claims, [&](double f) {
      return ode.guards(f * h, {a[0] + f * h * a[1], a[1], a[2], 0.0});
    });
  }
  EXPECT_GT(claimed, 150);
}

}  // namespace
}  // namespace blockfrag
