// The load on a block seated on two contacts or more of its seat, under an external load that
// opens the crack under its base (ExternalLoad::opens_seated_crack: the reservoir's
// "zero_in_gap" uplift). Where the closed crack's load would pull an outermost contact (the heel
// upstream, the toe downstream) off the seat, the crack opens from that contact's side just far
// enough for the contact's normal force to reach zero (engine/contact/crack_seating.hpp); where
// even a fully open crack leaves it in tension, the crack is fully open and the contact's lift-off
// guard crosses zero: the block rocks about the other side. So the block rocks where the statics
// say (engine/water/block_statics.hpp), and does not rattle between a closed crack that lifts it
// and an open one that sets it down.
#pragma once

#include <span>

#include "engine/contact/body_load.hpp"
#include "engine/contact/planar_contact.hpp"

namespace blockfrag {

struct SeatedLoadInput {
  double inertia_per_mass, lambda, lambda_v, g, mu;
  const ExternalLoad* external;  // none: the dry block
};

// The load at the state s on the active `contacts` in their `states`. The crack's opening is the
// quasi-static one first: the least that keeps the loads' moment about the other outermost contact
// pressing the lifting one down, as at rest and in the statics (CADAM's pseudo-static crack length
// under the loads of the moment; the forces of three sticking contacts or more are not unique). A
// sliding block's friction grows with the normal force the opening adds and tips it forward, so
// with the contacts slipping the lifting corner's force can fall again as the crack opens further:
// the opening is then the least one up to the quasi-static one that seats the corner under the
// contacts' own states, and where none does, the quasi-static one (the corner lifts: its guard
// crosses zero). Any other load, or fewer than two contacts: the seated load, body_load(...,
// Footing::seated). The openings tried are the external load's at s (ExternalLoad::search_openings:
// the reservoir places the block once for them all).
BodyLoad seated_load(const SeatedLoadInput& in, const BlockState& s,
                     std::span<const PlanarContact> contacts, std::span<const ContactState> states);

}  // namespace blockfrag
