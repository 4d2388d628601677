#include "engine/seat/seat_contacts.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numbers>

#include "engine/sine_cosine.hpp"
#include "engine/tolerances.hpp"

namespace blockfrag {

namespace {

Vec2 minus(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
double dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }
double norm(Vec2 a) { return std::sqrt(a.x * a.x + a.y * a.y); }

// The segment from a to b: its unit direction, its left normal (up for a seat segment, inward
// for a counter-clockwise block's edge) and its length.
struct SegmentFrame {
  Vec2 direction, normal;
  double length;
};

SegmentFrame segment_frame(Vec2 a, Vec2 b) {
  const Vec2 d = minus(b, a);
  const double length = norm(d);
  const Vec2 u{d.x / length, d.y / length};
  return {u, {-u.y, u.x}, length};
}

// The squared distance from p to the edge from a to b: |ap - t d|^2, t the projection's place
// clamped to [0, 1].
double squared_distance_to_edge(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 d = minus(b, a), ap = minus(p, a);
  // Clamped as the quotient would be, without dividing where it is clamped (a point off the
  // edge's ends: a seat's far ends at every guard evaluation), nor taking 0 or 1 times d off ap,
  // which leaves ap or ap - d to the bit (most edges, at every evaluation of a seat point's guard).
  const double along = dot(d, ap), squared_length = dot(d, d);
  if (along <= 0.0) return dot(ap, ap);
  const double t = along >= squared_length ? 1.0 : along / squared_length;
  const Vec2 off = t == 1.0 ? minus(ap, d) : minus(ap, Vec2{t * d.x, t * d.y});
  return dot(off, off);
}

// Whether the edge from a to b, one end above p's level and the other not, crosses that level right
// of p: the even-odd rule's count of p inside a polygon. Which ends are above is found once a
// vertex by the passes over the block's edges (each vertex ends two edges).
bool crossed_right_of(Vec2 p, Vec2 a, Vec2 b) {
  // The edge's x at the point's level lies between a.x and b.x but for a few ulps of them: a
  // point beside both by more is left or right of it without the division (a seat's far ends at
  // every guard evaluation).
  const double rounding = kGeometryRounding * (std::abs(a.x) + std::abs(b.x));
  if (p.x < std::min(a.x, b.x) - rounding) return true;
  if (p.x > std::max(a.x, b.x) + rounding) return false;
  return p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y);
}

// A lower bound on sqrt(squared_distance_to_edge(p, a, b)) as computed, for an edge with both ends
// above p's level y (above) or both not: N - kGeometryRounding F, N and F the computed heights of
// its nearer and farther ends from that level. Used only where over kSmallestGap.
//
// Why rounding cannot put the edge's value under it, u = 2^-53, G <= H the exact heights: for any
// t in [0, 1] the point a + t (b - a) lies between the ends' levels, so the exact ap - t d has a y
// of size at least G. Each branch of squared_distance_to_edge rounds ap.y, d.y (both at most H in
// size, the ends being on one side), t d.y and their difference, fused or not: its off.y is within
// 3.01 u H of that y before its own rounding, so |off.y| >= (1 - u)(G - 3.01 u H). The squared
// distance, fl(off.y^2) plus a term >= 0, rounded, is at least (1 - u) off.y^2, so its root is at
// least N - 5.52 u F (N >= G within u G, F within u H). The bound's product, subtraction and
// square add at most 1.51 u N <= 1.51 u F: its square at or above a squared distance D puts
// sqrt(D) at most N - (kGeometryRounding - 1.6 u) F, below this edge's root as kGeometryRounding
// >= 8 u; min() then keeps D. Gaps over kSmallestGap keep every square clear of underflow.
double level_gap(double y, double a_y, double b_y, bool above) {
  const double low = std::min(a_y, b_y), high = std::max(a_y, b_y);
  const double nearer = above ? low - y : y - high, farther = above ? high - y : y - low;
  return nearer - kGeometryRounding * farther;
}

// Gaps at most this small are not pruned (see level_gap).
constexpr double kSmallestGap = 1e-100;

// Seats with at most this many points between their ends find a place's segment by a scan.
constexpr std::ptrdiff_t kScannedSeatPoints = 4;

}  // namespace

SeatContacts::SeatContacts(const std::vector<Vertex>& block, const std::vector<Vertex>& seat) {
  const Vertex c = polygon_properties(block).centroid;
  centre_ = {c[0], c[1]};
  for (const Vertex& v : block) body_.push_back({v[0] - c[0], v[1] - c[1]});
  for (const Vertex& p : seat) seat_.push_back({p[0], p[1]});
  for (std::size_t k = 0; k + 1 < seat_.size(); ++k) {
    const SegmentFrame frame = segment_frame(seat_[k], seat_[k + 1]);
    segments_.push_back({frame.direction, frame.normal, frame.length});
  }
  double size = 0.0;
  for (const Vec2& r : body_) size = std::max(size, norm(r));
  block_radius_ = size;
  straight_ = straight(kContactHeight * size);
  end_depth_ = kContactHeight * size;
  const auto [low, high] = std::minmax_element(
      seat_.begin(), seat_.end(), [](const Vec2& a, const Vec2& b) { return a.y < b.y; });
  over_top_ = high->y + kGeometryRounding * (std::abs(high->y) + std::abs(low->y));
  // A seat point between two collinear segments cannot touch a block edge without a vertex of
  // that edge on the seat's line, where that vertex's own contact carries the block. Taken as a
  // contact, the joint under a block rocking down onto its far corner would touch (its gap within
  // the contact height) while that corner is still up, and lay the block flat too early.
  for (std::size_t k = 0; k < seat_.size(); ++k) {
    bool bends = k == 0 || k + 1 == seat_.size();
    if (!bends) {
      const SegmentFrame chord = segment_frame(seat_[k - 1], seat_[k + 1]);
      bends = std::abs(dot(chord.normal, minus(seat_[k], seat_[k - 1]))) > kContactHeight * size;
    }
    point_touches_edges_.push_back(bends);
  }
  for (std::size_t k = 0; k + 1 < seat_.size(); ++k) {
    std::size_t start = k, end = k + 1;
    while (!point_touches_edges_[start]) --start;
    while (!point_touches_edges_[end]) ++end;
    run_start_.push_back(static_cast<int>(start));
    run_end_.push_back(static_cast<int>(end));
  }
  if (seat_.size() == 2 && seat_[1].x > seat_[0].x) {
    const Vec2 a = seat_[0], b = seat_[1];
    single_ = {a.x, a.y, b.x, b.y - a.y, b.x - a.x};
  }
  if (seat_.size() == 3 && seat_[1].x > seat_[0].x && seat_[2].x > seat_[1].x) {
    for (std::size_t k = 0; k < 2; ++k) {
      const Vec2 a = seat_[k], b = seat_[k + 1];
      folded_[k] = {a.x, a.y, b.x, b.y - a.y, b.x - a.x};
    }
  }
}

bool SeatContacts::straight(double tolerance) const {
  const SegmentFrame whole = segment_frame(seat_.front(), seat_.back());
  return std::all_of(seat_.begin(), seat_.end(), [&](const Vec2& p) {
    return std::abs(dot(whole.normal, minus(p, seat_.front()))) <= tolerance;
  });
}

std::optional<double> SeatContacts::level() const {
  const double y = seat_.front().y;
  const bool level = std::all_of(seat_.begin(), seat_.end(), [&](const Vec2& p) {
    return std::bit_cast<std::uint64_t>(p.y) == std::bit_cast<std::uint64_t>(y);
  });
  if (!level) return std::nullopt;
  return y;
}

double SeatContacts::overturn_margin(const BlockGeometry& geometry, double theta) const {
  if (straight_) return geometry.overturn_margin(theta);
  return std::numbers::pi / 2 - std::abs(theta);
}

double SeatContacts::overturn_theta(const BlockGeometry& geometry, double direction) const {
  if (straight_) return geometry.overturn_theta(direction);
  return direction > 0 ? std::numbers::pi / 2 : -std::numbers::pi / 2;
}

// The segment's frame as the constructor found it (segment_frame): a chart is asked for at each
// motion piece, and finding the frame anew, a square root and two quotients, was most of a line.
SeatLine SeatContacts::segment_line(int k) const {
  const Vec2 a = seat_[static_cast<std::size_t>(k)];
  const Segment& segment = segments_[static_cast<std::size_t>(k)];
  return {segment.direction, segment.normal, dot(segment.normal, a)};
}

SeatContacts::RunPlace SeatContacts::place_on_run(int k, Vec2 p) const {
  const auto at = static_cast<std::size_t>(k);
  const Vec2 start = seat_[static_cast<std::size_t>(run_start_[at])];
  const SegmentFrame run = segment_frame(start, seat_[static_cast<std::size_t>(run_end_[at])]);
  return {dot(run.direction, minus(p, start)), run.length};
}

Vec2 SeatContacts::vertex_at(int i, const BlockState& s) const {
  const SineCosine turn = cached_turn(s.theta);
  const Vec2 r = rotate(body_[static_cast<std::size_t>(i)], turn.cos, turn.sin);
  return {s.x + r.x, s.y + r.y};
}

PairPose SeatContacts::pose(const SeatPair& pair, const BlockState& s) const {
  if (pair.kind == ContactKind::block_vertex) return vertex_pose(pair, s, vertex_at(pair.block, s));
  return point_pose(pair, s, vertex_at(pair.block, s),
                    vertex_at((pair.block + 1) % vertex_count(), s));
}

PairPose SeatContacts::pose(const SeatPair& pair, const BlockState& s,
                            std::span<const Vec2> world) const {
  const auto block = static_cast<std::size_t>(pair.block);
  if (pair.kind == ContactKind::block_vertex) return vertex_pose(pair, s, world[block]);
  return point_pose(pair, s, world[block], world[(block + 1) % body_.size()]);
}

PairPose SeatContacts::vertex_pose(const SeatPair& pair, const BlockState& s, Vec2 p) const {
  const Vec2 a = seat_[static_cast<std::size_t>(pair.seat)];
  const Segment& seg = segments_[static_cast<std::size_t>(pair.seat)];
  const Vec2 ap = minus(p, a);
  return {dot(seg.normal, ap), dot(seg.direction, ap), seg.length,
          PlanarContact{minus(p, Vec2{s.x, s.y}), seg.normal, ContactKind::block_vertex}};
}

PairPose SeatContacts::point_pose(const SeatPair& pair, const BlockState& s, Vec2 a, Vec2 b) const {
  const SegmentFrame edge = segment_frame(a, b);
  const Vec2 p = seat_[static_cast<std::size_t>(pair.seat)];
  const Vec2 ap = minus(p, a);
  return {-dot(edge.normal, ap), dot(edge.direction, ap), edge.length,
          PlanarContact{minus(p, Vec2{s.x, s.y}), edge.normal, ContactKind::seat_point}};
}

void SeatContacts::vertices_on_segments(const BlockState& s, double tolerance,
                                        const std::optional<SeatPair>& left,
                                        std::vector<SeatPair>& found,
                                        VertexMarks& vertex_on_seat) const {
  for (int i = 0; i < vertex_count(); ++i) {
    for (int j = 0; j + 1 < point_count(); ++j) {
      const SeatPair pair{ContactKind::block_vertex, i, j};
      if (left && *left == pair) continue;
      const PairPose p = pose(pair, s);
      if (std::abs(p.gap) <= tolerance && p.along >= -tolerance &&
          p.along <= p.length + tolerance) {
        found.push_back(pair);
        vertex_on_seat[static_cast<std::size_t>(i)] = true;
      }
    }
  }
}

Vec2 SeatContacts::upward_at_point(int k) const {
  // The sum of the normals of the segments either side of the point.
  Vec2 up{0.0, 0.0};
  for (const int j : {k - 1, k}) {
    if (j < 0 || j + 1 >= point_count()) continue;
    const Vec2 n =
        segment_frame(seat_[static_cast<std::size_t>(j)], seat_[static_cast<std::size_t>(j) + 1])
            .normal;
    up = {up.x + n.x, up.y + n.y};
  }
  return up;
}

namespace {

// Of a seat point arrived at a block vertex whose two edges' normals are equally near the seat's
// upward direction (the block's fold in the seat's fold): whether it belongs on the other edge
// rather than on `here`'s. It goes on along the edge whose range it moves into (the block's base
// as the block slides over it), or, into neither, the one it approaches faster.
bool arrived_point_prefers_other_edge(const PlanarContact& here_contact, const PlanarContact& other,
                                      bool at_start, const BlockState& s) {
  const RigidVelocity v{s.vx, s.vy, s.omega};
  const ContactVelocity here = contact_velocity(here_contact, v);
  const ContactVelocity there = contact_velocity(other, v);
  // The point moves along an edge at minus the block's tangential velocity there; the
  // other edge meets this vertex at its other end.
  // Rates below the velocities' rounding say nothing.
  const double noise = kSeatPointRateRounding * (std::abs(here.tangent) + std::abs(there.tangent) +
                                                 std::abs(here.normal) + std::abs(there.normal));
  const bool enters_here = at_start ? here.tangent < -noise : here.tangent > noise;
  const bool enters_there = at_start ? there.tangent > noise : there.tangent < -noise;
  // Into both: the edge it moves more nearly along (a seat point at the joint of two
  // collinear segments slides along the base, whatever the face beside it does).
  bool other_edge_better = here.normal > there.normal;
  if (enters_here != enters_there) {
    other_edge_better = !enters_here;
  } else if (enters_here) {
    other_edge_better = std::abs(here.tangent) < std::abs(there.tangent);
  }
  return other_edge_better;
}

}  // namespace

bool SeatContacts::takes_point_at_vertex(const BlockState& s, const PairPose& p, int m, int k,
                                         bool at_start, Vec2 up, int arrived,
                                         const VertexMarks& vertex_on_seat) const {
  // Taken only when that vertex is on no seat segment, and only on the one of the vertex's two
  // edges whose normal is nearer the seat's upward direction (the heel's base, not its upstream
  // face).
  const int n = vertex_count();
  const int vertex = at_start ? m : (m + 1) % n;
  // A vertex that already has a contact on a seat segment there carries the block at this
  // point: the seat point is not taken again on an edge, even when it has just arrived. The
  // two pairs are one constraint (rows equal but for the edge's turn, theta), and the
  // projection onto both moved the block along the incline by their gaps' difference over
  // theta (record-suite sample 74: 6e-4 m at theta = 1.5e-12).
  if (vertex_on_seat[static_cast<std::size_t>(vertex)]) return false;
  const int other_edge = at_start ? (m + n - 1) % n : (m + 1) % n;
  const PlanarContact other = pose({ContactKind::seat_point, other_edge, k}, s).contact;
  // How much nearer the seat's upward direction this edge's normal is than the other's.
  const double nearer_up = dot(p.contact.normal, up) - dot(other.normal, up);
  if (k == arrived && std::abs(nearer_up) <= kEdgeNormalTie * norm(up)) {
    return !arrived_point_prefers_other_edge(p.contact, other, at_start, s);
  }
  if (nearer_up < 0) return false;
  return true;
}

std::vector<SeatPair> SeatContacts::touching(const BlockState& s, double tolerance,
                                             const std::optional<SeatPair>& left,
                                             int arrived) const {
  std::vector<SeatPair> found;
  // Room for any set of contacts the simulation takes (kMaxSeatContacts) without growing: the
  // search runs at every landing.
  found.reserve(8);
  VertexMarks vertex_on_seat{};
  vertices_on_segments(s, tolerance, left, found, vertex_on_seat);
  // Within `tolerance` of an edge, a point is within the block's radius and twice the tolerance of
  // the centre of mass: every edge lies inside the circle through the farthest vertex. A point
  // farther off (a long seat's ends, at each landing) touches none.
  const double reach = block_radius_ * (1.0 + kGeometryRounding) + 2.0 * tolerance;
  for (int k = 0; k < point_count(); ++k) {
    if (!touches_edges(k)) continue;
    const Vec2 point = seat_point(k);
    if (std::abs(point.x - s.x) > reach || std::abs(point.y - s.y) > reach) continue;
    const Vec2 up = upward_at_point(k);
    for (int m = 0; m < vertex_count(); ++m) {
      const SeatPair pair{ContactKind::seat_point, m, k};
      if (left && *left == pair) continue;
      const PairPose p = pose(pair, s);
      if (!(std::abs(p.gap) <= tolerance && p.along >= -tolerance &&
            p.along <= p.length + tolerance)) {
        continue;
      }
      const bool at_start = p.along <= tolerance, at_end = p.along >= p.length - tolerance;
      if ((at_start || at_end) &&
          !takes_point_at_vertex(s, p, m, k, at_start, up, arrived, vertex_on_seat)) {
        continue;
      }
      found.push_back(pair);
    }
  }
  return found;
}

bool SeatContacts::leaves_with(const SeatPair& left, const SeatPair& pair, int slip,
                               const BlockState& s) const {
  if (left.kind == pair.kind || slip == 0) return false;
  const SeatPair& vertex = left.kind == ContactKind::block_vertex ? left : pair;
  const SeatPair& point = left.kind == ContactKind::block_vertex ? pair : left;
  // The point's edge starts or ends at the vertex; the vertex's segment starts or ends at the
  // point.
  const int n = vertex_count();
  const bool same_vertex = point.block == vertex.block || (point.block + 1) % n == vertex.block;
  const bool same_point = vertex.seat == point.seat || vertex.seat + 1 == point.seat;
  if (!same_vertex || !same_point) return false;
  // A vertex moves along its segment with its contact's tangent (the segment's direction); a seat
  // point moves along its edge against it (the edge's direction, the block moving under it).
  const int along_rate = pair.kind == ContactKind::block_vertex ? slip : -slip;
  const PairPose p = pose(pair, s);
  return (p.along < 0.0 && along_rate < 0) || (p.along > p.length && along_rate > 0);
}

void SeatContacts::world_vertices(const BlockState& s, std::span<Vec2> out) const {
  const SineCosine turn = cached_turn(s.theta);
  for (std::size_t i = 0; i < body_.size(); ++i) {
    const Vec2 r = rotate(body_[i], turn.cos, turn.sin);
    out[i] = {s.x + r.x, s.y + r.y};
  }
}

bool SeatContacts::under_end_segment(Vec2 p, bool last_end) const {
  const std::size_t k = last_end ? segments_.size() - 1 : 0;
  const Segment& segment = segments_[k];
  // Only an end segment that leans away from its end has such points past its end's x.
  const bool leans = last_end ? segment.direction.y > 0 : segment.direction.y < 0;
  const Vec2 ap = minus(p, seat_[k]);
  const double along = dot(segment.direction, ap);
  return leans && dot(segment.normal, ap) < -end_depth_ && along >= 0 && along <= segment.length;
}

double SeatContacts::clearance_at_any(Vec2 p) const {
  // Over a two-segment seat (the type B block's notch), its height on the segment under p
  // without looking for its ends' cases or its segment: every guard evaluation's vertices.
  if (p.x >= folded_[0].start_x && p.x <= folded_[1].end_x) {
    const SingleSegment& f = folded_[p.x < folded_[1].start_x ? 0 : 1];
    return p.y - (f.start_y + f.rise * ((p.x - f.start_x) / f.run));
  }
  const Vec2 first = seat_.front(), last = seat_.back();
  if (p.x < first.x && !under_end_segment(p, false)) return norm(minus(p, first));
  if (p.x > last.x && !under_end_segment(p, true)) return norm(minus(p, last));
  // The first point right of p past the first, or the last point. A scan finds it faster than a
  // binary search among a few points (the type B seat's one inner point, at every guard
  // evaluation); the points' x increase, so both find the same one.
  const auto last_point = seat_.end() - 1;
  auto right = seat_.begin() + 1;
  if (last_point - right > kScannedSeatPoints) {
    right =
        std::upper_bound(right, last_point, p.x, [](double x, const Vec2& v) { return x < v.x; });
  } else {
    while (right != last_point && !(p.x < right->x)) ++right;
  }
  const Vec2 a = *(right - 1), b = *right;
  return p.y - (a.y + (b.y - a.y) * ((p.x - a.x) / (b.x - a.x)));
}

double SeatContacts::vertex_clearance(int i, const BlockState& s) const {
  return clearance_at(vertex_at(i, s));
}

double SeatContacts::point_clearance(int k, std::span<const Vec2> world) const {
  // One pass for both the distance and the side: the dearest of the guards of a block on a seat.
  const Vec2 p = seat_[static_cast<std::size_t>(k)];
  double squared = std::numeric_limits<double>::infinity();
  bool inside = false;
  const std::size_t n = body_.size();
  bool end_above = world[0].y > p.y;
  // The edge from vertex j to vertex i, i after j, with its ends as the plain pass orders them. An
  // edge wholly above or below p farther than the nearest so far is not the nearest (the block's
  // far edges, at every evaluation): min() of the rest is the same to the bit, in any order, as
  // squared starts at infinity and min() never takes a NaN from an edge.
  const auto visit = [&](std::size_t i, std::size_t j) {
    const bool start_above = world[i].y > p.y;
    if (start_above != end_above) {
      inside = inside != crossed_right_of(p, world[i], world[j]);
      end_above = start_above;
    } else {
      const double gap = level_gap(p.y, world[i].y, world[j].y, start_above);
      if (gap > kSmallestGap && gap * gap >= squared) return;
    }
    squared = std::min(squared, squared_distance_to_edge(p, world[i], world[j]));
  };
  // The base's edges first: the seat's points lie under the base, so the nearest so far is small
  // early and prunes the rest.
  for (std::size_t i = 1; i < n; ++i) visit(i, i - 1);
  visit(0, n - 1);
  const double distance = std::sqrt(squared);
  return inside ? -distance : distance;
}

double SeatContacts::boundary_distance(int k, std::span<const Vec2> world) const {
  const Vec2 p = seat_[static_cast<std::size_t>(k)];
  double squared = std::numeric_limits<double>::infinity();
  const std::size_t n = body_.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    squared = std::min(squared, squared_distance_to_edge(p, world[i], world[j]));
  }
  return std::sqrt(squared);
}

double SeatContacts::point_clearance_within(int k, std::span<const Vec2> world, double far) const {
  // Every point of the block lies within twice its radius of its first vertex.
  const double diameter = 2.0 * block_radius_;
  const Vec2 off = minus(seat_[static_cast<std::size_t>(k)], world[0]);
  const double squared = dot(off, off), reach = diameter + far;
  if (squared > reach * reach) return std::sqrt(squared) - diameter;
  return point_clearance(k, world);
}

bool SeatContacts::inside_block(int k, std::span<const Vec2> world) const {
  const Vec2 p = seat_[static_cast<std::size_t>(k)];
  bool inside = false;
  const std::size_t n = body_.size();
  bool end_above = world[n - 1].y > p.y;
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const bool start_above = world[i].y > p.y;
    if (start_above != end_above) inside = inside != crossed_right_of(p, world[i], world[j]);
    end_above = start_above;
  }
  return inside;
}

double SeatContacts::point_clearance(int k, const BlockState& s) const {
  std::array<Vec2, kMaxSeatClearances> world;  // the first vertex_count() set and read
  world_vertices(s, world);
  return point_clearance(k, world);
}

double SeatContacts::penetration(const BlockState& s) const {
  std::array<Vec2, kMaxSeatClearances> world;  // the first vertex_count() set and read
  world_vertices(s, world);
  return penetration(std::span<const Vec2>(world).first(body_.size()));
}

double SeatContacts::penetration(std::span<const Vec2> world) const {
  return deepest_point(world, deepest_vertex(world),
                       [](int) { return std::numeric_limits<double>::quiet_NaN(); });
}

double SeatContacts::deepest_vertex(std::span<const Vec2> world) const {
  double deepest = 0.0;
  const double first = seat_.front().x, last = seat_.back().x;
  for (const Vec2& p : world) {
    // A vertex over the seat's top adds nothing: its -clearance is below 0 (the corners a rocking
    // block lifts, at every step).
    if (p.x >= first && p.x <= last && p.y > over_top_) continue;
    deepest = std::max(deepest, -clearance_at(p));
  }
  return deepest;
}

double SeatContacts::height_over_fall(const BlockState& s, std::span<const Vec2> world,
                                      double depth) const {
  const bool past_left = s.x<seat_.front().x, past_right = s.x> seat_.back().x;
  if (!past_left && !past_right) return depth;
  const double end = past_left ? seat_.front().y : seat_.back().y;
  double lowest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < body_.size(); ++i) lowest = std::min(lowest, world[i].y);
  return lowest - (end - depth);
}

}  // namespace blockfrag
