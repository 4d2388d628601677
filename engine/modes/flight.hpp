// Free flight in closed form: theta and y do not feel the horizontal ground motion, so where the
// block is and when a corner lands need no integration.
#pragma once

#include <optional>

#include "engine/scene/block_geometry.hpp"
#include "engine/scene/block_state.hpp"

namespace blockfrag {

struct FlightStart {
  double y, theta, vy, omega;
};

inline BlockState flight_pose(const FlightStart& f, double g, double tau) {
  BlockState s;
  s.y = f.y + f.vy * tau - 0.5 * g * tau * tau;
  s.vy = f.vy - g * tau;
  s.theta = f.theta + f.omega * tau;
  s.omega = f.omega;
  return s;
}

// The first tau in (0, tau_max] at which a corner reaches the ground moving down, if any.
// Conservative advancement: a corner's height has |h''| <= g + omega^2 R, so a step that keeps
// h + h' dt - K dt^2 / 2 >= 0 cannot skip a touchdown; steps shorter than min_step are taken as
// min_step, so a graze shallower than K min_step^2 / 8 may go unseen. A block turning slower than
// sqrt(g / R) has every corner's height concave (h'' <= -(g - omega^2 R) < 0), which brackets a
// corner's landing from any sample above the ground: no advancement, and no graze missed.
std::optional<double> first_landing(BlockGeometry& geometry, const FlightStart& f, double g,
                                    double tau_max, double min_step);

// How far a flight from `start` at t0 is searched for its landing and its overturning: to t_stop,
// or, when the stretch ends the run (`ends_run`), to where the centre of mass would reach the
// ground in free fall (a corner lands before that). Where a run ends then cannot move a landing
// it reaches, and a run past the settle time gives the settled run's summary.
double flight_horizon(const FlightStart& start, double g, double t0, double t_stop, bool ends_run);

// Where a flight from `start` at t0 ends (by t_stop): where it lands or reaches the overturning
// tilt, and whether it ends overturned or landed there. Heights are from the ground's level.
struct FlightEnd {
  double t;
  bool overturns, lands;
};
FlightEnd flight_end(BlockGeometry& geometry, const FlightStart& start, double g, double t0,
                     double t_stop, bool ends_run, double min_step);

}  // namespace blockfrag
