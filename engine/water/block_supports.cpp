#include "engine/water/block_supports.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "engine/errors.hpp"

namespace blockfrag {

namespace {

double distance_to_segment(const Vertex& a, const Vertex& b, const Vertex& p) {
  const double dx = b[0] - a[0], dy = b[1] - a[1];
  const double t =
      std::clamp(((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
  return std::hypot(p[0] - (a[0] + t * dx), p[1] - (a[1] + t * dy));
}

// Left of the direction from a to b: up for a seat segment (x increasing), inward for a
// counter-clockwise block's edge.
Vertex left_normal(const Vertex& a, const Vertex& b) {
  const double dx = b[0] - a[0], dy = b[1] - a[1];
  const double length = std::hypot(dx, dy);
  return {-dy / length, dx / length};
}

}  // namespace

std::vector<Support> flat_ground_supports(const WorldPolygon& block, double ground_y,
                                          double tolerance) {
  std::vector<Support> supports;
  for (const Vertex& v : block) {
    if (v[1] <= ground_y + tolerance) supports.push_back({v, {0.0, 1.0}});
  }
  return supports;
}

std::vector<Support> seat_supports(const WorldPolygon& block, const std::vector<Vertex>& seat,
                                   double tolerance) {
  std::vector<Support> supports;
  for (const Vertex& v : block) {
    for (std::size_t s = 0; s + 1 < seat.size(); ++s) {
      if (distance_to_segment(seat[s], seat[s + 1], v) <= tolerance) {
        supports.push_back({v, left_normal(seat[s], seat[s + 1])});
      }
    }
  }
  for (const Vertex& p : seat) {
    const bool at_vertex = std::any_of(block.begin(), block.end(), [&](const Vertex& v) {
      return std::hypot(v[0] - p[0], v[1] - p[1]) <= tolerance;
    });
    if (at_vertex) continue;
    for (std::size_t i = 0; i < block.size(); ++i) {
      const Vertex& a = block[i];
      const Vertex& b = block[(i + 1) % block.size()];
      if (distance_to_segment(a, b, p) <= tolerance) supports.push_back({p, left_normal(a, b)});
    }
  }
  return supports;
}

std::vector<Support> scene_supports(const Scene& scene, double ground_y, const WorldPolygon& block,
                                    double tolerance) {
  return scene.seat ? seat_supports(block, scene.seat->points, tolerance)
                    : flat_ground_supports(block, ground_y, tolerance);
}

OutermostSupports outermost_supports(const std::vector<Support>& supports) {
  if (supports.empty()) throw ContractViolation("outermost_supports: no support");
  const auto by_x = [](const Support& a, const Support& b) { return a.point[0] < b.point[0]; };
  return {std::min_element(supports.begin(), supports.end(), by_x)->point,
          std::max_element(supports.begin(), supports.end(), by_x)->point};
}

}  // namespace blockfrag
