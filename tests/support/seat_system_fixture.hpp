// A block on its seat with what a SeatSystem is built on around it: the seat's contacts, the
// block's geometry, the ground's motion pieces (a cosine pulse of 0.4 g, 1.9 s, and no vertical
// motion) and the reservoir's load, the block dry or under the scene's reservoir. Not to be copied:
// its context points into it.
#pragma once

#include <utility>

#include "engine/scene/block_geometry.hpp"
#include "engine/scene/seat.hpp"
#include "engine/seat/seat_system.hpp"
#include "engine/water/reservoir_load.hpp"

namespace blockfrag::testing {

struct SeatSystemFixture {
  // `scene` has a seat and a reservoir, whose load acts only `wet`.
  SeatSystemFixture(Scene scene_, bool wet, double mu)
      : scene(std::move(scene_)), under_water(wet), friction(mu) {}
  SeatSystemFixture(const SeatSystemFixture&) = delete;
  SeatSystemFixture& operator=(const SeatSystemFixture&) = delete;

  Scene scene;
  bool under_water;
  double friction;
  ReservoirLoad water{scene};
  SeatContacts contacts{scene_block_vertices(scene), scene.seat->points};
  BlockGeometry geometry{*scene.polygon};
  MotionPiece ground{{MotionPiece::Shape::cosine, 0.4, 1.9}, 0.0, 1e3};
  MotionPiece still{MotionPiece::Formula{}, 0.0, 1e3};
  SeatSystemContext context{&contacts,
                            &geometry,
                            &ground,
                            &still,
                            scene.g,
                            friction,
                            0.5 * geometry.size(),
                            under_water ? &water : nullptr};
};

}  // namespace blockfrag::testing
