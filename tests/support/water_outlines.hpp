// What the water-load tests share: fresh water, and outlines whose edge 0 (vertex 0 to 1) is the
// base, the crack the reservoir does not wet.
#pragma once

#include <array>
#include <cstddef>

#include "engine/water/water_load.hpp"

namespace blockfrag::testing {

inline constexpr double kWaterDensity = 1000.0;  // kg/m^3
inline constexpr std::array<std::size_t, 1> kBaseEdge{0};

// Counter-clockwise from the heel at the origin: a vertical upstream face of the given height.
inline WorldPolygon rectangle_outline(double width, double height) {
  return {{0, 0}, {width, 0}, {width, height}, {0, height}};
}

}  // namespace blockfrag::testing
