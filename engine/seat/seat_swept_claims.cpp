// Which watched clearances a step in flight cannot bring to zero (SeatSystem::claim_swept_clear):
// bounds on how far the block's vertices move over the step's dense output, against the seat's
// height under them or a seat point's distance from the block at the step's start.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

#include "engine/seat/seat_system.hpp"
#include "engine/sine_cosine.hpp"
#include "engine/tolerances.hpp"

namespace blockfrag {

namespace {

double swept_norm(Vec2 v) { return std::sqrt(v.x * v.x + v.y * v.y); }

}  // namespace

// A vertex moving within the box [x_lo, x_hi] x [y_lo, y_hi]. Over the seat's range its clearance
// is its height over the segment under it: positive while the box's bottom is above each segment's
// line wherever the box overlaps it (a line's highest there is at an end of the overlap). Past an
// end it is its distance from the end, positive but where an end segment leaning away from the end
// puts it under that segment (SeatContacts::under_end_segment), which asks that the vertex project
// onto the segment: a box wholly beyond the segment's end along its direction is never there.
bool SeatSystem::stays_clear_of_seat(double x_lo, double x_hi, double y_lo, double y_hi) const {
  const SeatContacts& seat = *c_.contacts;
  const int last = seat.point_count() - 1;
  const double rounding =
      kGeometryRounding * (length_scale() + std::max(std::abs(x_lo), std::abs(x_hi)) +
                           std::max(std::abs(y_lo), std::abs(y_hi)));
  const Vec2 first = seat.seat_point(0), end = seat.seat_point(last);
  // Beyond an end, every corner of the box's part there is past the end segment's end.
  const auto beyond = [&](int segment, Vec2 at, double from_x, double to_x, double sign) {
    const Vec2 d = seat.segment_line(segment).direction;
    const bool leans = sign * d.y > 0;
    const double past = std::min(sign * (d.x * (from_x - at.x) + d.y * (y_lo - at.y)),
                                 sign * (d.x * (to_x - at.x) + d.y * (y_lo - at.y)));
    const double past_top = std::min(sign * (d.x * (from_x - at.x) + d.y * (y_hi - at.y)),
                                     sign * (d.x * (to_x - at.x) + d.y * (y_hi - at.y)));
    return !leans || std::min(past, past_top) > rounding;
  };
  if (x_lo < first.x && !beyond(0, first, x_lo, std::min(x_hi, first.x), -1.0)) return false;
  if (x_hi > end.x && !beyond(last - 1, end, std::max(x_lo, end.x), x_hi, 1.0)) return false;
  for (int k = 0; k < last; ++k) {
    const Vec2 a = seat.seat_point(k), b = seat.seat_point(k + 1);
    const double from = std::max(x_lo, a.x), to = std::min(x_hi, b.x);
    if (from > to) continue;
    const double slope = (b.y - a.y) / (b.x - a.x);
    const double highest = std::max(a.y + slope * (from - a.x), a.y + slope * (to - a.x));
    if (!(y_lo > highest + rounding)) return false;
  }
  return true;
}

// A vertex's offset from the centre, b turned by theta, has components whose second derivative in
// theta is at most |b|: over the tilt's range each strays from the chord between its ends by at
// most |b| (theta_hi - theta_lo)^2 / 8. A seat point at distance d outside the block at the
// step's start stays outside while no point of the block moves by d or more (a lower bound on its
// distance where it is far: point_clearance_within); a point at b from the centre moves by at most
// its centre's move and |b| times the tilt's.
void SeatSystem::claim_swept_clear(const SweptMotion& swept,
                                   const std::array<double, kGuards>& at_start,
                                   const GuardClaims& asked, GuardClaims& claims) const {
  const SeatContacts& seat = *c_.contacts;
  const double R = length_scale();
  const double turn = swept.theta_hi - swept.theta_lo;
  const SineCosine lo = sine_cosine(swept.theta_lo), hi = sine_cosine(swept.theta_hi);
  auto g = static_cast<std::size_t>(kFirstClearanceGuard);
  for (const int i : watched_vertices_) {
    if (asked[g]) {
      const Vec2 b = seat.body_vertex(i);
      const Vec2 a = rotate(b, lo.cos, lo.sin), c = rotate(b, hi.cos, hi.sin);
      const double bend = 0.125 * swept_norm(b) * turn * turn;
      claims[g] = stays_clear_of_seat(
          swept.x_lo + std::min(a.x, c.x) - bend, swept.x_hi + std::max(a.x, c.x) + bend,
          swept.y_lo + std::min(a.y, c.y) - bend, swept.y_hi + std::max(a.y, c.y) + bend);
    }
    ++g;
  }
  if (watched_points_.empty()) return;
  double radius = 0.0;
  for (int i = 0; i < seat.vertex_count(); ++i) {
    radius = std::max(radius, swept_norm(seat.body_vertex(i)));
  }
  const BlockState& s = swept.start;
  const double moves = std::hypot(std::max(swept.x_hi - s.x, s.x - swept.x_lo),
                                  std::max(swept.y_hi - s.y, s.y - swept.y_lo)) +
                       radius * std::max(swept.theta_hi - s.theta, s.theta - swept.theta_lo);
  const double rounding = kGeometryRounding * (R + std::abs(s.x) + std::abs(s.y));
  for (std::size_t k = 0; k < watched_points_.size(); ++k, ++g) {
    if (asked[g]) claims[g] = at_start[g] * R > moves + rounding;
  }
}

}  // namespace blockfrag
