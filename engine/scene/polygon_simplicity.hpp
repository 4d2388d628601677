// Whether a polygon's edges meet anywhere but at the vertices neighbouring edges share: a sweep
// line over the edges (Shamos & Hoey), O(n log n), so a digitised outline of thousands of
// vertices is checked in milliseconds rather than the seconds all pairs would take.
#pragma once

#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

#include "engine/scene/polygon_properties.hpp"

namespace blockfrag {

// Closed segments pq and rs share a point (a proper crossing, a touch or an overlap).
bool segments_meet(const Vertex& p, const Vertex& q, const Vertex& r, const Vertex& s);

// A pair of edges that meet (edge i runs from vertex i to vertex i + 1), lower index first; none
// for a simple polygon. Assumes neighbouring edges share only their common vertex (no straight
// or folded corner, no repeated vertex).
std::optional<std::pair<std::size_t, std::size_t>> first_meeting_edges(
    const std::vector<Vertex>& vertices);

}  // namespace blockfrag
