// Where a block touches its seat (engine/scene/seat.hpp) at a pose: the possible contacts (a block
// vertex on a seat segment, a seat point on a block edge), their gaps and the contacts the force
// and impact laws of engine/contact/planar_contact.hpp take. World frame: the frame of the block's
// vertices and the seat's points; BlockState's (x, y) is the centre of mass there.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <span>
#include <vector>

#include "engine/contact/planar_contact.hpp"
#include "engine/scene/block_state.hpp"
#include "engine/scene/polygon_properties.hpp"
#include "engine/seat/turn_cache.hpp"
#include "engine/tolerances.hpp"

namespace blockfrag {

// A possible contact. block_vertex: block vertex `block` on seat segment `seat` (from seat point
// `seat` to the next). seat_point: seat point `seat` on block edge `block` (from vertex `block` to
// the next, counter-clockwise).
struct SeatPair {
  ContactKind kind;
  int block, seat;
  bool operator==(const SeatPair&) const = default;
};

// The line through a seat segment: its unit direction (left to right), its upward normal, and the
// offset of its points along that normal.
struct SeatLine {
  Vec2 direction, normal;
  double offset;
};

// A pair at a pose: its gap (> 0 open), where its point lies along the segment or edge (0 at its
// start, `length` at its end) and the contact the force laws take (the normal is the segment's
// upward one, or the edge's inward one).
struct PairPose {
  double gap, along, length;
  PlanarContact contact;
};

class SeatContacts {
 public:
  // The block's vertices (counter-clockwise) and the seat's points (left to right), in one frame.
  SeatContacts(const std::vector<Vertex>& block, const std::vector<Vertex>& seat);

  // The centre of mass at rest, in the seat's frame.
  Vec2 rest_centre() const { return centre_; }
  int vertex_count() const { return static_cast<int>(body_.size()); }
  int point_count() const { return static_cast<int>(seat_.size()); }
  Vec2 seat_point(int k) const { return seat_[static_cast<std::size_t>(k)]; }
  // Block vertex i from the centre of mass, body frame.
  Vec2 body_vertex(int i) const { return body_[static_cast<std::size_t>(i)]; }
  SeatLine segment_line(int k) const;
  // Seat segment k's upward unit normal: a block vertex's contact normal on it at any pose.
  Vec2 segment_normal(int k) const { return segments_[static_cast<std::size_t>(k)].normal; }
  // Block vertex i in the world frame at the pose.
  Vec2 vertex_at(int i, const BlockState& s) const;

  PairPose pose(const SeatPair& pair, const BlockState& s) const;
  // The same with the block's vertices at s given (world_vertices): the guards, which have turned
  // them all, pose a seat point's contact without turning its edge's ends again.
  PairPose pose(const SeatPair& pair, const BlockState& s, std::span<const Vec2> world) const;

  // Every pair whose gap is within `tolerance` of zero and whose point lies on its segment or
  // edge (within `tolerance`), but `left` (a contact that has just left its segment's end). A
  // block vertex at a seat point (the type B block's heel and fold) is taken on each seat segment
  // it ends, with that segment's normal; a seat point at a block vertex is taken on the block's
  // edges there only when that vertex is on no seat segment, and then on the edge whose normal is
  // nearer the seat's upward one: where a vertex meets a vertex, the seat pushes up (the heel's
  // seat point never pushes on the upstream face above it).
  // Not even a seat point that has just reached the block (`arrived`) is taken at a vertex on the
  // seat: that vertex's own contact carries the block there. Where the two edges' normals are
  // equally near the seat's upward direction (the block's fold in the seat's fold), an arrived
  // point is taken on the edge whose range it moves into, or if that does not decide, on the one
  // it approaches faster: the one it came in through.
  std::vector<SeatPair> touching(const BlockState& s, double tolerance,
                                 const std::optional<SeatPair>& left, int arrived) const;
  // Whether `pair`, slipping with sign `slip` (its contact's tangential velocity's), is the other
  // pair of the block-vertex-on-seat-point corner `left` has just left through its end (a vertex
  // on a segment that ends at the point, the point on an edge that ends at the vertex), lies past
  // its own end at s, and moves further past it: the corner leaves the seat, and `pair` touches
  // only within the tolerance a drifted contact is given.
  bool leaves_with(const SeatPair& left, const SeatPair& pair, int slip, const BlockState& s) const;

  // Where p (on the line of seat segment k) lies along the straight run of seats segments k is
  // part of (between the points either side of it that bend: see touches_edges), and the run's
  // length: a vertex slipping along a flat seat given as several segments passes their joints as
  // it would a long segment's middle.
  struct RunPlace {
    double along, length;
  };
  RunPlace place_on_run(int k, Vec2 p) const;

  // Whether seat point k can touch a block edge: an end of the seat, or a point where it bends
  // (off the line through its neighbours by more than the contact height).
  bool touches_edges(int k) const { return point_touches_edges_[static_cast<std::size_t>(k)]; }

  // Whether p, past the first point's x (last_end false) or the last's, lies under the end
  // segment's line (by more than the contact height) with its projection on that segment: where the
  // segment leans away from its end (the type B seat's incline rising to its last point), that is
  // the segment's contact region (SeatContacts::touching takes a vertex there on it). Taken as past
  // the end, a vertex there would not be under the seat, and a block corner leaving the seat's
  // corner tip to tip (the type B block's toe bouncing off the incline's top, landing 1e-8 m past
  // it) would go down past it, its base edge crossing the incline with no vertex or seat point
  // inside the other.
  bool under_end_segment(Vec2 p, bool last_end) const;
  // Whether block vertex i at s lies inside the seat's x range within `near` of an end's x, more
  // than `depth` below the seat there, while the block's centre of mass is past that end: a vertex
  // of a block going down beside the seat that comes into its range under its end (a seat has no
  // face under its ends, and its clearance jumps there from the distance to the end to the depth
  // under the seat). A block whose centre is over the seat is not beside it.
  bool under_an_end(int i, const BlockState& s, double near, double depth) const {
    const double first = seat_.front().x, last = seat_.back().x;
    if (s.x >= first && s.x <= last) return false;
    const Vec2 p = vertex_at(i, s);
    const bool beside =
        s.x < first ? p.x >= first && p.x - first <= near : p.x <= last && last - p.x <= near;
    return beside && clearance_at(p) < -depth;
  }
  // Whether the seat's points lie on one line (a flat seat, within `tolerance` m).
  bool straight(double tolerance) const;
  // How far theta is from overturning (> 0 inside): on a straight seat the flat ground's rule (the
  // face next to the base lies on it, engine/scene/block_geometry.hpp), elsewhere a quarter turn
  // either way (on a folded seat no single face lies on it; past a quarter turn the block's base
  // faces sideways, and it has tipped over).
  double overturn_margin(const BlockGeometry& geometry, double theta) const;
  // The tilt the block is reported at when it overturns towards the sign of `direction`.
  double overturn_theta(const BlockGeometry& geometry, double direction) const;

  // The seat's height where all its points have the same one (a level seat), else none.
  std::optional<double> level() const;
  // Whether every point of the block lies strictly inside the seat's x range, by `margin`, at
  // every pose whose centre of mass is within `drift` of x along x.
  bool inside_ends_drifting(double x, double drift, double margin) const {
    const double reach = block_radius_ * (1.0 + kGeometryRounding) + drift + margin;
    return x - reach > seat_.front().x && x + reach < seat_.back().x;
  }
  // Whether every point of the block at the pose lies over the seat's x range, its ends included.
  bool within_ends(const BlockState& s) const {
    const double reach = block_radius_ * (1.0 + kGeometryRounding);
    return s.x - reach >= seat_.front().x && s.x + reach <= seat_.back().x;
  }
  // Whether within_ends holds at every tilt of a block turning about its point at p (each of its
  // points within the block's diameter of p): a pivot's, asked once for all its steps.
  bool within_ends_turning_about(Vec2 p) const {
    const double reach =
        2.0 * block_radius_ * (1.0 + kGeometryRounding) + kGeometryRounding * std::abs(p.x);
    return p.x - reach >= seat_.front().x && p.x + reach <= seat_.back().x;
  }
  // The block's vertices in the world frame at the pose, into `out` (vertex_count() of them): one
  // rotation for all, for the guards that look at every vertex.
  void world_vertices(const BlockState& s, std::span<Vec2> out) const;
  // vertex_clearance and point_clearance for the vertices given in the world frame.
  double clearance_at(Vec2 p) const {
    // Over a one-segment seat, its height there without looking for the segment: a rocking
    // block's watched vertices at every guard evaluation.
    if (p.x >= single_.start_x && p.x <= single_.end_x) {
      return p.y - (single_.start_y + single_.rise * ((p.x - single_.start_x) / single_.run));
    }
    return clearance_at_any(p);
  }
  double point_clearance(int k, std::span<const Vec2> world) const;
  // point_clearance where seat point k may lie within `far` of the block; farther, a lower bound
  // on it above `far`, from one distance instead of a pass over the block's edges (a flat seat's
  // ends, 1e4 R away, at every guard evaluation). A touching guard that far from zero is only
  // ever read as positive and far from zero.
  double point_clearance_within(int k, std::span<const Vec2> world, double far) const;
  // Whether seat point k is inside the block (point_clearance's sign, without its distance).
  bool inside_block(int k, std::span<const Vec2> world) const;
  // Seat point k's distance from the block's boundary (point_clearance's size, without its sign).
  double boundary_distance(int k, std::span<const Vec2> world) const;

  // How far block vertex i is above the seat (its height over the seat for x within the seat's
  // ends, else its distance from the nearer end): <= 0 where it touches or is below. A vertex past
  // an end's x but under the end segment, its projection on that segment, is below: its height
  // over the segment's line (see under_end_segment).
  double vertex_clearance(int i, const BlockState& s) const;
  // Seat point k's signed distance from the block's boundary: > 0 outside, < 0 inside.
  double point_clearance(int k, const BlockState& s) const;
  // How deep the block is in the seat: the largest of -clearance over vertices and points (>= 0).
  double penetration(const BlockState& s) const;
  // The same with the block's vertices at the pose given (world_vertices).
  double penetration(std::span<const Vec2> world) const;
  // The same with the clearances of the seat points `points` at that pose given as
  // point_clearance_within finds them (NaN where not found): their sign says whether they are
  // inside, and inside, their size is the distance boundary_distance finds, without a pass over
  // the block's edges (a rocking block's watched points, at every step's end).
  template <class Points>
  double penetration(std::span<const Vec2> world, const Points& points,
                     std::span<const double> clearances) const {
    return deepest_point(world, deepest_vertex(world), [&](int k) {
      for (std::size_t at = 0; at < points.size(); ++at) {
        if (points[at] == k) return clearances[at];
      }
      return std::numeric_limits<double>::quiet_NaN();
    });
  }
  // How far the lowest block vertex is above the level `depth` below the end of the seat the
  // centre of mass has passed (> 0 while it has not fallen there); `depth` where it has passed
  // neither end. `world`: the block's vertices at the pose (world_vertices).
  double height_over_fall(const BlockState& s, std::span<const Vec2> world, double depth) const;

 private:
  // touching's steps: the block vertices on seat segments (marking those vertices), the seat's
  // upward direction at point k, and whether a seat point at a block vertex (the pair's point at
  // the start of edge m, or at its end) is taken on that edge.
  // Per block vertex (at most kMaxSeatClearances of them, as the scene's validation has it).
  using VertexMarks = std::array<bool, kMaxSeatClearances>;
  void vertices_on_segments(const BlockState& s, double tolerance,
                            const std::optional<SeatPair>& left, std::vector<SeatPair>& found,
                            VertexMarks& vertex_on_seat) const;
  Vec2 upward_at_point(int k) const;
  // pose() of a block vertex at p, and of a seat point on the block's edge from a to b.
  PairPose vertex_pose(const SeatPair& pair, const BlockState& s, Vec2 p) const;
  PairPose point_pose(const SeatPair& pair, const BlockState& s, Vec2 a, Vec2 b) const;
  // penetration's passes: the deepest of the vertices under the seat, then of that and the seat
  // points inside the block, known(k) giving point k's clearance where known (else NaN).
  double deepest_vertex(std::span<const Vec2> world) const;
  template <class Known>
  double deepest_point(std::span<const Vec2> world, double deepest, const Known& known) const {
    // A point outside adds nothing: its -clearance is not above 0. A point farther from the first
    // vertex than the block's diameter (and its rounding) is outside without a pass over its edges
    // (a flat seat's ends, 1e4 R away, at every step).
    const double reach = 2.0 * block_radius_ * (1.0 + kGeometryRounding);
    for (int k = 0; k < point_count(); ++k) {
      const Vec2 p = seat_[static_cast<std::size_t>(k)];
      const Vec2 off{p.x - world[0].x, p.y - world[0].y};
      if (off.x * off.x + off.y * off.y > reach * reach) continue;
      const double clearance = known(k);
      if (!std::isnan(clearance)) {
        if (std::signbit(clearance)) deepest = std::max(deepest, -clearance);
      } else if (inside_block(k, world)) {
        deepest = std::max(deepest, boundary_distance(k, world));
      }
    }
    return deepest;
  }
  // clearance_at on any seat, past its ends or over any of its segments.
  double clearance_at_any(Vec2 p) const;
  bool takes_point_at_vertex(const BlockState& s, const PairPose& p, int m, int k, bool at_start,
                             Vec2 up, int arrived, const VertexMarks& vertex_on_seat) const;

  struct Segment {  // a seat segment's unit direction, upward normal and length
    Vec2 direction, normal;
    double length;
  };

  std::vector<Vec2> body_;     // block vertices relative to the centre of mass, body frame
  double block_radius_ = 0.0;  // the farthest vertex from the centre of mass
  std::vector<Vec2> seat_;
  std::vector<Segment> segments_;
  Vec2 centre_;
  bool straight_ = false;  // set from the block's size: see the constructor
  // The contact height (m): a vertex at a seat's end, the type B block rocking on its toe there, is
  // under the end segment's line or past its end by rounding only.
  double end_depth_ = 0.0;
  // Above the seat: a point over its x range higher than this is above every segment there, its
  // clearance positive (the seat's highest point and its rounding).
  double over_top_ = 0.0;
  std::vector<bool> point_touches_edges_;
  std::vector<int> run_start_, run_end_;  // per segment: its straight run's first and last point
  // A one-segment seat's first point, its last point's x and the segment's rise and run, as
  // clearance_at_any finds them; on any other seat an empty range of x, taking no point.
  struct SingleSegment {
    double start_x = std::numeric_limits<double>::infinity(), start_y = 0.0;
    double end_x = -std::numeric_limits<double>::infinity(), rise = 0.0, run = 1.0;
  };
  SingleSegment single_;
  // A two-segment seat's segments, each as single_ holds one; on any other seat empty ranges.
  std::array<SingleSegment, 2> folded_;
};

}  // namespace blockfrag
