// The paper's dam blocks with the water at their crest, as configs/dam_block_type_a_reservoir.json
// and configs/dam_block_type_b_reservoir.json have them (H = 100 m, Westergaard, restitution 0.2),
// under a constant ground acceleration lambda g from t = 0 for 0.3 s, solved to 1e-10: the scenes
// of the reservoir's onset tests, with friction mu and the uplift rule given.
#pragma once

#include "engine/scene/scene.hpp"

namespace blockfrag::testing {

inline Scene wet_type_a_step(double mu, double lambda, UpliftRule rule) {
  Scene scene;
  scene.polygon = PolygonBlock{{{0, 0}, {12.55, 0}, {10, 3.4}, {10, 16.7}, {0, 16.7}}, 411204.0};
  scene.contact = {mu, 0.2};
  scene.reservoir = Reservoir{};
  scene.reservoir->level = 16.7;
  scene.reservoir->uplift = rule;
  scene.ground_motion = RectangularPulse{lambda, 1.0};
  scene.duration = 0.3;
  scene.solver.tolerance = 1e-10;
  return scene;
}

// The type B block on its seat.
inline Scene wet_type_b_step(double mu, double lambda, UpliftRule rule) {
  Scene scene = wet_type_a_step(mu, lambda, rule);
  const double fold = 5.858333333333333;
  scene.polygon = PolygonBlock{
      {{0, 0}, {fold, 0}, {12.525, 5}, {10, 8.366666666666667}, {10, 21.7}, {0, 21.7}}, 521301.0};
  scene.seat = Seat{{{0, 0}, {fold, 0}, {12.525, 5}}};
  scene.reservoir->level = 21.7;
  return scene;
}

}  // namespace blockfrag::testing
