// Which block vertices a seat's system watches for touching while block vertices on one straight
// line carry the block (a one-segment seat's). A line touches a convex polygon first at its convex
// hull, and the heights over a line of a convex polygon's vertices, taken around it, rise from
// its lowest to its highest and fall back: while the carrying vertices (one hull vertex, or two
// neighbouring ones) are on the line and the hull vertices next to them are above it, every other
// vertex is above it too. Only those neighbours can touch first; the others need no guard.
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "engine/scene/block_geometry.hpp"
#include "engine/seat/seat_contacts.hpp"
#include "engine/seat/seat_system.hpp"
#include "engine/seat/watched_list.hpp"

namespace blockfrag {

class HullWatch {
 public:
  // `body`: the block's vertices, counter-clockwise, in any frame.
  explicit HullWatch(std::span<const Vec2> body);

  // The vertices to watch, ascending, while the vertices `carrying` are on the line: the hull
  // neighbours of their chain, and every other vertex nearly on a line from the chain's ends to
  // those neighbours or along the chain (see kHullEdgeSine). None where `carrying` is not one hull
  // vertex or two neighbouring ones: then every vertex not carrying is watched.
  std::optional<WatchedList> watched(std::span<const int> carrying) const;

  // The hull's vertices, counter-clockwise, without vertices on its edges.
  const std::vector<int>& hull() const { return hull_; }

 private:
  // Whether vertex v lies within kHullEdgeSine of the line from vertex `from` through `to`.
  bool near_line(int v, int from, int to) const;

  std::vector<Vec2> body_;
  std::vector<int> hull_;
  std::vector<int> place_;  // each vertex's place in hull_, -1 off it
};

// The block's vertices from its centre of mass, body frame.
std::vector<Vec2> body_vertices(const SeatContacts& contacts);

// The block vertices a seat's system with the contacts `active` watches for touching: on a
// one-segment seat carried by block vertices alone, those `hull` (the block's) watches; else every
// vertex not in an active contact.
WatchedList watched_block_vertices(const SeatContacts& contacts, const HullWatch& hull,
                                   std::span<const ActiveContact> active);

}  // namespace blockfrag
