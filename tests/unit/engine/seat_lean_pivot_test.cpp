// A block vertex sticking alone on a one-segment seat, turning clear of the seat's ends, has its
// guards found as the flat ground finds a rocking block's (SeatSystem::set_clear_of_ends): its
// contact force in closed form, the mass matrix (the added mass's coupling with it) times the
// acceleration of a centre of mass turning about a fixed point, less the load, and only the watched
// vertices' heights. Over random poses of the type A block turning on its toe and on its heel, dry
// and under the reservoir at its crest, on a flat seat and on a seat inclined by 0.2 rad, against
// the same system's general guards (the fixed-state solve of the contact, every vertex and point):
// the force guards agree to the solve's rounding; the overturning margin, the watched vertices'
// clearances and the penetration are the same to the bit; the fall and the seat's far ends, out of
// the block's reach, are left at 1 where the general guards find them positive.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include <gtest/gtest.h>

#include "engine/scene/block_geometry.hpp"
#include "engine/scene/scene_validation.hpp"
#include "engine/scene/seat.hpp"
#include "engine/seat/hull_watch.hpp"
#include "engine/seat/seat_system.hpp"
#include "engine/sine_cosine.hpp"
#include "engine/water/reservoir_load.hpp"
#include "tests/support/fixed_uniforms.hpp"
#include "tests/support/same_bits.hpp"
#include "tests/support/seat_system_fixture.hpp"
#include "tests/support/wet_dam_blocks.hpp"

namespace blockfrag {
namespace {

using testing::same_bits;

constexpr double kLeanPivotMu = 0.9;

// The type A block, dry or under the reservoir at its crest, on a one-segment seat 1000 m either
// side of its heel, falling by `slope` downstream.
struct BlockOnLine : testing::SeatSystemFixture {
  BlockOnLine(double slope, bool wet) : SeatSystemFixture(make_scene(slope), wet, kLeanPivotMu) {}

 private:
  static Scene make_scene(double slope) {
    Scene s = testing::wet_type_a_step(kLeanPivotMu, 0.3, UpliftRule::unchanged);
    const double c = std::cos(slope), sn = std::sin(slope);
    s.seat = Seat{{{-1000.0, 0.0}, {1000.0, 0.0}}};
    validate_scene(s);
    // Tilted through the heel after validation, which asks for a block at rest on its seat: the
    // poses compared are turning on it, not resting.
    s.seat = Seat{{{-1000.0 * c, 1000.0 * sn}, {1000.0 * c, -1000.0 * sn}}};
    return s;
  }
};

// Returns how many poses were compared.
int expect_lean_guards_are_the_general_ones(const BlockOnLine& seat, int pivot, unsigned seed) {
  const std::vector<ActiveContact> active{
      {{ContactKind::block_vertex, pivot, 0}, ContactState::stick}};
  const Vec2 body = seat.contacts.body_vertex(pivot);
  const WatchedList vertices = *HullWatch(body_vertices(seat.contacts)).watched({&pivot, 1});
  const WatchedList points{0, 1};
  const Vec2 a = seat.contacts.seat_point(0), b = seat.contacts.seat_point(1);
  testing::FixedUniforms u(seed);
  SeatSystem system(seat.context, active, vertices, points);
  int compared = 0;
  for (int n = 0; n < 200; ++n) {
    // The pivot somewhere on the seat's middle, the block turned within its overturning range
    // (away from the seat's tilt) and turning at a random rate.
    const double along = u(0.45, 0.55);
    const PivotChart chart({a.x + along * (b.x - a.x), a.y + along * (b.y - a.y)}, body);
    const double theta = std::atan2(b.y - a.y, b.x - a.x) + u(-0.25, 0.25);
    const double t = u(0.0, 3.0);
    const BlockState s = chart.full(t, {theta, u(-1.5, 1.5)});
    system.set_clear_of_ends(false);
    const auto general = system.guards(t, s);
    const double general_depth = system.penetration(s);
    system.set_clear_of_ends(true);
    EXPECT_TRUE(system.lean_pivot());
    const auto lean = system.guards(t, s);
    EXPECT_TRUE(same_bits(lean[0], general[0])) << n;
    EXPECT_NEAR(lean[2], general[2], 1e-12) << n;
    EXPECT_NEAR(lean[3], general[3], 1e-12) << n;
    EXPECT_EQ(lean[1], 1.0) << n;
    EXPECT_GT(general[1], 0.0) << n;
    const std::size_t first = kFirstClearanceGuard;
    for (std::size_t k = 0; k < vertices.size(); ++k) {
      EXPECT_TRUE(same_bits(lean[first + k], general[first + k])) << n << " " << k;
    }
    for (std::size_t k = vertices.size(); k < vertices.size() + points.size(); ++k) {
      EXPECT_EQ(lean[first + k], 1.0) << n << " " << k;
      EXPECT_GT(general[first + k], 0.0) << n << " " << k;
    }
    EXPECT_TRUE(same_bits(system.penetration(s), general_depth)) << n;
    // The contact check at the step's end reads the force the guards found.
    const SeatSystem::PivotForce f = system.pivot_force(t, s);
    EXPECT_TRUE(same_bits(f.normal / seat.scene.g, lean[2])) << n;
    ++compared;
  }
  return compared;
}

TEST(SeatLeanPivot, GuardsAreTheGeneralOnesOnAFlatSeat) {
  for (const bool wet : {false, true}) {
    const BlockOnLine seat(0.0, wet);
    EXPECT_EQ(expect_lean_guards_are_the_general_ones(seat, 1, wet ? 31 : 47), 200);  // the toe
    EXPECT_EQ(expect_lean_guards_are_the_general_ones(seat, 0, wet ? 37 : 53), 200);  // the heel
  }
}

TEST(SeatLeanPivot, GuardsAreTheGeneralOnesOnAnInclinedSeat) {
  for (const bool wet : {false, true}) {
    const BlockOnLine seat(0.2, wet);
    EXPECT_EQ(expect_lean_guards_are_the_general_ones(seat, 1, wet ? 41 : 59), 200);
    EXPECT_EQ(expect_lean_guards_are_the_general_ones(seat, 0, wet ? 43 : 61), 200);
  }
}

// Only a block vertex sticking alone on a one-segment seat, clear of its ends, is a lean pivot.
TEST(SeatLeanPivot, IsOnlyOneVertexStickingClearOfTheEnds) {
  const BlockOnLine seat(0.0, false);
  const SeatPair toe{ContactKind::block_vertex, 1, 0}, heel{ContactKind::block_vertex, 0, 0};
  SeatSystem slipping(seat.context, {{toe, ContactState::slip_positive}}, {0}, {});
  slipping.set_clear_of_ends(true);
  EXPECT_FALSE(slipping.lean_pivot());
  SeatSystem two(seat.context, {{heel, ContactState::stick}, {toe, ContactState::stick}}, {}, {});
  two.set_clear_of_ends(true);
  EXPECT_FALSE(two.lean_pivot());
  SeatSystem pivot(seat.context, {{toe, ContactState::stick}}, {0}, {});
  pivot.set_clear_of_ends(false);
  EXPECT_FALSE(pivot.lean_pivot());
  pivot.set_clear_of_ends(true);
  EXPECT_TRUE(pivot.lean_pivot());
  Scene on_two = seat.scene;
  on_two.seat = Seat{{{-1000.0, 0.0}, {0.0, 0.0}, {1000.0, 0.0}}};
  const SeatContacts folded(scene_block_vertices(on_two), on_two.seat->points);
  SeatSystemContext on_two_context = seat.context;
  on_two_context.contacts = &folded;
  SeatSystem on_two_segments(on_two_context, {{toe, ContactState::stick}}, {0}, {});
  on_two_segments.set_clear_of_ends(true);
  EXPECT_FALSE(on_two_segments.lean_pivot());
}

}  // namespace
}  // namespace blockfrag
