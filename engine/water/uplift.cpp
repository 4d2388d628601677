#include "engine/water/uplift.hpp"

#include <algorithm>

#include "engine/errors.hpp"
#include "engine/water/linear_pressure.hpp"

namespace blockfrag {

UpliftLoad crack_uplift(const Crack& crack, const StillWater& water, double area_factor,
                        const Vertex& reference) {
  if (!(crack.end_x > crack.mouth_x) || !(area_factor >= 0.0 && area_factor <= 1.0)) {
    throw ContractViolation("crack_uplift: needs end_x > mouth_x and an area factor in [0, 1]");
  }
  const double head = std::max(0.0, water.surface - crack.y);
  const double mouth_pressure = area_factor * water.density * water.g * head;
  // The crack is the block's base: its outward normal points down, the water presses up.
  const WaterLoad load = linear_pressure_load({crack.mouth_x, crack.y}, {crack.end_x, crack.y},
                                              mouth_pressure, 0.0, {0.0, -1.0}, reference);
  return {load.fy, crack.mouth_x + (crack.end_x - crack.mouth_x) / 3, load.moment};
}

}  // namespace blockfrag
