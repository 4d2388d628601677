#include "engine/scene/polygon_properties.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <numeric>

#include "engine/scene/polygon_simplicity.hpp"

namespace blockfrag {

namespace {

std::size_t next(std::size_t i, std::size_t n) { return (i + 1) % n; }

// Twice the signed area (> 0 counter-clockwise).
double twice_area(const std::vector<Vertex>& v) {
  double sum = 0.0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Vertex& a = v[i];
    const Vertex& b = v[next(i, v.size())];
    sum += cross(a[0], a[1], b[0], b[1]);
  }
  return sum;
}

// The base's left end: of the vertices at the lowest y, the one the counter-clockwise order
// leaves along the base to the right.
std::size_t base_left(const std::vector<Vertex>& v) {
  std::size_t lowest = 0;
  for (std::size_t i = 1; i < v.size(); ++i) {
    if (v[i][1] < v[lowest][1]) lowest = i;
  }
  const std::size_t before = (lowest + v.size() - 1) % v.size();
  return v[before][1] == v[lowest][1] ? before : lowest;
}

std::vector<Vertex> convex_hull(const std::vector<Vertex>& points) {
  std::vector<Vertex> hull;
  for (const int i : convex_hull_indices(points))
    hull.push_back(points[static_cast<std::size_t>(i)]);
  return hull;
}

std::string number(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", x);
  return text;
}

}  // namespace

std::vector<int> convex_hull_indices(const std::vector<Vertex>& points) {
  std::vector<int> order(points.size());
  std::iota(order.begin(), order.end(), 0);
  const auto at = [&](int i) -> const Vertex& { return points[static_cast<std::size_t>(i)]; };
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    return at(a)[1] < at(b)[1] || (at(a)[1] == at(b)[1] && at(a)[0] < at(b)[0]);
  });
  std::vector<int> hull;
  const auto add = [&](int p, std::size_t floor) {
    while (hull.size() >= floor + 2 &&
           orientation(at(hull[hull.size() - 2]), at(hull.back()), at(p)) <= 0) {
      hull.pop_back();
    }
    hull.push_back(p);
  };
  for (const int p : order) add(p, 0);  // right side, going up
  const std::size_t right_chain = hull.size() - 1;
  for (auto it = order.rbegin() + 1; it != order.rend(); ++it) add(*it, right_chain);
  hull.pop_back();  // the first point again
  return hull;
}

std::optional<PolygonDefect> polygon_defect(const std::vector<Vertex>& v) {
  const std::size_t n = v.size();
  if (n < 3) return PolygonDefect{-1, "needs at least 3 vertices (got " + std::to_string(n) + ")"};
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(v[i][0]) || !std::isfinite(v[i][1])) {
      return PolygonDefect{static_cast<int>(i), "coordinates must be finite"};
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (orientation(v[(i + n - 1) % n], v[i], v[next(i, n)]) == 0) {
      return PolygonDefect{static_cast<int>(i),
                           "makes a straight corner or repeats a vertex: leave it out"};
    }
  }
  if (const auto meeting = first_meeting_edges(v)) {
    return PolygonDefect{-1, "crosses itself (the edges from vertices " +
                                 std::to_string(meeting->first) + " and " +
                                 std::to_string(meeting->second) + " meet)"};
  }
  if (twice_area(v) < 0) {
    return PolygonDefect{-1, "is clockwise: list the vertices counter-clockwise"};
  }
  const std::size_t left = base_left(v);
  const std::size_t right = next(left, n);
  const auto at_lowest =
      std::count_if(v.begin(), v.end(), [&](const Vertex& p) { return p[1] == v[left][1]; });
  if (v[right][1] != v[left][1] || at_lowest != 2) {
    return PolygonDefect{static_cast<int>(left),
                         "is at the lowest y with " + std::to_string(at_lowest - 1) +
                             " other vertices: the block rests on one horizontal base edge, so "
                             "exactly two neighbouring vertices must share the lowest y"};
  }
  const PolygonProperties p = polygon_properties(v);
  if (!(p.centroid[0] > v[left][0] && p.centroid[0] < v[right][0])) {
    return PolygonDefect{-1, "has its centre of mass (x = " + number(p.centroid[0]) +
                                 ") outside the base (x from " + number(v[left][0]) + " to " +
                                 number(v[right][0]) + "): it cannot rest on its base"};
  }
  return std::nullopt;
}

PolygonProperties polygon_properties(const std::vector<Vertex>& vertices) {
  const std::size_t n = vertices.size();
  // Every sum runs from the base's left end, so the result does not depend on where the list
  // starts. Coordinates are relative to the vertices' mean (the centroid of a symmetric block: the
  // corrections below then cancel exactly, and a rectangle's corners come out as exactly
  // (+-a, +-b), as BlockGeometry's rectangle has them).
  const std::size_t left = base_left(vertices);
  std::vector<Vertex> d(n);
  double mx = 0.0, my = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    d[i] = vertices[(left + i) % n];
    mx += d[i][0];
    my += d[i][1];
  }
  mx /= static_cast<double>(n);
  my /= static_cast<double>(n);
  for (Vertex& p : d) p = {p[0] - mx, p[1] - my};
  const double area2 = twice_area(d);
  double sx = 0.0, sy = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vertex& a = d[i];
    const Vertex& b = d[next(i, n)];
    const double c = cross(a[0], a[1], b[0], b[1]);
    sx += (a[0] + b[0]) * c;
    sy += (a[1] + b[1]) * c;
  }
  const double cx = sx / (3.0 * area2), cy = sy / (3.0 * area2);

  PolygonProperties out;
  out.area = 0.5 * area2;
  out.centroid = {mx + cx, my + cy};
  std::vector<Vertex> centred(n);
  for (std::size_t i = 0; i < n; ++i) centred[i] = {d[i][0] - cx, d[i][1] - cy};
  // J = (1/12) sum c_i (x_i^2 + x_i x_j + x_j^2 + y_i^2 + y_i y_j + y_j^2), j = i + 1, about the
  // centroid; I/M = J / A = sum / (6 * 2A).
  double j_sum = 0.0, centred_area2 = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vertex& a = centred[i];
    const Vertex& b = centred[next(i, n)];
    const double c = cross(a[0], a[1], b[0], b[1]);
    centred_area2 += c;
    j_sum +=
        c * (a[0] * a[0] + a[0] * b[0] + b[0] * b[0] + a[1] * a[1] + a[1] * b[1] + b[1] * b[1]);
  }
  out.inertia_per_mass = j_sum / (6.0 * centred_area2);
  // The hull starts at its lowest-then-leftmost point: the base's left end.
  out.hull = convex_hull(centred);
  return out;
}

}  // namespace blockfrag
