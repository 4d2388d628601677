// The contact forces of a block on its seat for a fixed set of contact states (docs/physics.md,
// "Contact on a seat"): each active contact's normal acceleration is zero, a sticking one's
// tangential too, a slipping one's friction is -s mu times its normal force. Per unit mass.
#pragma once

#include <array>
#include <optional>
#include <span>

#include "engine/contact/body_load.hpp"
#include "engine/contact/planar_contact.hpp"
#include "engine/scene/block_state.hpp"

namespace blockfrag {

// At most this many contacts at once (engine/contact/contact_lcp.hpp's limit).
inline constexpr int kMaxSeatContacts = 6;

struct FixedStateForces {
  BodyAcceleration acceleration{0.0, 0.0, 0.0};
  std::array<double, kMaxSeatContacts> normal{}, tangent{};
  Vec2 total{0.0, 0.0};  // the sum of the contact forces, world frame
};

// The forces of the fixed states at the state s under the load (per unit mass): any number of
// contacts, solved by full-pivoting LU (least-norm forces where the contacts are redundant); two
// slipping contacts by two_slipping_contacts_forces where it gives them.
FixedStateForces fixed_state_forces(std::span<const PlanarContact> contacts,
                                    std::span<const ContactState> states, const BlockState& s,
                                    const BodyLoad& load, double mu);
// No contact (flight): no forces, and the load's own accelerations, M^-1 Q; what the general solve
// gives for no contacts, without its passes (a wet block's flight, at every stage).
FixedStateForces no_contact_forces(const BodyLoad& load);
// The same always by the LU.
FixedStateForces general_fixed_state_forces(std::span<const PlanarContact> contacts,
                                            std::span<const ContactState> states,
                                            const BlockState& s, const BodyLoad& load, double mu);

// Two slipping contacts (a flat base sliding on its seat: a 2x2 system in the normal forces), the
// general solve's operations on the same entries in the same order, its LU written out for 2x2 as
// for one sticking contact below; under any mass matrix. Nothing for other contacts or where the
// system is singular.
std::optional<FixedStateForces> two_slipping_contacts_forces(
    std::span<const PlanarContact> contacts, std::span<const ContactState> states,
    const BlockState& s, const BodyLoad& load, double mu);

// The same for one contact (sticking: a 2x2 system, slipping: 1x1) in fixed-size arithmetic, the
// general solve's operations on the same entries in the same order (Eigen's full-pivoting LU
// written out), so that both give the same numbers; nothing where the system is singular, which
// the general solve's least-norm forces handle, and nothing for a coupled mass matrix (the
// reservoir's added mass), which the general solve takes. The flat ground's sticking_corner and
// slipping_corner (engine/contact/contact_dynamics.hpp) are this system for a vertical normal,
// solved in closed form in another order, whose rounding differs.
std::optional<FixedStateForces> one_contact_forces(const PlanarContact& c, ContactState state,
                                                   const BlockState& s, const BodyLoad& load,
                                                   double mu);
// The same into `out` (its contact 0's entries, total and acceleration; the others are left as
// they are), without the copies of a returned one: false where the above gives nothing (`out`
// then unspecified).
bool one_contact_forces(const PlanarContact& c, ContactState state, const BlockState& s,
                        const BodyLoad& load, double mu, FixedStateForces& out);

}  // namespace blockfrag
