// A bounce in flight that lands and goes on into the seat between two of the flight's guard
// samples: its clearance's guard, not armed as the flight began, fires only where a sample finds it
// below its level, and a crossing found later (another corner's) must not leave it in the seat.
#include <utility>

#include <gtest/gtest.h>

#include "engine/simulate.hpp"
#include "tests/support/type_b_rk4_scene.hpp"

namespace blockfrag {
namespace {

Scene type_b_dry(double friction, double restitution, GroundMotion motion) {
  // Each failed on no progress; a few thousand events fail them at once.
  return testing::type_b_rk4_scene(friction, restitution, std::move(motion), 4.0, 10'000);
}

// The randomized scene that failed on no progress at 1.1843 s: the type B block flies off its
// fold at 1.14 s; its heel landed unseen 0.5 ms before the crossing found, the seat's corner's,
// and went 1.2 mm into the seat.
TEST(SeatBounceLanding, HeelLandingBetweenSamplesLandsOnTheSeat) {
  const Summary s = simulate(type_b_dry(0.5278044156707562, 0.22351850421763314,
                                        SinePulse{1.4162463584303324, 2.306062393428019, 1.0}));
  ASSERT_EQ(s.status, Status::ok) << s.status_reason;
  EXPECT_LT(s.events, 100);
  EXPECT_LT(s.max_penetration, 1e-12);
  EXPECT_FALSE(s.fell);
  EXPECT_FALSE(s.overturned);
}

// The randomized scene that failed on no progress at 0.3278 s: the heel's bounces (e = 0.73)
// landed unseen before the seat's corner's crossings, three in a row.
TEST(SeatBounceLanding, HeelBouncesLandingBetweenSamplesEachLandOnTheSeat) {
  const Summary s = simulate(type_b_dry(0.6706800989428972, 0.7341454156765816,
                                        CosinePulse{1.2917387603607877, 1.2164442655578447, 1.0}));
  ASSERT_EQ(s.status, Status::ok) << s.status_reason;
  EXPECT_LT(s.events, 1000);
  EXPECT_LT(s.max_penetration, 1e-12);
  EXPECT_FALSE(s.fell);
  EXPECT_FALSE(s.overturned);
}

}  // namespace
}  // namespace blockfrag
