// What the reservoir's loads on a block are computed from and what they come to: plain values per
// metre of dam (the block's polygon is a slice of unit thickness), SI units, in the scene's frame:
// x downstream (the reservoir is on the block's left, at smaller x), y up.
#pragma once

#include <vector>

#include "engine/scene/polygon_properties.hpp"

namespace blockfrag {

// The reservoir at rest.
struct StillWater {
  double surface;  // y_w: the water surface's y, m
  double density;  // rho_w, kg/m^3
  double g;        // m/s^2
};

// A resultant per metre of dam: the force (N/m) and its moment (N m/m, counter-clockwise positive)
// about a reference point the caller names (the block's centre of mass).
struct WaterLoad {
  double fx = 0.0, fy = 0.0;
  double moment = 0.0;
};

// The block's outline at its current pose, in the world frame: counter-clockwise vertices, edge i
// from vertex i to vertex i + 1 (the last edge closes the polygon). What reads an outline placed at
// every right-hand side takes its vertices as std::span<const Vertex>, which the outline's room on
// the caller's stack (engine/water/vertex_buffer.hpp) serves as a WorldPolygon does.
using WorldPolygon = std::vector<Vertex>;

}  // namespace blockfrag
