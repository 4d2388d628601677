// A record's knots (its sample times, where one linear piece of the motion ends and the next
// starts) are not contact events: a block at rest under a long record stays at rest without one
// event a knot, and rest still ends where the motion crosses a threshold between two knots.
#include <cmath>
#include <memory>

#include <gtest/gtest.h>

#include "engine/simulate.hpp"
#include "tests/support/scene_builders.hpp"

namespace blockfrag {
namespace {

using testing::block_scene;

// count samples every step s of a(t) in g.
template <class Acceleration>
std::shared_ptr<const Accelerogram> tabulated(long count, double step, const Acceleration& a) {
  auto record = std::make_shared<Accelerogram>();
  for (long k = 0; k < count; ++k) {
    const double t = static_cast<double>(k) * step;
    record->times.push_back(t);
    record->acceleration_g.push_back(a(t));
  }
  return record;
}

TEST(RecordKnots, ABlockAtRestUnderALongRecordCountsNoEventAKnot) {
  // 20,000 knots of a 0.05 g sine, far below friction (0.6) and tipping (a/b = 0.5): the event
  // budget of 100 is one event for the start, whatever the number of knots.
  const auto record = tabulated(20'000, 0.01, [](double t) { return 0.05 * std::sin(3.0 * t); });
  Scene scene = block_scene(0.5, 1.0, 0.6, 0.6, RecordedMotion{"long.txt", 1.0, record}, 200.0);
  scene.solver.max_events = 100;
  const Summary summary = simulate(scene);
  EXPECT_EQ(summary.status, Status::ok) << summary.status_reason;
  EXPECT_EQ(summary.events, 1);
  EXPECT_FALSE(summary.slide_start_time);
  EXPECT_DOUBLE_EQ(summary.max_abs_theta, 0.0);
}

TEST(RecordKnots, RestEndsWhereTheRecordCrossesFrictionBetweenTwoKnots) {
  // A wide block (tipping at a/b = 2) with friction 0.5 under 0.1 g, then a ramp from 0.1 g at
  // t = 1 s to 1.0 g at 1.01 s: sliding starts where the ramp reaches 0.5 g (plus the onset
  // margin), at 1 + 0.01 x 0.4 / 0.9 s, inside the piece between the two knots.
  const auto record = tabulated(301, 0.01, [](double t) {
    const double ramp_start = 1.0, ramp_end = 1.01;
    if (t < ramp_start - 1e-9) return 0.1;
    return t < ramp_end - 1e-9 ? 0.1 : 1.0;
  });
  Scene scene = block_scene(1.0, 0.5, 0.5, 0.0, RecordedMotion{"ramp.txt", 1.0, record}, 3.0);
  const Summary summary = simulate(scene);
  ASSERT_EQ(summary.status, Status::ok) << summary.status_reason;
  ASSERT_TRUE(summary.slide_start_time);
  EXPECT_NEAR(*summary.slide_start_time, 1.0 + 0.01 * 0.4 / 0.9, 1e-8);
}

}  // namespace
}  // namespace blockfrag
