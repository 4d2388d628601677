// How far a seated block's crack opens under the uplift rule "zero_in_gap" (USBR 1987, "uplift
// pressure within the crack is assumed to be zero", as CADAM and CADAM3D apply it: the crack
// opens from the side that lifts, the open part carries no uplift, the closed rest the static
// linear distribution, and the crack's length is iterated until the stresses at its tip balance;
// Leclerc, Leger & Tinawi, CADAM User's Manual; CADAM3D's help, "Uplift in cracks during
// earthquakes"). For a rigid block on its base the tip's stress is the lifting corner's normal
// force: the crack opens just far enough for it to reach zero. Removing uplift near the lifting
// corner presses that corner down, so its force does not decrease as the crack opens.
//
// One rule for the dynamics (engine/seat/seated_load.hpp, the corner's force from the contact
// problem) and the statics (engine/water/block_statics.hpp, from the moment about the other
// corner).
#pragma once

namespace blockfrag {

// The side of a seated block's base whose outermost contact lifts: upstream (the heel, at the
// crack's mouth) or downstream (the toe, at its end).
enum class LiftingSide { upstream, downstream };

// The least fraction f in [0, 1] of the crack's length, opened from the lifting side, at which
// corner_force(f) >= 0: 0 where the closed crack already seats the corner (corner_force(0) >= 0),
// 1 where even a fully open crack leaves it in tension (the block rocks). corner_force must not
// decrease in f. Bisected to the last bit of f.
template <class CornerForce>
double seating_opening(const CornerForce& corner_force) {
  if (corner_force(0.0) >= 0.0) return 0.0;
  if (!(corner_force(1.0) >= 0.0)) return 1.0;
  double lifted = 0.0, seated = 1.0;
  for (;;) {
    const double middle = 0.5 * (lifted + seated);
    if (middle == lifted || middle == seated) return seated;
    (corner_force(middle) >= 0.0 ? seated : lifted) = middle;
  }
}

}  // namespace blockfrag
