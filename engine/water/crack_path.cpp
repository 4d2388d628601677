#include "engine/water/crack_path.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/errors.hpp"

namespace blockfrag {

namespace {

// A point on the outline: on edge `edge` at the fraction t in [0, 1) of its length (t = 0 at a
// vertex).
struct OutlinePlace {
  std::size_t edge;
  double t;
};

OutlinePlace place_on_outline(const WorldPolygon& block, const Vertex& p, double tolerance) {
  const std::size_t n = block.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (std::hypot(block[i][0] - p[0], block[i][1] - p[1]) <= tolerance) return {i, 0.0};
  }
  OutlinePlace best{0, 0.0};
  double nearest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < n; ++i) {
    const Vertex& a = block[i];
    const Vertex& b = block[(i + 1) % n];
    const double dx = b[0] - a[0], dy = b[1] - a[1];
    const double t =
        std::clamp(((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
    const double distance = std::hypot(p[0] - (a[0] + t * dx), p[1] - (a[1] + t * dy));
    if (distance < nearest) {
      nearest = distance;
      best = {i, t};
    }
  }
  if (!(nearest <= tolerance)) {
    throw ContractViolation("crack_between: a crack's end is not on the block's outline");
  }
  return best;
}

}  // namespace

double CrackPath::length() const {
  double total = 0.0;
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    total += std::hypot(points[i + 1][0] - points[i][0], points[i + 1][1] - points[i][1]);
  }
  return total;
}

CrackPath crack_between(const WorldPolygon& block, const Vertex& mouth, const Vertex& end,
                        double tolerance) {
  const std::size_t n = block.size();
  const OutlinePlace from = place_on_outline(block, mouth, tolerance);
  const OutlinePlace to = place_on_outline(block, end, tolerance);
  const auto point_at = [&](const OutlinePlace& place) -> Vertex {
    if (place.t == 0.0) return block[place.edge];
    const Vertex& a = block[place.edge];
    const Vertex& b = block[(place.edge + 1) % n];
    return {a[0] + place.t * (b[0] - a[0]), a[1] + place.t * (b[1] - a[1])};
  };
  CrackPath crack;
  crack.points.push_back(point_at(from));
  if (from.edge == to.edge && from.t <= to.t) {
    if (to.t > from.t) {
      crack.points.push_back(point_at(to));
      crack.edges.push_back(from.edge);
    }
    return crack;
  }
  // Counter-clockwise from the mouth's edge through every vertex up to the end's edge.
  std::size_t edge = from.edge;
  do {
    crack.edges.push_back(edge);
    edge = (edge + 1) % n;
    crack.points.push_back(block[edge]);
  } while (edge != to.edge);
  if (to.t > 0.0) {
    crack.edges.push_back(to.edge);
    crack.points.push_back(point_at(to));
  }
  return crack;
}

CrackPath crack_under(const WorldPolygon& block, const std::vector<Support>& supports,
                      double tolerance) {
  const OutermostSupports outermost = outermost_supports(supports);
  return crack_between(block, outermost.upstream, outermost.downstream, tolerance);
}

void place_crack(const std::vector<Vertex>& body_points, double cos_theta, double sin_theta,
                 const Vertex& shift, std::span<Vertex> out) {
  for (std::size_t i = 0; i < body_points.size(); ++i) {
    const Vertex& p = body_points[i];
    out[i] = {shift[0] + p[0] * cos_theta - p[1] * sin_theta,
              shift[1] + p[0] * sin_theta + p[1] * cos_theta};
  }
}

}  // namespace blockfrag
