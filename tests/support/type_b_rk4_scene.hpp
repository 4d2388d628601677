// The paper's type B dam block on its seat, dry, with the paper's RK4 step: the randomized scenes
// that once failed, each with an event budget small enough that a run that chatters again fails at
// once.
#pragma once

#include <utility>

#include "engine/scene/scene.hpp"
#include "tests/support/type_b_block.hpp"

namespace blockfrag::testing {

inline Scene type_b_rk4_scene(double friction, double restitution, GroundMotion motion,
                              double duration, long max_events) {
  Scene scene;
  scene.polygon = PolygonBlock{kTypeB, 521301.0};
  scene.seat = Seat{kTypeBSeat};
  scene.contact = {friction, restitution};
  scene.ground_motion = std::move(motion);
  scene.duration = duration;
  scene.solver.method = Method::rk4;
  scene.solver.dt = 0.00025;
  scene.solver.max_events = max_events;
  return scene;
}

}  // namespace blockfrag::testing
