#include "engine/water/linear_pressure.hpp"

#include <cmath>

namespace blockfrag {

WaterLoad linear_pressure_load(const Vertex& a, const Vertex& b, double p_a, double p_b,
                               const Vertex& outward, const Vertex& reference) {
  const double dx = b[0] - a[0], dy = b[1] - a[1];
  const double length = std::hypot(dx, dy);
  const double total = length * (p_a + p_b) / 2;      // integral of p ds
  const double first = length * (p_a + 2 * p_b) / 6;  // integral of (s / l) p ds
  const double arm_x = (a[0] - reference[0]) * total + dx * first;
  const double arm_y = (a[1] - reference[1]) * total + dy * first;
  WaterLoad load;
  load.fx = -outward[0] * total;
  load.fy = -outward[1] * total;
  load.moment = cross(arm_x, arm_y, -outward[0], -outward[1]);
  return load;
}

}  // namespace blockfrag
