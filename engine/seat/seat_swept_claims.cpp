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

// Over the seat's range (first point included, last excluded) the clearance is the vertex's height
// over the segment under it, whose line lies there at most as high as its higher end: a vertex
// that stays above every segment end reachable in x stays above the seat. Past an end, or at the
// last point's x, the clearance is measured otherwise: not claimed.
bool SeatSystem::stays_above_seat(Vec2 p, double reach_x, double reach_y) const {
  const SeatContacts& seat = *c_.contacts;
  const int last = seat.point_count() - 1;
  const double x_lo = p.x - reach_x, x_hi = p.x + reach_x;
  if (!(x_lo >= seat.seat_point(0).x && x_hi < seat.seat_point(last).x)) return false;
  double highest = -std::numeric_limits<double>::infinity();
  for (int k = 0; k < last; ++k) {
    const Vec2 a = seat.seat_point(k), b = seat.seat_point(k + 1);
    if (std::max(a.x, b.x) < x_lo || std::min(a.x, b.x) > x_hi) continue;
    highest = std::max({highest, a.y, b.y});
  }
  const double rounding =
      kGeometryRounding * (length_scale() + std::abs(p.x) + std::abs(p.y) + std::abs(highest));
  return p.y - reach_y > highest + rounding;
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
          stays_above_seat(world[static_cast<std::size_t>(i)], swept.dx + turn, swept.dy + turn);
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
