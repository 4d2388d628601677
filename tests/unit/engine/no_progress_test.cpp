// The no-progress guard (engine/no_progress.hpp): a run fails once more than kMaxInstantEvents
// contact changes fall within kInstant (1 + t) s of the first of them; changes spread wider go on.
#include "engine/no_progress.hpp"

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

}  // namespace
}  // namespace blockfrag
