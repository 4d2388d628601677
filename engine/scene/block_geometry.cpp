#include "engine/scene/block_geometry.hpp"

#include <cmath>

#include "engine/scene/polygon_properties.hpp"
#include "engine/scene/seat.hpp"
#include "engine/tolerances.hpp"

namespace blockfrag {

BlockGeometry::BlockGeometry(const PolygonBlock& block) : size_(0.0) {
  const PolygonProperties p = polygon_properties(block.vertices);
  // Only the convex hull can touch a flat ground.
  corners_.reserve(p.hull.size());
  for (const auto& v : p.hull) {
    corners_.push_back({v[0], v[1]});
    size_ = std::max(size_, std::hypot(v[0], v[1]));
  }
  inertia_per_mass_ = p.inertia_per_mass;
  // A rectangle about its centre of mass takes its closed form I/M = R^2/3, which the shoelace sum
  // can miss in the last bit: a rectangle gives the same numbers to the bit whether it is given by
  // its sizes or by its vertices, and as before polygons existed.
  const auto& c = corners_;
  if (c.size() == 4 && c[0].x == -c[1].x && c[0].y == c[1].y && c[2].x == c[1].x &&
      c[2].y == -c[1].y && c[3].x == c[0].x && c[3].y == c[2].y) {
    inertia_per_mass_ = size_ * size_ / 3.0;
  }
  rest_height_ = -corners_[0].y;
  // The faces next to the base: from the right end to the vertex after it, and from the left end
  // to the vertex before it (mirrored, so a symmetric block gets the same angle both sides).
  const Vec2 left = corners_[0], right = corners_[1];
  const Vec2 after_right = corners_[2], before_left = corners_.back();
  overturn_angle_ = {std::atan2(before_left.y - left.y, left.x - before_left.x),
                     std::atan2(after_right.y - right.y, after_right.x - right.x)};
}

double block_alpha(const Scene& scene) {
  if (scene.seat) {
    return seat_alpha(scene.seat->points, scene_block_vertices(scene),
                      kContactHeight * scene_geometry(scene).size());
  }
  if (!scene.polygon) return std::atan2(scene.block.half_width, scene.block.half_height);
  return std::atan(BlockGeometry(*scene.polygon).flat_slide_friction_limit());
}

}  // namespace blockfrag
