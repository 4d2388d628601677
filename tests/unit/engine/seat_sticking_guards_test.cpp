// A block turning on one sticking contact has its two force guards (lift-off, friction) from that
// contact alone, posed from the world vertices and solved without the passes over the contacts
// (SeatSystem::set_sticking_guards): they, and the forces kept for the next asks at that time and
// state, are those of the contact pose() gives under the lifted block's load, to the bit, as the
// general contact guards find them, whether the system solved there before or not and whichever of
// the two guards is asked for. Over random states of the type A block on a flat one-segment seat
// (its toe) and of the type B block on its own seat (its toe, a seat point on its base), dry and
// under the reservoir.
#include <cmath>
#include <cstddef>
#include <vector>

#include <gtest/gtest.h>

#include "engine/scene/block_geometry.hpp"
#include "engine/scene/scene_validation.hpp"
#include "engine/scene/seat.hpp"
#include "engine/seat/seat_system.hpp"
#include "engine/water/block_outline.hpp"
#include "engine/water/reservoir_load.hpp"
#include "tests/support/fixed_uniforms.hpp"
#include "tests/support/same_bits.hpp"
#include "tests/support/seat_system_fixture.hpp"
#include "tests/support/wet_dam_blocks.hpp"

namespace blockfrag {
namespace {

using testing::same_bits;

constexpr double kMu = 0.9;

// A dam block on its seat (the type A block's: flat, of one segment, 1000 m either side), dry or
// under the reservoir at its crest.
struct BlockOnSeat : testing::SeatSystemFixture {
  BlockOnSeat(bool type_b, bool wet) : SeatSystemFixture(make_scene(type_b), wet, kMu) {}

 private:
  static Scene make_scene(bool type_b) {
    Scene s = type_b ? testing::wet_type_b_step(kMu, 0.3, UpliftRule::unchanged)
                     : testing::wet_type_a_step(kMu, 0.3, UpliftRule::unchanged);
    if (!type_b) s.seat = Seat{{{-993.725, 0.0}, {1006.275, 0.0}}};
    validate_scene(s);
    return s;
  }
};

// The forces of the one sticking contact `pair` at s as pose() gives it, solved as the system
// solves one contact under the lifted block's load.
FixedStateForces posed_forces(const BlockOnSeat& seat, const SeatPair& pair, const BlockState& s,
                              double t) {
  const PlanarContact contact = seat.contacts.pose(pair, s).contact;
  const ContactState stick = ContactState::stick;
  MotionPiece ground = seat.ground;  // lambda() remembers its last time
  const BodyLoad load = body_load(seat.geometry.inertia_per_mass(), ground.lambda(t), 0.0,
                                  seat.scene.g, seat.context.external, s, Footing::lifted);
  const auto one = one_contact_forces(contact, stick, s, load, kMu);
  return one ? *one : fixed_state_forces({&contact, 1}, {&stick, 1}, s, load, kMu);
}

void expect_same_forces(const FixedStateForces& kept, const FixedStateForces& posed, int n) {
  EXPECT_TRUE(same_bits(kept.acceleration.x_dd, posed.acceleration.x_dd)) << n;
  EXPECT_TRUE(same_bits(kept.acceleration.y_dd, posed.acceleration.y_dd)) << n;
  EXPECT_TRUE(same_bits(kept.acceleration.theta_dd, posed.acceleration.theta_dd)) << n;
  EXPECT_TRUE(same_bits(kept.total.x, posed.total.x)) << n;
  EXPECT_TRUE(same_bits(kept.total.y, posed.total.y)) << n;
  EXPECT_TRUE(same_bits(kept.normal[0], posed.normal[0])) << n;
  EXPECT_TRUE(same_bits(kept.tangent[0], posed.tangent[0])) << n;
}

// Returns how many states were compared.
int expect_sticking_guards_are_the_posed_contacts(const BlockOnSeat& seat, const SeatPair& pair,
                                                  unsigned seed) {
  const std::vector<ActiveContact> active{{pair, ContactState::stick}};
  const BlockState rest = BlockOutline(seat.scene).rest_state();
  const double g = seat.scene.g;
  testing::FixedUniforms u(seed);
  SeatSystem reused(seat.context, active, {}, {});
  int compared = 0;
  for (int n = 0; n < 150; ++n) {
    const BlockState s{
        rest.x + u(-1.0, 1.0), rest.y + u(-0.5, 0.5), u(-0.3, 0.3), u(-1, 1), u(-1, 1), u(-1, 1)};
    const double t = u(0.0, 3.0);
    const FixedStateForces f = posed_forces(seat, pair, s, t);
    const double lift_off = f.normal[0] / g;
    const double friction = (kMu * f.normal[0] - std::abs(f.tangent[0])) / g;
    // A system that has solved nothing yet, one that solved elsewhere before, and one that has
    // solved here (its kept forces read).
    const auto fresh = SeatSystem(seat.context, active, {}, {}).guards(t, s);
    const auto after_other = reused.guards(t, s);
    SeatSystem solved_here(seat.context, active, {}, {});
    solved_here.solve(t, s);
    const auto kept = solved_here.guards(t, s);
    for (const auto& guards : {fresh, after_other, kept}) {
      EXPECT_TRUE(same_bits(guards[2], lift_off)) << n;
      EXPECT_TRUE(same_bits(guards[3], friction)) << n;
    }
    expect_same_forces(reused.solve(t, s), f, n);
    // Each force guard asked for alone.
    for (const std::size_t slot : {std::size_t{2}, std::size_t{3}}) {
      GuardClaims one{};
      one[slot] = true;
      const double alone = SeatSystem(seat.context, active, {}, {}).guards(t, s, one)[slot];
      EXPECT_TRUE(same_bits(alone, slot == 2 ? lift_off : friction)) << n << " " << slot;
    }
    ++compared;
  }
  return compared;
}

TEST(SeatStickingGuards, AreThoseOfThePosedContactToTheBitOnTheTypeABlocksToe) {
  const SeatPair toe{ContactKind::block_vertex, 1, 0};
  for (const bool wet : {false, true}) {
    const BlockOnSeat seat(false, wet);
    EXPECT_EQ(expect_sticking_guards_are_the_posed_contacts(seat, toe, wet ? 11 : 13), 150);
  }
}

TEST(SeatStickingGuards, AreThoseOfThePosedContactToTheBitOnTheTypeBBlocksSeat) {
  const SeatPair toe{ContactKind::block_vertex, 2, 1}, point{ContactKind::seat_point, 1, 0};
  for (const bool wet : {false, true}) {
    const BlockOnSeat seat(true, wet);
    EXPECT_EQ(expect_sticking_guards_are_the_posed_contacts(seat, toe, wet ? 17 : 19), 150);
    EXPECT_EQ(expect_sticking_guards_are_the_posed_contacts(seat, point, wet ? 23 : 29), 150);
  }
}

}  // namespace
}  // namespace blockfrag
