#include "engine/scene/seat.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <limits>

#include <Eigen/Dense>

#include "engine/errors.hpp"
#include "engine/number_text.hpp"
#include "engine/scene/block_geometry.hpp"
#include "engine/tolerances.hpp"

namespace blockfrag {

namespace {

struct Point {
  double x, y;
};

Point at(const Vertex& v) { return {v[0], v[1]}; }
double cross(Point a, Point b) { return a.x * b.y - a.y * b.x; }
Point minus(Point a, Point b) { return {a.x - b.x, a.y - b.y}; }
double norm(Point a) { return std::hypot(a.x, a.y); }

// Signed distance of p from the line through a and b, > 0 on its left.
double side(Point a, Point b, Point p) {
  return cross(minus(b, a), minus(p, a)) / norm(minus(b, a));
}

double distance_to_segment(Point a, Point b, Point p) {
  const Point d = minus(b, a), ap = minus(p, a);
  const double t = std::clamp((d.x * ap.x + d.y * ap.y) / (d.x * d.x + d.y * d.y), 0.0, 1.0);
  return norm(minus(p, Point{a.x + t * d.x, a.y + t * d.y}));
}

// Left of the segment's direction: up for a seat segment (x increasing), inward for a
// counter-clockwise block's edge.
Vertex left_normal(Point a, Point b) {
  const Point d = minus(b, a);
  const double length = norm(d);
  return {-d.y / length, d.x / length};
}

bool inside(const std::vector<Vertex>& polygon, Point p) {
  bool in = false;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const Point a = at(polygon[i]), b = at(polygon[j]);
    if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y)) in = !in;
  }
  return in;
}

double distance_to_boundary(const std::vector<Vertex>& polygon, Point p) {
  double d = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    d = std::min(d, distance_to_segment(at(polygon[i]), at(polygon[(i + 1) % polygon.size()]), p));
  }
  return d;
}

// The seat's height at x, for x within its ends.
double seat_height(const std::vector<Vertex>& seat, double x) {
  const auto right = std::upper_bound(seat.begin() + 1, seat.end() - 1, x,
                                      [](double value, const Vertex& v) { return value < v[0]; });
  const Vertex& b = *right;
  const Vertex& a = *std::prev(right);
  return a[1] + (b[1] - a[1]) * ((x - a[0]) / (b[0] - a[0]));
}

// Whether non-negative pushes along the contacts' normals balance the weight (force and moment
// about the centroid). Contacts with one normal generate a segment of wrenches (the moment is
// linear in the position along the normal's line), so only its two extremes are kept; a solution
// exists, if any does, on at most three of them (Caratheodory), so the subsets of up to three are
// tried.
bool weight_carried(const std::vector<RestContact>& contacts, Point centroid, double length) {
  struct Column {
    Vertex normal;
    double moment;
  };
  struct Group {
    Vertex normal;
    double low, high;  // the moments of its contacts about the centroid, over length
  };
  std::vector<Group> groups;
  for (const RestContact& c : contacts) {
    const double moment = cross(minus(at(c.point), centroid), at(c.normal)) / length;
    const auto same = std::find_if(groups.begin(), groups.end(), [&](const Group& g) {
      return std::abs(g.normal[0] - c.normal[0]) + std::abs(g.normal[1] - c.normal[1]) <=
             kSameSeatNormal;
    });
    if (same == groups.end()) {
      groups.push_back({c.normal, moment, moment});
    } else {
      same->low = std::min(same->low, moment);
      same->high = std::max(same->high, moment);
    }
  }
  std::vector<Column> extremes;
  for (const Group& g : groups) {
    extremes.push_back({g.normal, g.low});
    if (g.high != g.low) extremes.push_back({g.normal, g.high});
  }
  const std::size_t n = extremes.size();
  const Eigen::Vector3d weight(0.0, 1.0, 0.0);
  const auto fits = [&](const std::vector<std::size_t>& chosen) {
    Eigen::MatrixXd a(3, static_cast<Eigen::Index>(chosen.size()));
    for (std::size_t k = 0; k < chosen.size(); ++k) {
      const Column& c = extremes[chosen[k]];
      a.col(static_cast<Eigen::Index>(k)) << c.normal[0], c.normal[1], c.moment;
    }
    const Eigen::VectorXd push = a.colPivHouseholderQr().solve(weight);
    return push.minCoeff() >= -kCarriedWeightResidual &&
           (a * push - weight).norm() <= kCarriedWeightResidual;
  };
  for (std::size_t i = 0; i < n; ++i) {
    if (fits({i})) return true;
    for (std::size_t j = i + 1; j < n; ++j) {
      if (fits({i, j})) return true;
      for (std::size_t k = j + 1; k < n; ++k) {
        if (fits({i, j, k})) return true;
      }
    }
  }
  return false;
}

// The block where it is enters the seat: a vertex below it, a seat point inside the block, or a
// block edge crossing a seat segment.
std::optional<SeatDefect> overlap_defect(const std::vector<Vertex>& seat,
                                         const std::vector<Vertex>& block, double tolerance) {
  for (std::size_t j = 0; j < block.size(); ++j) {
    const double x = block[j][0];
    if (x < seat.front()[0] || x > seat.back()[0]) continue;
    const double below = seat_height(seat, x) - block[j][1];
    if (below > tolerance) {
      return SeatDefect{-1, "block vertex " + std::to_string(j) + " lies " + format_number(below) +
                                " m below the seat"};
    }
  }
  for (std::size_t i = 0; i < seat.size(); ++i) {
    const Point p = at(seat[i]);
    if (inside(block, p) && distance_to_boundary(block, p) > tolerance) {
      return SeatDefect{static_cast<int>(i), "lies inside the block"};
    }
  }
  for (std::size_t i = 0; i + 1 < seat.size(); ++i) {
    const Point a = at(seat[i]), b = at(seat[i + 1]);
    for (std::size_t j = 0; j < block.size(); ++j) {
      const Point c = at(block[j]), d = at(block[(j + 1) % block.size()]);
      const double c_side = side(a, b, c), d_side = side(a, b, d);
      const double a_side = side(c, d, a), b_side = side(c, d, b);
      const bool crosses_seat = (c_side > tolerance && d_side < -tolerance) ||
                                (c_side < -tolerance && d_side > tolerance);
      const bool crosses_edge = (a_side > tolerance && b_side < -tolerance) ||
                                (a_side < -tolerance && b_side > tolerance);
      if (crosses_seat && crosses_edge) {
        return SeatDefect{static_cast<int>(i), "the segment to the next point crosses block edge " +
                                                   std::to_string(j) +
                                                   " (the block is in the seat)"};
      }
    }
  }
  return std::nullopt;
}

}  // namespace

std::vector<RestContact> rest_contacts(const std::vector<Vertex>& seat,
                                       const std::vector<Vertex>& block, double tolerance) {
  std::vector<RestContact> contacts;
  for (std::size_t s = 0; s + 1 < seat.size(); ++s) {
    const Point a = at(seat[s]), b = at(seat[s + 1]);
    for (const Vertex& v : block) {
      if (distance_to_segment(a, b, at(v)) <= tolerance) contacts.push_back({v, left_normal(a, b)});
    }
  }
  for (const Vertex& p : seat) {
    for (std::size_t i = 0; i < block.size(); ++i) {
      const Point a = at(block[i]), b = at(block[(i + 1) % block.size()]);
      if (distance_to_segment(a, b, at(p)) <= tolerance) contacts.push_back({p, left_normal(a, b)});
    }
  }
  return contacts;
}

namespace {

struct OutermostContacts {
  Vertex left, right;
};

// The leftmost and the rightmost point where the block resting on its seat touches it. A block
// that does not touch its seat has none: that scene breaks the seat's rule (seat_defect), and is
// refused as validate_scene refuses it.
OutermostContacts outermost_contacts(const std::vector<Vertex>& seat,
                                     const std::vector<Vertex>& block, double tolerance) {
  const std::vector<RestContact> contacts = rest_contacts(seat, block, tolerance);
  if (contacts.empty()) {
    throw InvalidInput("invalid scene: seat: does not touch the block (the block must rest on it)");
  }
  const auto by_x = [](const RestContact& a, const RestContact& b) {
    return a.point[0] < b.point[0];
  };
  return {std::min_element(contacts.begin(), contacts.end(), by_x)->point,
          std::max_element(contacts.begin(), contacts.end(), by_x)->point};
}

}  // namespace

double seat_alpha(const std::vector<Vertex>& seat, const std::vector<Vertex>& block,
                  double tolerance) {
  const Point centre = at(polygon_properties(block).centroid);
  const OutermostContacts outermost = outermost_contacts(seat, block, tolerance);
  const Point left = at(outermost.left), right = at(outermost.right);
  return std::min(std::atan2(centre.x - left.x, centre.y - left.y),
                  std::atan2(right.x - centre.x, centre.y - right.y));
}

std::optional<SeatDefect> seat_defect(const std::vector<Vertex>& seat,
                                      const std::vector<Vertex>& block, double tolerance) {
  if (seat.size() < 2) {
    return SeatDefect{-1, "needs at least 2 points (got " + std::to_string(seat.size()) + ")"};
  }
  for (std::size_t i = 0; i < seat.size(); ++i) {
    if (!std::isfinite(seat[i][0]) || !std::isfinite(seat[i][1])) {
      return SeatDefect{static_cast<int>(i), "coordinates must be finite"};
    }
    if (i > 0 && !(seat[i][0] > seat[i - 1][0])) {
      return SeatDefect{static_cast<int>(i),
                        "x must be greater than the previous point's (the seat runs left to "
                        "right, a height over x)"};
    }
  }
  if (auto defect = overlap_defect(seat, block, tolerance)) return defect;
  const std::vector<RestContact> contacts = rest_contacts(seat, block, tolerance);
  if (contacts.empty())
    return SeatDefect{-1, "does not touch the block (the block must rest on it)"};
  const PolygonProperties properties = polygon_properties(block);
  double length = 0.0;
  for (const Vertex& v : block) {
    length =
        std::max(length, std::hypot(v[0] - properties.centroid[0], v[1] - properties.centroid[1]));
  }
  if (!weight_carried(contacts, at(properties.centroid), length)) {
    return SeatDefect{
        -1,
        "does not carry the block at rest: no pushes along the seat's normals where "
        "they touch balance its weight (the centre of mass must lie over its support)"};
  }
  return std::nullopt;
}

SeatTilt tilt_on_seat(const std::vector<Vertex>& seat, const std::vector<Vertex>& block,
                      double theta, double tolerance, double turning) {
  const OutermostContacts outermost = outermost_contacts(seat, block, tolerance);
  const Vertex pivot =
      release_pivot(theta, turning) == Corner::left ? outermost.left : outermost.right;
  const double c = std::cos(theta), s = std::sin(theta);
  const auto turned = [&](const Vertex& v) {
    const double dx = v[0] - pivot[0], dy = v[1] - pivot[1];
    return Vertex{pivot[0] + c * dx - s * dy, pivot[1] + s * dx + c * dy};
  };
  SeatTilt tilt{pivot, {}, turned(polygon_properties(block).centroid)};
  for (const Vertex& v : block) tilt.vertices.push_back(turned(v));
  return tilt;
}

std::optional<std::string> tilt_defect(const std::vector<Vertex>& seat,
                                       const std::vector<Vertex>& block, double theta,
                                       double tolerance) {
  const auto defect =
      overlap_defect(seat, tilt_on_seat(seat, block, theta, tolerance).vertices, tolerance);
  if (!defect) return std::nullopt;
  const std::string where =
      defect->point < 0 ? "" : "seat point " + std::to_string(defect->point) + ": ";
  return "the block released tilted by it would enter the seat: " + where + defect->rule;
}

std::vector<Vertex> scene_block_vertices(const Scene& scene) {
  if (scene.polygon) return scene.polygon->vertices;
  const double a = scene.block.half_width, b = scene.block.half_height;
  return {{-a, -b}, {a, -b}, {a, b}, {-a, b}};
}

double lowest_block_y(const Scene& scene) {
  if (!scene.polygon) return -scene.block.half_height;
  double lowest = std::numeric_limits<double>::infinity();
  for (const Vertex& v : scene.polygon->vertices) lowest = std::min(lowest, v[1]);
  return lowest;
}

}  // namespace blockfrag
