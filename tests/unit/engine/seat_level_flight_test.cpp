// A flight over a level seat, clear of its ends, is the flat ground's flight (engine/seat/
// seat_level_flight.cpp): its landing is found in closed form on the block's corners, so a chain
// of bounces lands where the flat ground's lands, and near an end the guards watch it as before.
#include <cstddef>
#include <vector>

#include <gtest/gtest.h>

#include "engine/simulate.hpp"

namespace blockfrag {
namespace {

// The paper's rectangle bouncing under a pulse: 187 events, most of them landings.
Scene bouncing_rectangle() {
  Scene scene;
  scene.block = {0.5, 1.0};
  scene.contact = {0.7, 0.8};
  scene.ground_motion = CosinePulse{0.8, 1.0, 1.0};
  return scene;
}

// The first bounces' impacts at the flat ground's times: each bounce's landing is the flat
// ground's corner landing, from the same start up to rounding, and the chain amplifies a rounding
// difference by about 1.3 a bounce (1e-14 s by the tenth).
TEST(SeatLevelFlight, BouncesLandWhereTheFlatGroundsLand) {
  const Scene flat = bouncing_rectangle();
  Scene seat = flat;
  seat.seat = Seat{{{-1000.0, -1.0}, {1000.0, -1.0}}};
  const SimulationWithHistory a = simulate_with_history(flat, 0.1);
  const SimulationWithHistory b = simulate_with_history(seat, 0.1);
  ASSERT_EQ(a.summary.status, Status::ok) << a.summary.status_reason;
  ASSERT_EQ(b.summary.status, Status::ok) << b.summary.status_reason;
  constexpr std::size_t kCompared = 10;
  ASSERT_GE(a.impacts.size(), kCompared);
  ASSERT_GE(b.impacts.size(), kCompared);
  for (std::size_t k = 0; k < kCompared; ++k) {
    SCOPED_TRACE(k);
    EXPECT_EQ(a.impacts[k].mode_after, ModeKind::flight);
    EXPECT_EQ(b.impacts[k].mode_after, ModeKind::flight);
    EXPECT_NEAR(b.impacts[k].time, a.impacts[k].time, 2e-14);
  }
}

// The same block bouncing towards a seat's end 1 cm past its corner: its flights carry it over the
// end, where the seat is no longer the flat ground, and it falls. Flown as over an endless seat,
// its landings past the end were taken as the seat's, and it failed on no progress, still on the
// seat.
TEST(SeatLevelFlight, BouncesPastTheSeatsEndFallOffIt) {
  Scene scene = bouncing_rectangle();
  scene.ground_motion = CosinePulse{-1.2, 1.0, 1.0};
  scene.seat = Seat{{{-1000.0, -1.0}, {0.51, -1.0}}};
  const Summary s = simulate(scene);
  ASSERT_EQ(s.status, Status::ok) << s.status_reason;
  EXPECT_TRUE(s.fell);
  EXPECT_GT(s.final_slide, 0.51);
  EXPECT_LT(s.max_penetration, 1e-12);
}

}  // namespace
}  // namespace blockfrag
