#include "engine/seat/hull_watch.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <numeric>

#include "engine/tolerances.hpp"

namespace blockfrag {

namespace {

double hull_cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }
Vec2 hull_minus(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }

// Andrew's monotone chain over the vertices' indices, without points on the hull's edges:
// counter-clockwise, from the lowest-then-leftmost vertex.
std::vector<int> hull_indices(const std::vector<Vec2>& v) {
  std::vector<int> order(v.size());
  std::iota(order.begin(), order.end(), 0);
  const auto at = [&](int i) { return v[static_cast<std::size_t>(i)]; };
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    return at(a).y < at(b).y || (at(a).y == at(b).y && at(a).x < at(b).x);
  });
  std::vector<int> hull;
  const auto add = [&](int p, std::size_t floor) {
    while (hull.size() >= floor + 2 &&
           hull_cross(hull_minus(at(hull.back()), at(hull[hull.size() - 2])),
                      hull_minus(at(p), at(hull[hull.size() - 2]))) <= 0) {
      hull.pop_back();
    }
    hull.push_back(p);
  };
  for (const int p : order) add(p, 0);
  const std::size_t right_chain = hull.size() - 1;
  for (auto it = order.rbegin() + 1; it != order.rend(); ++it) add(*it, right_chain);
  hull.pop_back();
  return hull;
}

}  // namespace

HullWatch::HullWatch(std::span<const Vec2> body)
    : body_(body.begin(), body.end()), hull_(hull_indices(body_)), place_(body_.size(), -1) {
  for (std::size_t k = 0; k < hull_.size(); ++k) {
    place_[static_cast<std::size_t>(hull_[k])] = static_cast<int>(k);
  }
}

bool HullWatch::near_line(int v, int from, int to) const {
  const Vec2 a =
      hull_minus(body_[static_cast<std::size_t>(v)], body_[static_cast<std::size_t>(from)]);
  const Vec2 b =
      hull_minus(body_[static_cast<std::size_t>(to)], body_[static_cast<std::size_t>(from)]);
  return std::abs(hull_cross(a, b)) <= kHullEdgeSine * std::hypot(a.x, a.y) * std::hypot(b.x, b.y);
}

std::optional<WatchedList> HullWatch::watched(std::span<const int> carrying) const {
  if (carrying.empty() || carrying.size() > 2) return std::nullopt;
  const auto n = static_cast<int>(hull_.size());
  const auto place = [&](int i) { return place_[static_cast<std::size_t>(i)]; };
  const auto hull_at = [&](int k) { return hull_[static_cast<std::size_t>((k + n) % n)]; };
  int first = carrying[0], last = carrying.back();
  if (place(first) < 0 || place(last) < 0) return std::nullopt;
  // Two carrying vertices are a chain where they are neighbours on the hull, `first` then `last`
  // counter-clockwise.
  if (first != last && hull_at(place(first) + 1) != last) std::swap(first, last);
  if (first != last && hull_at(place(first) + 1) != last) return std::nullopt;
  const int before = hull_at(place(first) - 1), after = hull_at(place(last) + 1);
  WatchedList out;
  for (int v = 0; v < static_cast<int>(body_.size()); ++v) {
    if (v == first || v == last) continue;
    // The neighbours lie on their own lines.
    if (near_line(v, first, before) || near_line(v, last, after) ||
        (first != last && near_line(v, first, last))) {
      out.push_back(v);
    }
  }
  return out;
}

std::vector<Vec2> body_vertices(const SeatContacts& contacts) {
  std::vector<Vec2> body;
  for (int i = 0; i < contacts.vertex_count(); ++i) body.push_back(contacts.body_vertex(i));
  return body;
}

WatchedList watched_block_vertices(const SeatContacts& contacts, const HullWatch& hull,
                                   std::span<const ActiveContact> active) {
  std::array<int, kMaxSeatContacts> carrying{};
  std::size_t count = 0;
  const bool on_one_line = contacts.point_count() == 2 && !active.empty() &&
                           std::all_of(active.begin(), active.end(), [&](const ActiveContact& a) {
                             return a.pair.kind == ContactKind::block_vertex;
                           });
  for (const ActiveContact& a : active) {
    if (a.pair.kind == ContactKind::block_vertex) carrying[count++] = a.pair.block;
  }
  const std::span<const int> carried = std::span(carrying).first(count);
  if (on_one_line) {
    if (const std::optional<WatchedList> near = hull.watched(carried)) return *near;
  }
  WatchedList vertices;
  for (int i = 0; i < contacts.vertex_count(); ++i) {
    if (std::find(carried.begin(), carried.end(), i) == carried.end()) vertices.push_back(i);
  }
  return vertices;
}

}  // namespace blockfrag
