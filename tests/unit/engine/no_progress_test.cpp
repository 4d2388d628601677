// The no-progress guard (engine/no_progress.hpp): a run fails once more than kMaxInstantEvents
// contact changes fall within kInstant (1 + t) s of the first of them; changes spread wider go on.
// It also fails once more than kMaxStandstillEvents events in a row leave the block where it was.
#include "engine/no_progress.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "engine/errors.hpp"
#include "engine/tolerances.hpp"

namespace blockfrag {
namespace {

TEST(NoProgressGuard, FailsPastTheLimitOfChangesAtOneInstant) {
  NoProgressGuard guard;
  const double t = 3.0;
  guard.count_event(t);  // opens the instant
  for (int i = 0; i < kMaxInstantEvents; ++i) ASSERT_NO_THROW(guard.count_event(t));
  EXPECT_THROW(guard.count_event(t), SimulationFailure);
}

// Changes at distinct times count together while they stay within the width of the first: a block
// whose indistinguishable force distributions flip 4e-11 s apart makes no progress either.
TEST(NoProgressGuard, ChangesWithinTheInstantsWidthCountAsOneInstant) {
  NoProgressGuard guard;
  const double t = 3.0, step = kInstant * (1.0 + t) / (2.0 * kMaxInstantEvents);
  guard.count_event(t);
  for (int i = 1; i <= kMaxInstantEvents; ++i) ASSERT_NO_THROW(guard.count_event(t + i * step));
  EXPECT_THROW(guard.count_event(t + (kMaxInstantEvents + 1) * step), SimulationFailure);
}

TEST(NoProgressGuard, TimeMovingOnStartsANewInstant) {
  NoProgressGuard guard;
  double t = 1.0;
  for (int burst = 0; burst < 3; ++burst) {
    // A burst just under the limit, then time moves past the instant's width.
    for (int i = 0; i <= kMaxInstantEvents; ++i) ASSERT_NO_THROW(guard.count_event(t));
    t += 2 * kInstant * (1.0 + t);
  }
}

// The type B block nested in its seat, its lift-off and friction-limit guards taking turns every
// 1e-10 s as lambda crept on: wider than an instant, but the block never moved.
TEST(NoProgressGuard, FailsPastTheLimitOfEventsThatLeaveTheBlockWhereItWas) {
  NoProgressGuard guard;
  const BlockState nested{5.0714241494943524, 10.976798667607049, 6.0897865691412181e-17};
  double t = 3.1965107095733107;
  for (int i = 0; i < kMaxStandstillEvents; ++i) {
    ASSERT_NO_THROW(guard.count_pose(t, nested));
    t += 1e-10;
  }
  EXPECT_THROW(guard.count_pose(t, nested), SimulationFailure);
}

TEST(NoProgressGuard, ABlockThatMovesByABitStartsTheCountAgain) {
  NoProgressGuard guard;
  BlockState s{1.0, 2.0, 0.0};
  for (int burst = 0; burst < 3; ++burst) {
    for (int i = 0; i < kMaxStandstillEvents; ++i) ASSERT_NO_THROW(guard.count_pose(1.0, s));
    s.x = std::nextafter(s.x, 2.0);
  }
}

}  // namespace
}  // namespace blockfrag
