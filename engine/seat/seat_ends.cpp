// Which of a seat's guards are least at an end of a step (SeatOde::guard_claims, SeatSystem's
// claims): the guard watch samples a guard near zero inside a step only where this is not known.
// Each claim holds of the guard as SeatSystem::guards computes it; where a case is not covered, the
// guard is sampled. Only the guards asked about are looked at.
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>
#include <span>
#include <utility>

#include "engine/seat/seat_system.hpp"
#include "engine/seat/turn_cache.hpp"
#include "engine/tolerances.hpp"

namespace blockfrag {

namespace {

// Where x lies against the seat's range: -1 past its first point, 0 over it, 1 past its last.
int side_of(double x, const SeatContacts& seat) {
  if (x < seat.seat_point(0).x) return -1;
  return x > seat.seat_point(seat.point_count() - 1).x ? 1 : 0;
}

// Whether the seat is one segment running left to right and a vertex whose x is the sinusoid x
// stays over it at every tilt: its x within |a| + |b| of c, that reach again (far more than the
// rounding of its extent) and `margin` (kSeatEndMargin R) inside the seat's ends. Then
// vertex_claim finds neither end's case and asks only whether the step holds its height's minimum
// over that segment.
bool stays_over_one_segment(const SeatContacts& seat, const Sinusoid& x, double margin) {
  if (seat.point_count() != 2) return false;
  const double first = seat.seat_point(0).x, last = seat.seat_point(1).x;
  const double reach = 2 * (std::abs(x.a) + std::abs(x.b)) + kGeometryRounding * std::abs(x.c);
  return first < last && x.c - reach >= first + margin && x.c + reach <= last - margin;
}

// A sinusoid's slope moves by at most |a| + |b| times the tilt's change: within this reach of the
// tilt whose turn is given, it keeps the sign it has there (a constant's, everywhere).
double slope_sign_reach(const Sinusoid& f, SineCosine turn) {
  const double swing = std::abs(f.a) + std::abs(f.b);
  return swing > 0 ? std::abs(f.slope_at(turn)) / swing : std::numeric_limits<double>::infinity();
}

// The tilts within `reach` of theta, less twice kThetaStepMarginRad at each side: a step whose
// range, widened by kThetaStepMarginRad, lies inside them lies within reach (far more than the
// slopes' rounding).
void set_range_about(double theta, double reach, double& lo, double& hi) {
  const double margin = 2 * kThetaStepMarginRad;
  lo = theta - reach + margin;
  hi = theta + reach - margin;
}

}  // namespace

void SeatSystem::claim_overturn_and_fall(double x_lo, double x_hi, bool theta_one_way,
                                         bool vertices_linear, GuardClaims& claims) const {
  const int side = side_of(x_lo, *c_.contacts);
  if (side != side_of(x_hi, *c_.contacts)) return;
  // Over the seat, the overturning margin (concave in theta) and a constant fall depth; past an
  // end, a constant 1 and the lowest vertex's height, the least of functions linear in a place
  // moving one way where vertices_linear.
  claims[0] = side != 0 || theta_one_way;
  claims[1] = side == 0 || vertices_linear;
}

void SeatSystem::claim_contact_guards(bool place_one_way, bool rate_one_way,
                                      GuardClaims& claims) const {
  for (int i = 0; i < count_; ++i) {
    if (active_[static_cast<std::size_t>(i)].state == ContactState::stick) continue;
    const auto base = static_cast<std::size_t>(2 + kSeatContactGuards * i);
    claims[base + 1] = rate_one_way;
    claims[base + 2] = place_one_way;
    claims[base + 3] = place_one_way;
  }
}

void SeatSystem::claim_lift_offs(GuardClaims& claims) const {
  for (int i = 0; i < count_; ++i) {
    if (active_[static_cast<std::size_t>(i)].state == ContactState::stick) continue;
    claims[static_cast<std::size_t>(2 + kSeatContactGuards * i)] = true;
  }
}

bool SeatSystem::slide_forces_one_way(double t0, double t1, double rise) const {
  if (!c_.vertical->is_zero() || !c_.piece->extrema_between(t0, t1).empty()) return false;
  if (c_.external == nullptr) return true;
  return rise == 0.0 && c_.external->seated_crack() == SeatedCrack::unaffected;
}

template <class HeightLeastAtEnds>
bool SeatSystem::clearance_least_at_ends(double x_lo, double x_hi,
                                         const HeightLeastAtEnds& height_least_at_ends) const {
  const SeatContacts& seat = *c_.contacts;
  const int last = seat.point_count() - 1;
  const double margin = kSeatEndMargin * length_scale();
  if (!(x_lo >= seat.seat_point(0).x + margin && x_hi <= seat.seat_point(last).x - margin)) {
    return false;
  }
  int k = 0;
  while (seat.seat_point(k + 1).x < x_lo) ++k;
  // Where the seat's slope only grows (a valley), its height at x is the largest of its segments'
  // lines there: the clearance is the least of the heights over them.
  double slope_before = -std::numeric_limits<double>::infinity();
  for (; k < last; ++k) {
    const Vec2 a = seat.seat_point(k), b = seat.seat_point(k + 1);
    if (!(b.x > a.x)) return false;
    const double slope = (b.y - a.y) / (b.x - a.x);
    if (slope < slope_before || !height_least_at_ends(k)) return false;
    slope_before = slope;
    if (b.x >= x_hi) return true;
  }
  return false;
}

// The block turns about the chart's point p: a vertex w from the pivot (body frame) is at
// p + Rot(theta) w, and its height over a line of slope m through a is a sinusoid of theta. Seen
// from the block, a seat point s moves on a circle about the pivot, at body + Rot(-theta) (s - p).
PivotSweep::PivotSweep(const SeatSystem& system, const PivotChart& chart) : chart_(chart) {
  reset(system, chart);
}

// Its storage is kept: a record's pieces turn on a new pivot often (its place found anew from the
// state at each), and allocating the sweep's blocks anew was a sixth of setting it up.
void PivotSweep::reset(const SeatSystem& system, const PivotChart& chart) {
  system_ = &system;
  contacts_ = system.c_.contacts;
  chart_ = chart;
  watched_vertices_ = system.watched_vertices_;
  watched_points_ = system.watched_points_;
  centre_x_ = {chart.point.x, -chart.body.x, chart.body.y};
  last_end_ = 0;
  last_end_turn_ = {0.0, 1.0};
  vertices_.clear();
  vertex_ranges_.clear();
  points_.clear();
  sinusoids_.clear();
  const SeatContacts& seat = *system.c_.contacts;
  const Vec2 p = chart.point, body = chart.body;
  segment_count_ = static_cast<std::size_t>(seat.point_count() - 1);
  block_vertex_count_ = static_cast<std::size_t>(seat.vertex_count());
  if (edge_normals_of_ != contacts_) set_edge_normals();
  vertices_.reserve(system.watched_vertices_.size());
  points_.reserve(system.watched_points_.size());
  sinusoids_.reserve(system.watched_vertices_.size() * segment_count_ +
                     system.watched_points_.size() * 2 * block_vertex_count_);
  for (const int i : system.watched_vertices_) {
    const Vec2 v = seat.body_vertex(i);
    const Vec2 w{v.x - body.x, v.y - body.y};
    Vertex vertex{{p.x, w.x, -w.y}, sinusoids_.size(), {}};
    for (const int end : {0, 1}) {
      const Vec2 e = seat.seat_point(end == 0 ? 0 : seat.point_count() - 1);
      const Vec2 f{p.x - e.x, p.y - e.y};
      vertex.ends[static_cast<std::size_t>(end)] = {f.x * f.x + f.y * f.y + w.x * w.x + w.y * w.y,
                                                    2 * (f.x * w.x + f.y * w.y),
                                                    2 * (f.y * w.x - f.x * w.y)};
    }
    for (int k = 0; k + 1 < seat.point_count(); ++k) {
      const Vec2 a = seat.seat_point(k), b = seat.seat_point(k + 1);
      // A segment that does not run left to right is never asked (clearance_least_at_ends).
      const double m = b.x > a.x ? (b.y - a.y) / (b.x - a.x) : 0.0;
      sinusoids_.push_back({p.y - a.y - m * (p.x - a.x), w.y - m * w.x, w.x + m * w.y});
    }
    // A folded seat's pivots, set up at every sample of a record, keep no ranges.
    if (segment_count_ == 1) {
      vertex_ranges_.push_back(
          {stays_over_one_segment(seat, vertex.x, kSeatEndMargin * system.length_scale())});
    }
    vertices_.push_back(vertex);
  }
  for (const int k : system.watched_points_) add_point(k);
}

// The block's edges do not change from pivot to pivot: their normals are found once, not at each
// point of each pivot a record's pieces turn on.
void PivotSweep::set_edge_normals() {
  const SeatContacts& seat = *contacts_;
  const std::size_t n = block_vertex_count_;
  edge_normals_.clear();
  for (std::size_t j = 0; j < n; ++j) {
    const Vec2 a = seat.body_vertex(static_cast<int>(j));
    const Vec2 b = seat.body_vertex(static_cast<int>((j + 1) % n));
    const double length = std::sqrt((b.x - a.x) * (b.x - a.x) + (b.y - a.y) * (b.y - a.y));
    edge_normals_.push_back({-(b.y - a.y) / length, (b.x - a.x) / length});
  }
  edge_normals_of_ = contacts_;
}

// Seen from the block, seat point k moves on a circle about the pivot.
void PivotSweep::add_point(int k) {
  const SeatContacts& seat = *contacts_;
  const Vec2 body = chart_.body, s = seat.seat_point(k);
  const Vec2 u{s.x - chart_.point.x, s.y - chart_.point.y};
  const std::size_t first = sinusoids_.size(), n = block_vertex_count_;
  sinusoids_.resize(first + 2 * n);
  for (std::size_t j = 0; j < n; ++j) {
    const Vec2 a = seat.body_vertex(static_cast<int>(j));
    const Vec2 e{body.x - a.x, body.y - a.y};
    sinusoids_[first + j] = {e.x * e.x + e.y * e.y + u.x * u.x + u.y * u.y,
                             2 * (e.x * u.x + e.y * u.y), 2 * (e.x * u.y - e.y * u.x)};
    const Vec2 normal = edge_normals_[j];
    sinusoids_[first + n + j] = {normal.x * e.x + normal.y * e.y, normal.x * u.x + normal.y * u.y,
                                 normal.x * u.y - normal.y * u.x};
  }
  points_.push_back({k, first});
}

bool PivotSweep::serves(const SeatSystem& system, const PivotChart& chart) const {
  return system.c_.contacts == contacts_ && chart.point.x == chart_.point.x &&
         chart.point.y == chart_.point.y && chart.body.x == chart_.body.x &&
         chart.body.y == chart_.body.y && system.watched_vertices_ == watched_vertices_ &&
         system.watched_points_ == watched_points_;
}

SineCosine PivotSweep::turn_at(double theta) const {
  return std::bit_cast<std::uint64_t>(theta) == last_end_ ? last_end_turn_ : sine_cosine(theta);
}

GuardClaims PivotSweep::claims(double theta0, double theta1, const GuardClaims& asked) {
  std::array<Vec2, kMaxSeatClearances> world;  // the first vertex_count(), once asked for
  bool world_set = false;
  return claims_with(theta0, theta1, asked, [&](double lo, const Point& point, std::size_t) {
    if (!world_set) system_->c_.contacts->world_vertices(chart_.full(0.0, {lo, 0.0}), world);
    world_set = true;
    return system_->c_.contacts->inside_block(point.k, world);
  });
}

// A watched point's guard is its point_clearance_within over R at the block's pose there, whose
// sign bit is inside_block's answer at that pose (-0 where it lies on the boundary inside); where
// it is farther than the block's reach, positive and outside. The guards at an end were found at
// the chart's pose for that tilt, the pose the claims above turn the block to, bit for bit.
GuardClaims PivotSweep::claims(double theta0, double theta1, const GuardClaims& asked,
                               const std::array<double, kSeatGuards>& at0,
                               const std::array<double, kSeatGuards>& at1) {
  const std::array<double, kSeatGuards>& at_lo = theta1 < theta0 ? at1 : at0;
  return claims_with(theta0, theta1, asked,
                     [&](double, const Point&, std::size_t g) { return std::signbit(at_lo[g]); });
}

template <class InsideAtLo>
GuardClaims PivotSweep::claims_with(double theta0, double theta1, const GuardClaims& asked,
                                    const InsideAtLo& inside_at_lo) {
  GuardClaims claims = system_->unused_guards();
  // The end's turn is the one the guards there just asked the turn cache for.
  const SineCosine turn0 = turn_at(theta0), turn1 = cached_turn(theta1);
  last_end_ = std::bit_cast<std::uint64_t>(theta1);
  last_end_turn_ = turn1;
  // The ends as std::min and std::max pick them.
  const bool lo_is_end = theta1 < theta0, hi_is_end = theta0 < theta1;
  const double lo = lo_is_end ? theta1 : theta0, hi = hi_is_end ? theta1 : theta0;
  const ThetaStep step(lo, hi, lo_is_end ? turn1 : turn0, hi_is_end ? turn1 : turn0);
  if (asked[0] || asked[1]) {
    const ThetaStep::Extent x = step.extent(centre_x_);
    system_->claim_overturn_and_fall(x.least, x.largest, true, false, claims);
  }
  auto g = static_cast<std::size_t>(kFirstClearanceGuard);
  // Only a vertex over a seat of one segment keeps a range: on a folded seat, the claim alone.
  if (segment_count_ == 1) {
    VertexRange* range = vertex_ranges_.data();
    for (const Vertex& v : vertices_) {
      VertexRange& r = *range++;
      const bool in_range = lo >= r.claimed_lo && hi <= r.claimed_hi;
      claims[g] =
          asked[g] && (in_range || (r.over_one_segment ? claims_vertex(step, v, r, theta1, turn1)
                                                       : vertex_claim(step, v)));
      ++g;
    }
  } else {
    for (const Vertex& v : vertices_) {
      claims[g] = asked[g] && vertex_claim(step, v);
      ++g;
    }
  }
  for (Point& point : points_) {
    if (asked[g] && claims_point(step, lo, hi, point, theta1, turn1)) {
      claims[g] = !inside_at_lo(lo, point, g);
    }
    ++g;
  }
  return claims;
}

// Over the seat, the vertex's clearance is its height over it; past an end, its distance from that
// end, whose square is a sinusoid too, while the vertex stays above the line of an end segment
// that leans away from that end (under it, the clearance is the height over it:
// SeatContacts::under_end_segment).
bool PivotSweep::vertex_claim(const ThetaStep& step, const Vertex& vertex) const {
  const SeatContacts& seat = *system_->c_.contacts;
  const auto [x_lo, x_hi] = step.extent(vertex.x);
  const double margin = kSeatEndMargin * system_->length_scale();
  const int last = seat.point_count() - 1;
  const auto above_end_segment = [&](int k, bool leans) {
    return !leans || step.least(heights(vertex)[static_cast<std::size_t>(k)]) > margin;
  };
  if (x_hi <= seat.seat_point(0).x - margin) {
    return above_end_segment(0, seat.seat_point(1).y < seat.seat_point(0).y) &&
           !step.holds_minimum(vertex.ends[0]);
  }
  if (x_lo >= seat.seat_point(last).x + margin) {
    return above_end_segment(last - 1, seat.seat_point(last).y > seat.seat_point(last - 1).y) &&
           !step.holds_minimum(vertex.ends[1]);
  }
  return system_->clearance_least_at_ends(x_lo, x_hi, [&](int k) {
    return !step.holds_minimum(heights(vertex)[static_cast<std::size_t>(k)]);
  });
}

bool PivotSweep::claims_vertex(const ThetaStep& step, const Vertex& vertex, VertexRange& range,
                               double theta_end, SineCosine end_turn) const {
  if (!vertex_claim(step, vertex)) return false;
  set_claimed_range(vertex, range, theta_end, end_turn);
  return true;
}

// Over one segment the claim is that the step holds no minimum of the vertex's height: within the
// reach of its slope's sign no step does, and vertex_claim finds that there. A rocking block's
// steps mostly lie within the last one's.
void PivotSweep::set_claimed_range(const Vertex& vertex, VertexRange& range, double theta,
                                   SineCosine turn) const {
  set_range_about(theta, slope_sign_reach(heights(vertex)[0], turn), range.claimed_lo,
                  range.claimed_hi);
}

// The point's clearance is its distance from the block's boundary, the least of its distances from
// the edges, while it stays outside. Its distance from an edge is the least of those from the
// edge's ends and, where its projection falls on the edge, from the edge's line. Where none of
// these has a minimum inside the step (the line's distance keeping its sign, and off the line by
// more than its rounding at the step's ends, so the point is on no edge there), no edge's distance
// has, so it never reaches the boundary: outside at the step's start (which claims() asks last,
// the dearest to ask), the clearance is least at an end.
bool PivotSweep::point_claim(const ThetaStep& step, const Point& point) const {
  for (const Sinusoid& corner : corners(point)) {
    if (step.holds_minimum(corner)) return false;
  }
  const double off = kSeatLineMargin * system_->length_scale();
  for (const Sinusoid& line : lines(point)) {
    const double at_lo = line.at(step.lo()), at_hi = line.at(step.hi());
    const bool above = at_lo > off && at_hi > off, below = at_lo < -off && at_hi < -off;
    if (!(above || below) || step.holds_minimum(above ? line : -line)) return false;
  }
  return true;
}

bool PivotSweep::claims_point(const ThetaStep& step, double lo, double hi, Point& point,
                              double theta_end, SineCosine end_turn) const {
  if (lo >= point.claimed_lo && hi <= point.claimed_hi) return true;
  if (!point_claim(step, point)) return false;
  set_claimed_range(point, theta_end, end_turn);
  return true;
}

// A sinusoid's slope and value move by at most |a| + |b| times the tilt's change: within `reach`
// of theta, each of the point's sinusoids keeps its slope's sign (so neither it nor its negation
// has a minimum there) and each line's value its side of the line beyond the line's margin
// (kSeatLineMargin R) and the value's rounding (far less than kGeometryRounding of its terms).
// A step inside the range set about theta finds what point_claim finds there: no minimum, and
// each line on one side at both ends. A rocking block's steps mostly lie within the last one's.
void PivotSweep::set_claimed_range(Point& point, double theta, SineCosine turn) const {
  const double off = kSeatLineMargin * system_->length_scale();
  double reach = std::numeric_limits<double>::infinity();
  for (const Sinusoid& corner : corners(point)) {
    reach = std::min(reach, slope_sign_reach(corner, turn));
  }
  for (const Sinusoid& line : lines(point)) {
    const double swing = std::abs(line.a) + std::abs(line.b);
    reach = std::min(reach, slope_sign_reach(line, turn));
    const double beyond =
        std::abs(line.at(turn)) - off - kGeometryRounding * (std::abs(line.c) + swing);
    if (swing > 0) reach = std::min(reach, beyond / swing);
    // A line parallel to the point's circle: its value never moves, and is beyond the margin.
    if (swing == 0 && !(beyond > 0)) reach = -std::numeric_limits<double>::infinity();
  }
  set_range_about(theta, reach, point.claimed_lo, point.claimed_hi);
}

namespace {

// A sinusoid a cos(theta) + b sin(theta), not constant, has its minima at atan2(-b, -a) + 2 pi k:
// whether one lies in [lo, hi] widened by kThetaStepMarginRad (far more than atan2's rounding).
bool minimum_within(double a, double b, double lo, double hi) {
  constexpr double kTurn = 2.0 * std::numbers::pi;
  const double least = std::atan2(-b, -a);
  const double first_after = least + kTurn * std::ceil((lo - kThetaStepMarginRad - least) / kTurn);
  return first_after <= hi + kThetaStepMarginRad;
}

}  // namespace

// The slipping vertex (the chart's `body`) stays on its segment's line, at p(s) = origin + s d +
// offset n: the centre of mass is at p(s) - Rot(theta) body, and another vertex, w = v - body from
// it in the body frame, at p(s) + Rot(theta) w. Their x are p(s).x, linear in the place s, within
// |body| or |w| (bounded by the sum of their coordinates' sizes): with s moving one way, within
// that of its range over the step. A vertex's height over the slip's own line is p(s)'s (its
// constant offset) plus (w.y - m w.x) cos(theta) + (w.x + m w.y) sin(theta) for the line's slope
// m, a sinusoid of theta alone: with theta moving one way and no minimum of it between the step's
// tilts, it is least at the step's ends. Over another segment's line its height moves with s too:
// not claimed.
GuardClaims SeatSystem::slip_claims(const SlipChart& chart, const OdeState<SlipChart::N>& q0,
                                    const OdeState<SlipChart::N>& q1, SlipMoves moves,
                                    const GuardClaims& asked) const {
  GuardClaims claims = unused_guards();
  claim_contact_guards(moves.place, moves.rate, claims);
  if (!moves.theta || !moves.place) return claims;
  const SeatLine& line = chart.line;
  const auto place_x = [&](double s) {
    return chart.origin.x + s * line.direction.x + line.offset * line.normal.x;
  };
  const double x0 = place_x(q0[2]), x1 = place_x(q1[2]);
  const double x_lo = std::min(x0, x1), x_hi = std::max(x0, x1);
  if (asked[0] || asked[1]) {
    const double reach = std::abs(chart.body.x) + std::abs(chart.body.y);
    claim_overturn_and_fall(x_lo - reach, x_hi + reach, true, false, claims);
  }
  const int seat = active_[0].pair.seat;
  const Vec2 a = c_.contacts->seat_point(seat), b = c_.contacts->seat_point(seat + 1);
  // A segment that does not run left to right is never asked (clearance_least_at_ends).
  const double m = b.x > a.x ? (b.y - a.y) / (b.x - a.x) : 0.0;
  const double lo = std::min(q0[0], q1[0]), hi = std::max(q0[0], q1[0]);
  auto g = static_cast<std::size_t>(kFirstClearanceGuard);
  for (const int i : watched_vertices_) {
    if (asked[g]) {
      const Vec2 v = c_.contacts->body_vertex(i);
      const Vec2 w{v.x - chart.body.x, v.y - chart.body.y};
      const double reach = std::abs(w.x) + std::abs(w.y);
      claims[g] = clearance_least_at_ends(x_lo - reach, x_hi + reach, [&](int k) {
        return k == seat && !minimum_within(w.y - m * w.x, w.x + m * w.y, lo, hi);
      });
    }
    ++g;
  }
  return claims;
}

// Sliding, every vertex moves along the line by the same amount: its height over a segment is
// linear in the place, and the least of such heights over a valley is concave in it. A seat point's
// distance from a moving edge is convex in the place, and can be least inside: not claimed.
GuardClaims SeatSystem::slide_claims(const BlockState& s0, const BlockState& s1, bool place_one_way,
                                     bool rate_one_way, bool forces_one_way,
                                     const GuardClaims& asked) const {
  GuardClaims claims = unused_guards();
  claim_contact_guards(place_one_way, rate_one_way, claims);
  if (forces_one_way) claim_lift_offs(claims);
  if (!place_one_way) return claims;
  claim_overturn_and_fall(std::min(s0.x, s1.x), std::max(s0.x, s1.x), true, true, claims);
  auto g = static_cast<std::size_t>(kFirstClearanceGuard);
  for (const int i : watched_vertices_) {
    if (asked[g]) {
      const double x0 = c_.contacts->vertex_at(i, s0).x, x1 = c_.contacts->vertex_at(i, s1).x;
      claims[g] =
          clearance_least_at_ends(std::min(x0, x1), std::max(x0, x1), [](int) { return true; });
    }
    ++g;
  }
  return claims;
}

GuardClaims SeatSystem::free_claims(double x0, double x1, bool x_one_way,
                                    bool theta_one_way) const {
  GuardClaims claims = unused_guards();
  if (x_one_way) {
    claim_overturn_and_fall(std::min(x0, x1), std::max(x0, x1), theta_one_way, false, claims);
  }
  return claims;
}

}  // namespace blockfrag
