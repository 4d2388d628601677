// The uplift in a crack under a block: the reservoir's head at the crack's upstream mouth falling
// linearly to zero at its downstream end (the static rule of USACE EM 1110-2-2200, 1995, FERC's
// guidelines chapter III and USBR for a crack through the section without drains, as compared by
// Ebeling et al. 2000, ERDC/ITL TR-00-1), times an effective area factor c (CADAM3D's uplift
// effective area). Over a crack of length B with head h = y_w - y_c at its mouth:
//   p(x) = c rho_w g h (1 - (x - x_u) / B),   U = 1/2 c rho_w g h B, upward, at x_u + B/3.
#pragma once

#include "engine/water/water_load.hpp"

namespace blockfrag {

// A straight horizontal crack from its upstream mouth to its downstream end.
struct Crack {
  double mouth_x;  // x_u, m
  double end_x;    // x_d > x_u, m
  double y;        // y_c, m
};

struct UpliftLoad {
  double force = 0.0;    // U, N/m, upward
  double point_x = 0.0;  // where it acts: x_u + B/3
  double moment = 0.0;   // about the reference point, N m/m, counter-clockwise positive
};

// `area_factor` c in [0, 1]. No head (a surface at or below the crack) is no uplift, exactly.
UpliftLoad crack_uplift(const Crack& crack, const StillWater& water, double area_factor,
                        const Vertex& reference);

}  // namespace blockfrag
