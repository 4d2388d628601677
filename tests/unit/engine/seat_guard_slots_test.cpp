// A seat system sets only the guard slots it uses: overturning and falling, four per active contact
// (lift-off, friction or slip, and a slipping contact's two ends), one per watched vertex or
// point. Its events, its live guards and its unused guards must agree with that layout slot by
// slot over every mix of contacts and watched lists of the paper's type B block.
#include <array>
#include <cstddef>
#include <span>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "engine/seat/seat_system.hpp"
#include "tests/support/type_b_seat_system.hpp"

namespace blockfrag {
namespace {

// The event of each slot as the layout gives it, every slot looked at.
std::array<SeatEvent, kSeatGuards> layout_events(const std::vector<ActiveContact>& active,
                                                 std::size_t watched) {
  std::array<SeatEvent, kSeatGuards> events;
  events.fill(SeatEvent::none);
  events[0] = SeatEvent::overturns;
  events[1] = SeatEvent::falls;
  for (std::size_t i = 0; i < active.size(); ++i) {
    const std::size_t base = 2 + kSeatContactGuards * i;
    const bool sticks = active[i].state == ContactState::stick;
    events[base] = SeatEvent::lift_off;
    events[base + 1] = sticks ? SeatEvent::friction_limit : SeatEvent::slip_stops;
    if (!sticks) events[base + 2] = events[base + 3] = SeatEvent::leaves_end;
  }
  for (std::size_t k = 0; k < watched; ++k) {
    events[static_cast<std::size_t>(kFirstClearanceGuard) + k] = SeatEvent::touches;
  }
  return events;
}

TEST(SeatGuardSlots, EventsLiveAndUnusedGuardsFollowTheLayout) {
  const testing::TypeBSeat seat;
  std::vector<std::vector<ActiveContact>> sets = testing::type_b_contact_sets();
  sets.insert(sets.begin(), std::vector<ActiveContact>{});
  const std::vector<std::pair<WatchedList, WatchedList>> watched = {
      {{}, {}}, {{0, 3, 4, 5}, {}}, {{}, {1}}, {{2, 3, 4, 5}, {0, 1, 2}}};
  int slots = 0;
  for (const auto& active : sets) {
    for (const auto& [vertices, points] : watched) {
      const SeatSystem system = seat.system(active, vertices, points);
      const auto expected = layout_events(active, vertices.size() + points.size());
      const GuardClaims live = system.live_guards(), unused = system.unused_guards();
      std::vector<int> live_in_order;
      for (int i = 0; i < kSeatGuards; ++i) {
        const auto at = static_cast<std::size_t>(i);
        EXPECT_EQ(system.event(i), expected[at]) << i;
        EXPECT_EQ(live[at], expected[at] != SeatEvent::none) << i;
        EXPECT_EQ(unused[at], expected[at] == SeatEvent::none) << i;
        if (expected[at] != SeatEvent::none) live_in_order.push_back(i);
        ++slots;
      }
      // The watch takes the live slots as the system lists them.
      const std::span<const int> listed = system.live_slots();
      EXPECT_EQ(std::vector<int>(listed.begin(), listed.end()), live_in_order);
    }
  }
  EXPECT_EQ(slots, 7 * 4 * kSeatGuards);
}

}  // namespace
}  // namespace blockfrag
