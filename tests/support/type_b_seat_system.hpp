// The paper's type B block on its seat as the seat's guards see it, on still ground: the fixture of
// the tests of which guards a step claims (seat_ends_test, seat_swept_claims_test).
#pragma once

#include <vector>

#include "engine/motion/ground_motion.hpp"
#include "engine/scene/block_geometry.hpp"
#include "engine/seat/seat_contacts.hpp"
#include "engine/seat/seat_system.hpp"
#include "tests/support/type_b_block.hpp"

namespace blockfrag::testing {

// Every guard is asked about.
inline const GuardClaims kEveryGuard = [] {
  GuardClaims every;
  every.fill(true);
  return every;
}();

// The contact sets the seat system's tests go through on the type B seat: one contact sticking,
// slipping either way (a block vertex and a seat point), two sticking, two slipping, and one
// sticking with a seat point slipping.
inline std::vector<std::vector<ActiveContact>> type_b_contact_sets() {
  const SeatPair heel{ContactKind::block_vertex, 0, 0}, fold{ContactKind::block_vertex, 1, 0};
  const SeatPair toe{ContactKind::block_vertex, 2, 1}, point{ContactKind::seat_point, 1, 0};
  return {{{toe, ContactState::stick}},
          {{heel, ContactState::slip_negative}},
          {{point, ContactState::slip_positive}},
          {{heel, ContactState::stick}, {fold, ContactState::stick}},
          {{heel, ContactState::slip_positive}, {fold, ContactState::slip_positive}},
          {{heel, ContactState::stick}, {point, ContactState::slip_negative}}};
}

// On its own seat, or on `seat`. Not to be copied: its context points into it.
struct TypeBSeat {
  SeatContacts contacts{kTypeB, kTypeBSeat};
  BlockGeometry geometry{PolygonBlock{kTypeB, 1.0}};
  MotionPiece still{MotionPiece::Formula{}, 0.0, 1e3};
  SeatSystemContext context{&contacts, &geometry, &still, &still, 9.81, 1.0, 0.5 * geometry.size()};

  TypeBSeat() = default;
  explicit TypeBSeat(const std::vector<Vertex>& seat) : contacts(kTypeB, seat) {}
  TypeBSeat(const TypeBSeat&) = delete;
  TypeBSeat& operator=(const TypeBSeat&) = delete;

  SeatSystem system(const std::vector<ActiveContact>& active, const WatchedList& vertices,
                    const WatchedList& points) const {
    return SeatSystem(context, active, vertices, points);
  }
};

}  // namespace blockfrag::testing
