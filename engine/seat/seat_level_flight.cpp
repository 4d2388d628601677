// A flight over a level seat, clear of its ends, is the flat ground's flight: its landing is a
// corner's, found in closed form (engine/modes/flight.hpp) in place of watching every vertex's and
// point's guard at samples inside each step, which was three quarters of the example study's
// engine time on a flat seat. Its landing is a block vertex's touch, as on_event reports one: no
// seat point can reach the block, and no vertex pass under an end.
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "engine/modes/flight.hpp"
#include "engine/seat/closed_form_flight.hpp"
#include "engine/seat/seat_ground.hpp"
#include "engine/tolerances.hpp"

namespace blockfrag {

std::optional<SeatSimulation::EventReport> SeatSimulation::fly_over_level_seat(
    const FlightChart& chart, MotionPiece& piece, double t_stop) {
  if (!level_) return std::nullopt;
  const double g = scene_.g;
  const double t0 = t_;
  const FlightStart start{state_.y - *level_, state_.theta, state_.vy, state_.omega};
  const bool ends_run = t_stop >= run_end_;
  // How far the centre of mass can drift along x while the landing is looked for: x'' is the
  // ground's acceleration, at most its largest over the piece.
  const double horizon = flight_horizon(start, g, t0, t_stop, ends_run) - t0;
  const double drift =
      std::abs(state_.vx) * horizon + 0.5 * g * piece.max_abs_lambda() * horizon * horizon;
  // Inside the ends by more than a contact's drift, no end point can touch the block's edges and
  // no vertex can pass under an end: the seat is the flat ground.
  if (!(horizon < std::numeric_limits<double>::infinity()) ||
      !contacts_.inside_ends_drifting(state_.x, drift, kSeatContactDrift * R_)) {
    return std::nullopt;
  }
  const FlightEnd ends =
      flight_end(geometry_, start, g, t0, t_stop, ends_run, kFlightMinStep * block_time_);
  const ClosedFormFlight flight(chart.coordinates(state_), state_, piece, t0, g);
  const BlockState end = chart.full(ends.t, flight.dense(ends.t));
  observe_flight(
      t0, ends.t, [&](double t) { return t == ends.t ? end : chart.full(t, flight.dense(t)); },
      piece);
  // Over a level seat the deepest point is the lowest vertex (SeatContacts::penetration).
  deepest_ = std::max(deepest_, -lowest_clearance(end));
  EventReport report;
  if (ends.lands) {
    report.by_event = true;
    report.touching = touching(end, report);
  }
  if (ends.overturns || (ends.lands && lies_overturned_on_level(end, *report.touching))) {
    stop_at(ends.t, end, SeatEvent::overturns);
    return EventReport{};
  }
  t_ = ends.t;
  state_ = end;
  return report;
}

bool SeatSimulation::lies_overturned_on_level(const BlockState& s,
                                              const std::vector<SeatPair>& touching) const {
  // Each touching vertex is put back on the seat from at most the touching tolerance away: alone,
  // that turns the block by at most the tolerance over twice its radius of gyration (the least
  // kinetic change); two of them, by at most twice the tolerance over their distance apart. Twice
  // these bounds from overturning, the projection is not needed to know the block stands.
  const double tolerance = kSeatContactDrift * R_;
  double turn = tolerance / (2.0 * std::sqrt(geometry_.inertia_per_mass()));
  for (std::size_t i = 0; i < touching.size(); ++i) {
    const Vec2 a = contacts_.vertex_at(touching[i].block, s);
    for (std::size_t j = i + 1; j < touching.size(); ++j) {
      const double apart = std::abs(contacts_.vertex_at(touching[j].block, s).x - a.x);
      if (!(apart > kGeometryRounding * R_)) return lies_overturned(s, touching);
      turn += 2.0 * tolerance / apart;
    }
  }
  if (contacts_.overturn_margin(geometry_, s.theta) > kContactHeight + 2.0 * turn) return false;
  return lies_overturned(s, touching);
}

double SeatSimulation::lowest_clearance(const BlockState& s) const {
  double lowest = std::numeric_limits<double>::infinity();
  for (int i = 0; i < contacts_.vertex_count(); ++i) {
    lowest = std::min(lowest, contacts_.clearance_at(contacts_.vertex_at(i, s)));
  }
  return lowest;
}

}  // namespace blockfrag
