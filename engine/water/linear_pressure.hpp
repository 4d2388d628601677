// The resultant of a pressure that varies linearly along a straight segment: the hydrostatic
// pressure on a wetted edge and the uplift in a crack both are one.
#pragma once

#include "engine/water/water_load.hpp"

namespace blockfrag {

// Pressure p_a at a, p_b at b, linear between, pressing on the body whose outward unit normal on
// the segment is `outward`: the force is -outward p per unit length. With s the distance from a
// and l the segment's length, the resultant is exact:
//   F = -outward l (p_a + p_b) / 2,
//   M = (integral of (r(s) - c) p(s) ds) x (-outward),
//   integral of (r(s) - c) p(s) ds = (a - c) l (p_a + p_b) / 2 + (b - a) l (p_a + 2 p_b) / 6,
// about the reference point c; no division, so a zero pressure gives exactly zero.
WaterLoad linear_pressure_load(const Vertex& a, const Vertex& b, double p_a, double p_b,
                               const Vertex& outward, const Vertex& reference);

// The same on a piece of a counter-clockwise outline's edge, run in the edge's direction, whose
// outward normal is (dy, -dx) / l with (dx, dy) = b - a: l cancels from every term,
//   F = (-dy, dx) (p_a + p_b) / 2,
//   M = ((a - c) (p_a + p_b) / 2 + (b - a) (p_a + 2 p_b) / 6) x (-dy, dx),
// so the load needs no square root, and a piece cut from an edge presses along the edge's normal.
// Inline: the reservoir's loads find it for each wetted piece at every right-hand side.
inline WaterLoad edge_pressure_load(const Vertex& a, const Vertex& b, double p_a, double p_b,
                                    const Vertex& reference) {
  const double dx = b[0] - a[0], dy = b[1] - a[1];
  const double mean = (p_a + p_b) / 2;
  const double first = (p_a + 2 * p_b) / 6;
  const double arm_x = (a[0] - reference[0]) * mean + dx * first;
  const double arm_y = (a[1] - reference[1]) * mean + dy * first;
  WaterLoad load;
  load.fx = -dy * mean;
  load.fy = dx * mean;
  load.moment = cross(arm_x, arm_y, -dy, dx);
  return load;
}

}  // namespace blockfrag
