// The reservoir behind the block ("reservoir" in a scene): the water's level, depth and density,
// and how it acts on the block while the ground shakes. The frame is the scene's (a polygon's
// vertices as given, a rectangle's about its centre, a seat's points): the reservoir is on the
// block's left (x < the block), downstream is +x. Loads are per metre of dam (the block is a slice
// of unit thickness), engine/water/reservoir_loads.hpp.
#pragma once

namespace blockfrag {

// The water's inertia on the block's upstream face: none, or Westergaard's (1933) added mass.
enum class Hydrodynamic { none, westergaard };

// The water in the crack under the block (the block's base on the flat ground, the seat's polyline
// under it on a seat) once the shaking opens it (engine/water/crack_pressure.hpp). Closed, the
// crack carries the static uplift of USACE EM 1110-2-2200 and FERC's guidelines chapter III: the
// head at its upstream mouth falling linearly to zero at its downstream end, times
// uplift_area_factor.
//   none: no uplift at all;
//   unchanged: the pre-earthquake uplift stays on the block throughout (USACE EM 1110-2-2100,
//     FERC chapter III);
//   zero_in_gap: no pressure where the base has lifted (USBR);
//   full_head_in_gap: the full head at the mouth over the open part (ICOLD).
enum class UpliftRule { none, unchanged, zero_in_gap, full_head_in_gap };

struct Reservoir {
  double level = 0.0;       // y_w: the water surface's y in the scene's frame, m
  double depth = 100.0;     // H: the reservoir's depth at the dam (Westergaard), m
  double density = 1000.0;  // rho_w, kg/m^3
  Hydrodynamic hydrodynamic = Hydrodynamic::westergaard;
  UpliftRule uplift = UpliftRule::unchanged;
  double uplift_area_factor = 1.0;  // c in [0, 1]
};

}  // namespace blockfrag
