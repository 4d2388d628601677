#include "engine/scene/polygon_simplicity.hpp"

#include <algorithm>
#include <cstddef>
#include <iterator>
#include <limits>
#include <set>

namespace blockfrag {

namespace {

// An edge from its left end to its right end (lower end first when vertical).
struct Edge {
  Vertex left, right;
  std::size_t index;  // the edge from vertex index to vertex index + 1

  // y where the sweep line at x meets the edge; a vertical edge is met at its lower end.
  double y_at(double x) const {
    if (x <= left[0]) return left[1];
    if (x >= right[0]) return right[1];
    return left[1] + (right[1] - left[1]) * ((x - left[0]) / (right[0] - left[0]));
  }
  // Its slope, +infinity for a vertical edge: of two edges meeting the sweep at one point, the
  // steeper one lies above just after it.
  double slope() const {
    const double dx = right[0] - left[0];
    return dx == 0 ? std::numeric_limits<double>::infinity() : (right[1] - left[1]) / dx;
  }
};

struct Event {
  double x, y;
  bool insert;  // inserts come before removals at the same point, so touching edges meet
  std::size_t edge;
};

// The polygon's edges (into `edges`, n of them) and their ends as the sweep meets them.
std::vector<Event> sorted_sweep_events(const std::vector<Vertex>& v, std::vector<Edge>& edges) {
  const std::size_t n = v.size();
  std::vector<Event> events;
  events.reserve(2 * n);
  for (std::size_t i = 0; i < n; ++i) {
    Vertex a = v[i], b = v[(i + 1) % n];
    if (b[0] < a[0] || (b[0] == a[0] && b[1] < a[1])) std::swap(a, b);
    edges[i] = {a, b, i};
    events.push_back({a[0], a[1], true, i});
    events.push_back({b[0], b[1], false, i});
  }
  std::sort(events.begin(), events.end(), [](const Event& a, const Event& b) {
    if (a.x != b.x) return a.x < b.x;
    if (a.insert != b.insert) return a.insert;
    return a.y < b.y;
  });
  return events;
}

}  // namespace

bool segments_meet(const Vertex& p, const Vertex& q, const Vertex& r, const Vertex& s) {
  const double d1 = orientation(r, s, p), d2 = orientation(r, s, q);
  const double d3 = orientation(p, q, r), d4 = orientation(p, q, s);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) {
    return true;
  }
  const auto within = [](const Vertex& a, const Vertex& b, const Vertex& c) {  // c on segment ab
    return std::min(a[0], b[0]) <= c[0] && c[0] <= std::max(a[0], b[0]) &&
           std::min(a[1], b[1]) <= c[1] && c[1] <= std::max(a[1], b[1]);
  };
  return (d1 == 0 && within(r, s, p)) || (d2 == 0 && within(r, s, q)) ||
         (d3 == 0 && within(p, q, r)) || (d4 == 0 && within(p, q, s));
}

std::optional<std::pair<std::size_t, std::size_t>> first_meeting_edges(
    const std::vector<Vertex>& v) {
  const std::size_t n = v.size();
  std::vector<Edge> edges(n);
  const std::vector<Event> events = sorted_sweep_events(v, edges);

  // The sweep's order of the edges it crosses, from below: valid for as long as no two of them
  // have met, which is all the search needs (Shamos & Hoey 1976: the first meeting pair is
  // neighbours in this order at some event before or at their meeting point).
  double sweep_x = 0.0;
  const auto below = [&](std::size_t a, std::size_t b) {
    const double ya = edges[a].y_at(sweep_x), yb = edges[b].y_at(sweep_x);
    if (ya != yb) return ya < yb;
    const double sa = edges[a].slope(), sb = edges[b].slope();
    if (sa != sb) return sa < sb;
    return a < b;
  };
  std::set<std::size_t, decltype(below)> crossed(below);
  std::vector<std::set<std::size_t, decltype(below)>::iterator> where(n, crossed.end());

  // Neighbouring edges of the polygon share a vertex: that is not a meeting.
  const auto adjacent = [n](std::size_t a, std::size_t b) {
    return (a + 1) % n == b || (b + 1) % n == a;
  };
  const auto meet = [&](std::size_t a, std::size_t b) {
    return !adjacent(a, b) && segments_meet(v[a], v[(a + 1) % n], v[b], v[(b + 1) % n]);
  };
  const auto found = [](std::size_t a, std::size_t b) {
    return std::optional<std::pair<std::size_t, std::size_t>>(std::minmax(a, b));
  };

  for (const Event& event : events) {
    sweep_x = event.x;
    if (event.insert) {
      const auto it = crossed.insert(event.edge).first;
      where[event.edge] = it;
      if (const auto above = std::next(it); above != crossed.end() && meet(*above, event.edge)) {
        return found(*above, event.edge);
      }
      if (it != crossed.begin() && meet(*std::prev(it), event.edge)) {
        return found(*std::prev(it), event.edge);
      }
    } else {
      const auto it = where[event.edge];
      const auto above = std::next(it);
      if (it != crossed.begin() && above != crossed.end() && meet(*std::prev(it), *above)) {
        return found(*std::prev(it), *above);
      }
      crossed.erase(it);
    }
  }
  return std::nullopt;
}

}  // namespace blockfrag
