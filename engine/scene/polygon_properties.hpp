// A polygon block's mass properties (shoelace formulas, uniform density), the corners that can
// touch a flat ground (its convex hull), and the rules a polygon block must keep: what
// BlockGeometry needs to treat a polygon like the rectangle.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace blockfrag {

using Vertex = std::array<double, 2>;  // (x, y), m

inline double cross(double ax, double ay, double bx, double by) { return ax * by - ay * bx; }

// > 0 when c lies left of the line from a to b.
inline double orientation(const Vertex& a, const Vertex& b, const Vertex& c) {
  return cross(b[0] - a[0], b[1] - a[1], c[0] - a[0], c[1] - a[1]);
}

// Why a vertex list cannot be a block resting on its base; `vertex` is the index of the offending
// vertex when one can be named, else -1 (the list as a whole).
struct PolygonDefect {
  int vertex;
  std::string rule;
};

// At least 3 finite vertices, counter-clockwise, a simple polygon (no edge crosses or touches
// another, no straight corner or repeated vertex), a unique lowest edge (exactly two vertices at
// the lowest y, one edge apart), and the centre of mass strictly above that edge (between its
// ends), so the block can rest on it. Reflex corners are allowed (the paper's type A dam block has
// one where its downstream slope starts): a flat ground touches only the convex hull.
std::optional<PolygonDefect> polygon_defect(const std::vector<Vertex>& vertices);

struct PolygonProperties {
  double area;      // m^2
  Vertex centroid;  // in the vertices' frame
  // Polar second moment of area about the centroid over the area: I/M for a uniform block.
  double inertia_per_mass;
  // The convex hull's vertices relative to the centroid, counter-clockwise from the base's left
  // end (so its right end comes second): the corners that can touch the ground. For a convex
  // polygon, all its vertices.
  std::vector<Vertex> hull;
};

// The indices of the convex hull's vertices (Andrew's monotone chain), without points on its
// edges: counter-clockwise, from the lowest-then-leftmost point.
std::vector<int> convex_hull_indices(const std::vector<Vertex>& points);

// For a polygon without defects; the vertex list may start at any vertex.
PolygonProperties polygon_properties(const std::vector<Vertex>& vertices);

}  // namespace blockfrag
