// A sample inside a step asks only for the guards it still follows (SeatSystem::guards(t, s,
// wanted)), and the contact forces, with the water's loads they take, are solved only where a guard
// made of them (a lift-off guard, a sticking contact's friction guard) is among those: each contact
// guard asked for alone, and with others at random, is the one guards() computes with all of them,
// to the bit, dry and under the reservoir, in each of the seat system's contact sets of the type B
// block, over random states asked of one system in turn.
#include <cstddef>
#include <vector>

#include <gtest/gtest.h>

#include "engine/scene/block_geometry.hpp"
#include "engine/scene/scene_validation.hpp"
#include "engine/scene/seat.hpp"
#include "engine/seat/seat_system.hpp"
#include "engine/water/reservoir_load.hpp"
#include "tests/support/fixed_uniforms.hpp"
#include "tests/support/same_bits.hpp"
#include "tests/support/type_b_seat_system.hpp"
#include "tests/support/wet_dam_blocks.hpp"

namespace blockfrag {
namespace {

using testing::same_bits;

// The type B block on its seat under the reservoir at its crest, or dry (`wet` false).
struct TypeBOnItsSeat {
  explicit TypeBOnItsSeat(bool wet) : context(make_context(wet)) {}
  TypeBOnItsSeat(const TypeBOnItsSeat&) = delete;
  TypeBOnItsSeat& operator=(const TypeBOnItsSeat&) = delete;

  Scene scene = [] {
    Scene s = testing::wet_type_b_step(0.7, 0.3, UpliftRule::unchanged);
    validate_scene(s);
    return s;
  }();
  ReservoirLoad water{scene};
  SeatContacts contacts{scene_block_vertices(scene), scene.seat->points};
  BlockGeometry geometry{*scene.polygon};
  MotionPiece ground{{MotionPiece::Shape::cosine, 0.4, 1.3}, 0.0, 1e3};
  MotionPiece still{MotionPiece::Formula{}, 0.0, 1e3};
  SeatSystemContext context;

 private:
  SeatSystemContext make_context(bool wet) {
    return {&contacts,
            &geometry,
            &ground,
            &still,
            scene.g,
            0.7,
            0.5 * geometry.size(),
            wet ? &water : nullptr};
  }
};

// Whether slot i holds one of the active contacts' guards.
bool contact_slot(const SeatSystem& system, int i) {
  return i >= 2 && i < 2 + kSeatContactGuards * system.active_count() &&
         system.event(i) != SeatEvent::none;
}

void expect_wanted_contact_guards_are_all_guards(bool wet) {
  const TypeBOnItsSeat seat(wet);
  const std::vector<std::vector<ActiveContact>> sets = testing::type_b_contact_sets();
  testing::FixedUniforms u(wet ? 83 : 89);
  int alone = 0, among_others = 0;
  for (const std::vector<ActiveContact>& active : sets) {
    SeatSystem asked(seat.context, active, {}, {});
    for (int n = 0; n < 40; ++n) {
      // About the block at rest on its seat, 11 m up, its base's middle at x = 5.
      const BlockState s{u(4.0, 8.0), u(9.5, 11.5), u(-0.3, 0.3), u(-1, 1), u(-1, 1), u(-1, 1)};
      const double t = u(0.0, 3.0);
      const auto all = SeatSystem(seat.context, active, {}, {}).guards(t, s);
      for (int i = 0; i < SeatSystem::kGuards; ++i) {
        if (!contact_slot(asked, i)) continue;
        GuardClaims one{};
        one[static_cast<std::size_t>(i)] = true;
        const double value = asked.guards(t, s, one)[static_cast<std::size_t>(i)];
        EXPECT_TRUE(same_bits(value, all[static_cast<std::size_t>(i)])) << n << " " << i;
        ++alone;
      }
      GuardClaims some{};
      for (bool& w : some) w = u(0.0, 1.0) < 0.3;
      const auto found = asked.guards(t, s, some);
      for (int i = 0; i < SeatSystem::kGuards; ++i) {
        if (!some[static_cast<std::size_t>(i)] || !contact_slot(asked, i)) continue;
        EXPECT_TRUE(same_bits(found[static_cast<std::size_t>(i)], all[static_cast<std::size_t>(i)]))
            << n << " " << i;
        ++among_others;
      }
    }
  }
  // Per state: 2 (toe sticking) + 4 + 4 (one contact slipping) + 4 (two sticking) + 8 (two
  // slipping) + 6 (one of each) live contact guards.
  EXPECT_EQ(alone, 40 * 28);
  EXPECT_GT(among_others, 40 * 28 / 5);
}

TEST(SeatWantedContactGuards, AreThoseComputedWithAllGuardsToTheBitWhenDry) {
  expect_wanted_contact_guards_are_all_guards(false);
}

TEST(SeatWantedContactGuards, AreThoseComputedWithAllGuardsToTheBitUnderTheReservoir) {
  expect_wanted_contact_guards_are_all_guards(true);
}

}  // namespace
}  // namespace blockfrag
