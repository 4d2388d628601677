// A flight over a level seat, clear of its ends, is the flat ground's flight: its landing is a
// corner's, found in closed form (engine/modes/flight.hpp) in place of watching every vertex's and
// point's guard at samples inside each step, which was three quarters of the example study's
// engine time on a flat seat.
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
    const SeatOde<FlightChart>& ode, MotionPiece& piece, double t_stop) {
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
  const ClosedFormFlight flight(ode.coordinates(state_), state_, piece, t0, g);
  const BlockState end = ode.full(ends.t, flight.dense(ends.t));
  observe_flight(
      t0, ends.t, [&](double t) { return t == ends.t ? end : ode.full(t, flight.dense(t)); },
      piece);
  // Over a level seat the deepest point is the lowest vertex (SeatContacts::penetration).
  const LowestVertex lowest = lowest_vertex(ode.system(), end);
  deepest_ = std::max(deepest_, -lowest.clearance);
  if (ends.overturns) {
    stop_at(ends.t, end, SeatEvent::overturns);
    return EventReport{};
  }
  if (ends.lands) return on_event(ode, lowest.guard, ends.t, end);
  t_ = ends.t;
  state_ = end;
  return EventReport{};
}

SeatSimulation::LowestVertex SeatSimulation::lowest_vertex(const SeatSystem& system,
                                                           const BlockState& s) const {
  LowestVertex lowest{-1, std::numeric_limits<double>::infinity()};
  int guard = kFirstClearanceGuard;
  for (const int i : system.watched_vertices()) {
    const double clearance = contacts_.clearance_at(contacts_.vertex_at(i, s));
    if (clearance < lowest.clearance) lowest = {guard, clearance};
    ++guard;
  }
  return lowest;
}

}  // namespace blockfrag
