// Where the ground holds a block resting at a pose: the points where it pushes on the block and the
// push's direction. The statics (engine/water/block_statics.hpp) slide the block along the lines
// these lie on and tip it about the outermost ones; the crack under the block runs between the
// outermost ones (engine/water/crack_path.hpp).
#pragma once

#include <vector>

#include "engine/scene/scene.hpp"
#include "engine/water/water_load.hpp"

namespace blockfrag {

struct Support {
  Vertex point;   // in the scene's frame
  Vertex normal;  // unit: the direction the ground pushes the block there
};

// The flat ground at height ground_y: the block's vertices within `tolerance` of it, pushed
// straight up.
std::vector<Support> flat_ground_supports(const WorldPolygon& block, double ground_y,
                                          double tolerance);

// A seat (engine/scene/seat.hpp): each block vertex within `tolerance` of a seat segment, pushed
// along the segment's upward normal (a vertex at a seat's fold gets both segments' normals), and
// each seat point within `tolerance` of a block edge but of none of its vertices, pushed along the
// edge's inward normal. A vertex meeting a seat point is a vertex on the seat's segments only: the
// seat's end under a heel does not push on the upstream face.
std::vector<Support> seat_supports(const WorldPolygon& block, const std::vector<Vertex>& seat,
                                   double tolerance);

// The scene's ground under its block at `block` (its outline in the scene's frame): the flat
// ground at ground_y (the block's lowest y at rest), or the scene's seat.
std::vector<Support> scene_supports(const Scene& scene, double ground_y, const WorldPolygon& block,
                                    double tolerance);

// The leftmost and rightmost supports' points (the upstream and downstream ones).
struct OutermostSupports {
  Vertex upstream, downstream;
};
// `supports` must not be empty.
OutermostSupports outermost_supports(const std::vector<Support>& supports);

}  // namespace blockfrag
