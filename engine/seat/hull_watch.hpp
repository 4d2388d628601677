// Which block vertices a seat's system watches for touching while block vertices on one straight
// line carry the block (a one-segment seat's). A line touches a convex polygon first at its convex
// hull, and the heights over a line of a convex polygon's vertices, taken around it, rise from
// its lowest to its highest and fall back: while the carrying vertices (one hull vertex, or two
// neighbouring ones) are on the line and the hull vertices next to them are above it, every other
// vertex is above it too. Only those neighbours can touch first; the others need no guard.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "engine/scene/block_geometry.hpp"
#include "engine/scene/polygon_properties.hpp"
#include "engine/seat/seat_contacts.hpp"
#include "engine/seat/seat_system.hpp"
#include "engine/seat/watched_list.hpp"
#include "engine/tolerances.hpp"

namespace blockfrag {

class HullWatch {
 public:
  // Without a block: watches every vertex (a seat of more segments, which never asks).
  HullWatch() = default;
  // `body`: the block's vertices, counter-clockwise, in any frame.
  explicit HullWatch(std::span<const Vec2> body)
      : body_(body.begin(), body.end()), hull_(hull_indices(body_)), place_(body_.size(), -1) {
    for (std::size_t k = 0; k < hull_.size(); ++k) {
      place_[static_cast<std::size_t>(hull_[k])] = static_cast<int>(k);
    }
  }

  // The vertices to watch, ascending, while the vertices `carrying` are on the line: the hull
  // neighbours of their chain, and every other vertex nearly on a line from the chain's ends to
  // those neighbours or along the chain (see kHullEdgeSine). None where `carrying` is not one hull
  // vertex or two neighbouring ones: then every vertex not carrying is watched.
  std::optional<WatchedList> watched(std::span<const int> carrying) const;

  // The hull's vertices, counter-clockwise, without vertices on its edges.
  const std::vector<int>& hull() const { return hull_; }

 private:
  // convex_hull_indices of the vertices.
  static std::vector<int> hull_indices(const std::vector<Vec2>& v);
  // Whether vertex v lies within kHullEdgeSine of the line from vertex `from` through `to`.
  bool near_line(int v, int from, int to) const;

  std::vector<Vec2> body_;
  std::vector<int> hull_;
  std::vector<int> place_;  // each vertex's place in hull_, -1 off it
};

inline std::vector<int> HullWatch::hull_indices(const std::vector<Vec2>& v) {
  std::vector<Vertex> points;
  for (const Vec2& p : v) points.push_back({p.x, p.y});
  return convex_hull_indices(points);
}

inline bool HullWatch::near_line(int v, int from, int to) const {
  const auto from_start = [&](int i) {
    const Vec2 p = body_[static_cast<std::size_t>(i)], o = body_[static_cast<std::size_t>(from)];
    return Vec2{p.x - o.x, p.y - o.y};
  };
  const Vec2 a = from_start(v), b = from_start(to);
  return std::abs(cross(a.x, a.y, b.x, b.y)) <=
         kHullEdgeSine * std::hypot(a.x, a.y) * std::hypot(b.x, b.y);
}

inline std::optional<WatchedList> HullWatch::watched(std::span<const int> carrying) const {
  if (hull_.empty() || carrying.empty() || carrying.size() > 2) return std::nullopt;
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

// The block's vertices from its centre of mass, body frame.
inline std::vector<Vec2> body_vertices(const SeatContacts& contacts) {
  std::vector<Vec2> body;
  for (int i = 0; i < contacts.vertex_count(); ++i) body.push_back(contacts.body_vertex(i));
  return body;
}

// The block vertices a seat's system with the contacts `active` watches for touching: on a
// one-segment seat carried by block vertices alone, those `hull` (the block's) watches; else every
// vertex not in an active contact.
inline WatchedList watched_block_vertices(const SeatContacts& contacts, const HullWatch& hull,
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
