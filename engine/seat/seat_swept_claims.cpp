// Which watched clearances a step in flight cannot bring to zero (SeatSystem::claim_swept_clear):
// bounds on how far the block's vertices move over the step's dense output, against the seat's
// height under them or a seat point's distance from the block at the step's start.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

#include "engine/seat/seat_system.hpp"
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
bool SeatSystem::stays_clear_of_seat(Vec2 p, double reach_x, double reach_y) const {
  const SeatContacts& seat = *c_.contacts;
  const int last = seat.point_count() - 1;
  const double x_lo = p.x - reach_x, x_hi = p.x + reach_x, y_lo = p.y - reach_y;
  const double rounding =
      kGeometryRounding * (length_scale() + std::abs(p.x) + std::abs(p.y) + reach_x + reach_y);
  const Vec2 first = seat.seat_point(0), end = seat.seat_point(last);
  // Beyond an end, every corner of the box's part there is past the end segment's end.
  const auto beyond = [&](int segment, Vec2 at, double from_x, double to_x, double sign) {
    const Vec2 d = seat.segment_line(segment).direction;
    const bool leans = sign * d.y > 0;
    const double past = std::min(sign * (d.x * (from_x - at.x) + d.y * (y_lo - at.y)),
                                 sign * (d.x * (to_x - at.x) + d.y * (y_lo - at.y)));
    const double past_top = std::min(sign * (d.x * (from_x - at.x) + d.y * (p.y + reach_y - at.y)),
                                     sign * (d.x * (to_x - at.x) + d.y * (p.y + reach_y - at.y)));
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

// A vertex at body distance r from the centre moves by at most r |dtheta| as the block turns, on
// top of its centre's move. A seat point at distance d outside the block at the step's start stays
// outside while no point of the block moves by d or more (a lower bound on its distance where it
// is far: point_clearance_within).
void SeatSystem::claim_swept_clear(const SweptMotion& swept,
                                   const std::array<double, kGuards>& at_start,
                                   const GuardClaims& asked, GuardClaims& claims) const {
  const SeatContacts& seat = *c_.contacts;
  const double R = length_scale();
  std::array<Vec2, kMaxSeatClearances> world;  // the first vertex_count() set here
  seat.world_vertices(swept.start, world);
  auto g = static_cast<std::size_t>(kFirstClearanceGuard);
  for (const int i : watched_vertices_) {
    if (asked[g]) {
      const double turn = swept_norm(seat.body_vertex(i)) * swept.dtheta;
      claims[g] =
          stays_clear_of_seat(world[static_cast<std::size_t>(i)], swept.dx + turn, swept.dy + turn);
    }
    ++g;
  }
  if (watched_points_.empty()) return;
  double radius = 0.0;
  for (int i = 0; i < seat.vertex_count(); ++i) {
    radius = std::max(radius, swept_norm(seat.body_vertex(i)));
  }
  const double moves = std::hypot(swept.dx, swept.dy) + radius * swept.dtheta;
  const double rounding =
      kGeometryRounding * (R + std::abs(swept.start.x) + std::abs(swept.start.y));
  for (std::size_t k = 0; k < watched_points_.size(); ++k, ++g) {
    if (asked[g]) claims[g] = at_start[g] * R > moves + rounding;
  }
}

}  // namespace blockfrag
