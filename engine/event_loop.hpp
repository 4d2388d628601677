// The one event loop every ground runs: integrate to the next event, locate it, resolve it, log
// the mode, check the budgets. A ground (the flat ground, engine/simulate.cpp; a seat,
// engine/seat/seat_simulation.cpp) derives from EventLoop<Ground> and supplies only what differs:
// where the block starts, its contact resolution at an event, the systems its contact sets
// integrate, rest's range, and what its events do.
//
// What a Ground supplies (called through the derived class, so no call goes through a virtual
// function):
//   struct EventReport;                    // what ended a stretch: ended_by_event(), and what the
//                                          // resolution at the event needs to know of it
//   void place_at_start();                 // state_ at t = 0
//   void resolve_and_enter(const EventReport&);  // resolves the contact at t_, enters its mode
//   EventReport advance(MotionPiece&, double t_stop);  // the mode to an event or t_stop
//   bool holds_under(MotionPiece&);  // the mode goes on under the next piece
//   bool at_rest() const;                  // the block rests
//   void observe(const BlockState&);       // a state the run passed through
//   ContactForces forces_now() const;      // the contact forces at t_ (per unit mass)
//   ModeKind mode_kind_now() const;
//   void finish_summary();                 // the ground's own summary fields
//   and, for integrate_with: refine_crossing, note_contact_violation, stepped and on_event (which
//   returns the EventReport of a guard's crossing); optionally watch_at_piece_start (the guard
//   watch at a stretch's start) and ended_piece (the guards at the end of a stretch that reached
//   its piece's end, at state_).
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "engine/errors.hpp"
#include "engine/integrate/guard_crossing.hpp"
#include "engine/integrate/root_finding.hpp"
#include "engine/modes/modes.hpp"
#include "engine/motion/scene_motion.hpp"
#include "engine/no_progress.hpp"
#include "engine/segment_observer.hpp"
#include "engine/simulate.hpp"
#include "engine/tolerances.hpp"
#include "engine/water/block_statics.hpp"

namespace blockfrag {

template <class Ground>
class EventLoop {
 public:
  void run();
  // Also called when the scene fails: the summary then tells where it stopped.
  void finish();
  Summary& summary() { return summary_; }
  std::vector<HistoryRow>& history() { return observer_.history(); }
  std::vector<ImpactRecord>& impact_log() { return impact_log_; }

 protected:
  EventLoop(const Scene& scene, double output_interval)
      : scene_(scene),
        geometry_(scene_geometry(scene)),
        motion_(scene_motion(scene)),
        vertical_(scene_vertical_motion(scene)),
        excitation_end_(std::max(motion_.end_of_motion(), vertical_.end_of_motion())),
        block_time_(std::sqrt(geometry_.size() / scene.g)),
        observer_(summary_, geometry_, output_interval, scene.g),
        log_impacts_(output_interval > 0) {}

  Ground& self() { return static_cast<Ground&>(*this); }
  const Ground& self() const { return static_cast<const Ground&>(*this); }

  // At rest with every excitation over: nothing can move the block again.
  bool at_rest_for_good() const { return self().at_rest() && t_ >= excitation_end_; }
  void check_budget() const;
  double step_cap(MotionPiece& piece);
  // A mode of kind `now` entered at t_ from one of kind `before` (`first`: the run's first):
  // counts the event, logs the mode (again, where `restarts` though its kind is unchanged) and
  // the onsets, observes the state and checks the budgets.
  void entered(ModeKind before, ModeKind now, bool first, bool restarts);
  // Rest: the block does not move; rest ends where margin(t) falls below zero, looked for at
  // lambda's extremes and, with vertical motion, at samples (unless it holds throughout the
  // piece). Returns whether rest ended before t_stop; t_ is left where it ended.
  template <class Margin, class ForcesAt>
  bool advance_rest(MotionPiece& piece, double t_stop, bool holds_throughout, const Margin& margin,
                    const ForcesAt& forces_at);
  // A flight from t0 to t_end in closed form (pose(t)), seen by the observer in equal parts no
  // longer than an integrator's step could be, so that it finds where x turns inside the flight as
  // it does in the other modes.
  template <class Pose>
  void observe_flight(double t0, double t_end, const Pose& pose, MotionPiece& piece);
  // Steps until a guard crosses zero or t_stop; a crossing is located on the dense output and the
  // state is left just after it, where the next mode's conditions hold (the ground's on_event).
  // Returns the Ground::EventReport of what ended the stretch (none at t_stop).
  template <class Ode, class Stepper>
  auto integrate_with(const Ode& ode, Stepper& stepper, MotionPiece& piece, double t_stop,
                      ModeKind kind);
  // integrate_with's steps: the stepper's work since it last counted, into the summary; the
  // first guard crossing in the step from (t0, q0) to (t, q), placed by the ground.
  // The guard watch at a stretch's start: the ground's where it gives one (watch_at_piece_start).
  template <class Ode>
  GuardWatch<Ode::kGuards> watch_at_start(const Ode& ode, double t, const OdeState<Ode::N>& q);
  template <class Stepper>
  void count_stepper_work(Stepper& stepper, long& steps_counted, long& rhs_counted);
  template <class Ode, class Stepper, class StateAt, class Q, class Guards>
  auto crossing_in_step(const Ode& ode, Stepper& stepper, GuardWatch<Ode::kGuards>& watch,
                        const StateAt& state_at, double t0, double t, const Q& q0, const Q& q,
                        const Guards& next, ModeKind kind);

  const Scene& scene_;
  BlockGeometry geometry_;
  GroundMotionPieces motion_;
  GroundMotionPieces vertical_;  // lambda_v; zero throughout when the scene has none
  // s: the ground, the vertical motion and the dam crest are still after it
  double excitation_end_;
  double block_time_;  // s: sqrt(R/g), asked for at every step cap
  Summary summary_;
  SegmentObserver observer_;
  double t_ = 0.0;
  BlockState state_;
  bool stopped_ = false;
  double rest_since_ = 0.0;  // when the block last came to rest
  double run_end_ = 0.0;     // where the run stops at the latest
  NoProgressGuard no_progress_;
  bool log_impacts_;
  std::vector<ImpactRecord> impact_log_;
};

// Runs the simulation to its end; a SimulationFailure becomes the summary's status.
template <class Simulation>
SimulationWithHistory run_to_end(Simulation& simulation) {
  try {
    simulation.run();
  } catch (const SimulationFailure& failure) {
    simulation.summary().status = Status::failed;
    simulation.summary().status_reason = failure.what();
    simulation.finish();
  }
  return {std::move(simulation.summary()), std::move(simulation.history()),
          std::move(simulation.impact_log())};
}

template <class Ground>
void EventLoop<Ground>::run() {
  Ground& ground = self();
  ground.place_at_start();
  observer_.start(state_);
  ground.resolve_and_enter(typename Ground::EventReport{});
  run_end_ = run_end_time(scene_, motion_, vertical_);
  const double t_end = run_end_;
  while (!stopped_ && t_ < t_end) {
    // Settling: once every excitation is over, a block at rest stays at rest.
    if (!scene_.duration && at_rest_for_good()) break;
    MotionPiece& piece = motion_.piece_at(t_);
    const double t_stop = std::min({t_end, piece.end(), vertical_.piece_at(t_).end()});
    const auto report = ground.advance(piece, t_stop);
    if (stopped_ || t_ >= t_end) break;
    no_progress_.count_event(t_);
    if (report.ended_by_event()) no_progress_.count_pose(t_, state_);
    // A piece boundary is not an event: a mode whose contact forces still hold under the next
    // piece goes on. Re-resolving there would lay a block that has only just lifted flat again
    // (its corners are still slower than the settling speed), so a finely tabulated motion
    // could never start it rocking.
    const bool at_piece_end = t_ == t_stop && !report.ended_by_event();
    if (at_piece_end && ground.holds_under(motion_.piece_at(t_))) continue;
    ground.resolve_and_enter(report);
  }
  finish();
}

template <class Ground>
void EventLoop<Ground>::finish() {
  summary_.end_time = t_;
  summary_.settled =
      summary_.status == Status::ok && (summary_.overturned || summary_.fell || at_rest_for_good());
  if (summary_.overturned) {
    summary_.settle_time = summary_.overturn_time;
  } else if (summary_.fell) {
    summary_.settle_time = summary_.fell_time;
  } else if (summary_.settled) {
    summary_.settle_time = rest_since_;
  }
  summary_.final_theta = state_.theta;
  summary_.final_slide = state_.x - observer_.x0();
  if (scene_.reservoir) {
    const bool standing = summary_.status == Status::ok && !summary_.overturned && !summary_.fell &&
                          self().mode_kind_now() == ModeKind::rest;
    summary_.post_earthquake = post_earthquake_check(scene_, state_, standing);
  }
  self().finish_summary();
  observer_.finish(t_, state_, self().forces_now(), self().mode_kind_now());
}

template <class Ground>
void EventLoop<Ground>::check_budget() const {
  const SolverSettings& solver = scene_.solver;
  if (summary_.steps > solver.max_steps) {
    throw SimulationFailure("step budget exceeded (" + std::to_string(solver.max_steps) +
                            " steps)");
  }
  if (summary_.events > solver.max_events) {
    throw SimulationFailure("event budget exceeded (" + std::to_string(solver.max_events) +
                            " events): the contact state keeps changing");
  }
}

template <class Ground>
double EventLoop<Ground>::step_cap(MotionPiece& piece) {
  return std::min({kMaxStepOverBlockTime * block_time_,
                   piece.time_scale() / kStepsPerPieceTimeScale,
                   vertical_.piece_at(t_).time_scale() / kStepsPerPieceTimeScale});
}

template <class Ground>
void EventLoop<Ground>::entered(ModeKind before, ModeKind now, bool first, bool restarts) {
  ++summary_.events;
  if (now == ModeKind::rest && (first || before != ModeKind::rest)) rest_since_ = t_;
  if (first || now != before || restarts) summary_.modes.push_back({t_, now});
  if ((now == ModeKind::rock || now == ModeKind::slide_rock) && !summary_.rock_start_time) {
    summary_.rock_start_time = t_;
  }
  if ((now == ModeKind::slide || now == ModeKind::slide_rock) && !summary_.slide_start_time) {
    summary_.slide_start_time = t_;
  }
  self().observe(state_);
  check_budget();
}

// The exit is placed where lambda is past a threshold by kOnsetMargin, so the modes it leads to
// see an unambiguous sign; a pulse that only grazes a threshold leaves the block at rest.
template <class Ground>
template <class Margin, class ForcesAt>
bool EventLoop<Ground>::advance_rest(MotionPiece& piece, double t_stop, bool holds_throughout,
                                     const Margin& margin, const ForcesAt& forces_at) {
  const BlockState s = state_;
  const auto state_at = [&](double) { return s; };
  if (holds_throughout) {
    observer_.observe_step(t_, t_stop, state_at, forces_at, ModeKind::rest);
    t_ = t_stop;
    return false;
  }
  // Without vertical motion rest's margin depends on lambda alone, so its extremes and the stop
  // time are the only places to look; with it, the sum of the two is also sampled at 1/64 of the
  // faster one's time scale.
  MotionPiece& vertical = vertical_.piece_at(t_);
  std::vector<double> checks = piece.extrema_between(t_, t_stop);
  if (!vertical.is_zero()) {
    const std::vector<double> more = vertical.extrema_between(t_, t_stop);
    checks.insert(checks.end(), more.begin(), more.end());
    const double spacing =
        std::min(piece.time_scale(), vertical.time_scale()) / kRestChecksPerTimeScale;
    if (std::isfinite(spacing)) {
      for (double t = t_ + spacing; t < t_stop; t += spacing) checks.push_back(t);
    }
    std::sort(checks.begin(), checks.end());
  }
  double previous = t_;
  double previous_margin = margin(t_);
  // Whether rest ends by t, the checks asked in increasing order; where it does, t_ is its end.
  const auto ends_by = [&](double t) {
    const double m = margin(t);
    if (m < 0) {
      const double t_event =
          previous_margin < 0
              ? previous
              : locate_crossing(margin, previous, t,
                                std::max(previous_margin, std::numeric_limits<double>::min()), m,
                                kEventTimeTolerance * (1.0 + t))
                    .after;
      observer_.observe_step(t_, t_event, state_at, forces_at, ModeKind::rest);
      t_ = t_event;
      return true;
    }
    previous = t;
    previous_margin = m;
    return false;
  };
  for (const double t : checks) {
    if (ends_by(t)) return true;
  }
  // The stop time last, not added to the checks: that was an allocation at each of a record's
  // samples the block rests through.
  if (ends_by(t_stop)) return true;
  observer_.observe_step(t_, t_stop, state_at, forces_at, ModeKind::rest);
  t_ = t_stop;
  return false;
}

// Out of line: inlined into the flat ground's flight, it took GCC's inlining budget for
// engine/simulate.cpp from the rocking block's steps (RockSystem::full called, not inlined: the
// type A block's scene took 1.3 % more instructions).
template <class Ground>
template <class Pose>
[[gnu::noinline]] void EventLoop<Ground>::observe_flight(double t0, double t_end, const Pose& pose,
                                                         MotionPiece& piece) {
  if (reached(t0, t_end)) return;
  const auto forces_at = [](double) { return ContactForces{0.0, 0.0}; };
  const double parts = std::ceil((t_end - t0) / step_cap(piece));
  double from = t0;
  for (double k = 1.0; k <= parts; k += 1.0) {
    const double to = k == parts ? t_end : t0 + (t_end - t0) * (k / parts);
    observer_.observe_step(from, to, pose, forces_at, ModeKind::flight);
    from = to;
  }
}

// Guard i of a system at (t, q): alone where the system computes one alone (guard()).
template <class Ode>
double ode_guard(const Ode& ode, int i, double t, const OdeState<Ode::N>& q) {
  if constexpr (requires { ode.guard(i, t, q); }) {
    return ode.guard(i, t, q);
  } else {
    return ode.guards(t, q)[static_cast<std::size_t>(i)];
  }
}

// The guards `wanted` names of a system at (t, q) (the others unset), where the system computes
// some alone; else all of them.
template <class Ode>
std::array<double, Ode::kGuards> ode_guards(const Ode& ode, double t, const OdeState<Ode::N>& q,
                                            const std::array<bool, Ode::kGuards>& wanted) {
  if constexpr (requires { ode.guards(t, q, wanted); }) {
    return ode.guards(t, q, wanted);
  } else {
    return ode.guards(t, q);
  }
}

// Lambdas taken as one callable, each call going to the one it fits.
template <class... Calls>
struct Overloads : Calls... {
  using Calls::operator()...;
};
template <class... Calls>
Overloads(Calls...) -> Overloads<Calls...>;

// A system that leaves some of its guard slots unused names the others (live_slots(), in order,
// or live_guards()).
template <class Ode>
GuardWatch<Ode::kGuards> watch_guards(const Ode& ode, double t, const OdeState<Ode::N>& q) {
  if constexpr (requires { ode.live_slots(); }) {
    return GuardWatch<Ode::kGuards>(ode.guards(t, q), ode.live_slots());
  } else if constexpr (requires { ode.live_guards(); }) {
    return GuardWatch<Ode::kGuards>(ode.guards(t, q), ode.live_guards());
  } else {
    return GuardWatch<Ode::kGuards>(ode.guards(t, q));
  }
}

template <class Ground>
template <class Ode>
GuardWatch<Ode::kGuards> EventLoop<Ground>::watch_at_start(const Ode& ode, double t,
                                                           const OdeState<Ode::N>& q) {
  if constexpr (requires { self().watch_at_piece_start(ode, t, q); }) {
    return self().watch_at_piece_start(ode, t, q);
  } else {
    return watch_guards(ode, t, q);
  }
}

template <class Ground>
template <class Stepper>
void EventLoop<Ground>::count_stepper_work(Stepper& stepper, long& steps_counted,
                                           long& rhs_counted) {
  summary_.steps += stepper.steps() - steps_counted;
  summary_.rhs_evaluations += stepper.rhs_evaluations() - rhs_counted;
  steps_counted = stepper.steps();
  rhs_counted = stepper.rhs_evaluations();
  if ((summary_.steps & kBudgetCheckMask) == 0) check_budget();
}

template <class Ground>
template <class Ode, class Stepper, class StateAt, class Q, class Guards>
auto EventLoop<Ground>::crossing_in_step(const Ode& ode, Stepper& stepper,
                                         GuardWatch<Ode::kGuards>& watch, const StateAt& state_at,
                                         double t0, double t, const Q& q0, const Q& q,
                                         const Guards& next, ModeKind kind) {
  const Overloads guards_at{[&](double x) { return ode.guards(x, stepper.dense(x)); },
                            [&](int i, double x) { return ode_guard(ode, i, x, stepper.dense(x)); },
                            [&](double x, const std::array<bool, Ode::kGuards>& wanted) {
                              return ode_guards(ode, x, stepper.dense(x), wanted);
                            }};
  const auto least_at_ends = [&](const std::array<bool, Ode::kGuards>& asked) {
    const auto one_way = [&](int i) { return stepper.moves_one_way(i); };
    if constexpr (requires {
                    ode.guard_claims(t0, t, q0, q, one_way, watch.values(), next, asked);
                  }) {
      auto claims = ode.guard_claims(t0, t, q0, q, one_way, watch.values(), next, asked);
      // In flight nothing else claims the clearances: those the step cannot bring to zero.
      if constexpr (requires { stepper.dense_spread(0); }) {
        const auto spread = [&](int i) { return stepper.dense_spread(i); };
        if constexpr (requires {
                        ode.claim_swept_clear(t0, t, q0, q, spread, watch.values(), asked, claims);
                      }) {
          ode.claim_swept_clear(t0, t, q0, q, spread, watch.values(), asked, claims);
        }
      }
      return claims;
    } else {
      return ode.least_at_ends(q0, q, one_way);
    }
  };
  return self().refine_crossing(ode, watch, guards_at, state_at, t0, t,
                                watch.first_crossing(guards_at, t0, t, next, least_at_ends), kind);
}

template <class Ground>
template <class Ode, class Stepper>
auto EventLoop<Ground>::integrate_with(const Ode& ode, Stepper& stepper, MotionPiece& piece,
                                       double t_stop, ModeKind kind) {
  using EventReport = typename Ground::EventReport;
  Ground& ground = self();
  auto q = ode.coordinates(state_);
  double t = t_;
  GuardWatch<Ode::kGuards> watch = watch_at_start(ode, t, q);
  const double cap = step_cap(piece);
  const auto forces_at = [&](double x) { return ode.forces(x, stepper.dense(x)); };
  const auto state_at = [&](double x) { return ode.full(x, stepper.dense(x)); };
  long steps_counted = 0, rhs_counted = 0;
  // A fixed step that crosses an event is taken again, ending just past the located event: the
  // step may have run through what ends the mode (near a Painleve pole), so its end and its
  // Hermite interpolant are not the trajectory there. The second location is kept; if the retaken
  // step finds no event, stepping goes on from its end, at least 1/100 of the step further.
  constexpr bool kRetakesStepToEvent = requires { Stepper::kFixedStep; };
  double retake_until = std::numeric_limits<double>::infinity();

  while (!reached(t, t_stop)) {
    const double t0 = t;
    const auto q0 = q;
    const bool retaking = std::isfinite(retake_until);
    stepper.step(ode, t, q, std::min({t_stop - t, cap, retake_until - t}));
    retake_until = std::numeric_limits<double>::infinity();
    if (reached(t, t_stop)) t = t_stop;
    count_stepper_work(stepper, steps_counted, rhs_counted);

    const auto next = ode.guards(t, q);
    const auto crossing = crossing_in_step(ode, stepper, watch, state_at, t0, t, q0, q, next, kind);
    const int which = crossing.which;
    const double t_event = crossing.after;
    if (kRetakesStepToEvent && which >= 0 && !retaking && t_event < t) {
      retake_until = t_event + kRetakeOvershoot * (t - t_event);
      t = t0;
      q = q0;
      continue;
    }
    watch.advance(next);

    // The contact laws at the end of what is kept of the step, inside the mode.
    const double kept = which < 0 ? t : t_event;
    // The states at the kept step's ends, found once: the observer, the contact laws' check (at
    // the end of a step without an event) and the ground's stepped hook each look at them.
    const BlockState at_start = state_at(t0), at_kept = state_at(kept);
    const BlockState at_before =
        std::bit_cast<std::uint64_t>(crossing.before) == std::bit_cast<std::uint64_t>(kept)
            ? at_kept
            : state_at(crossing.before);
    ground.note_contact_violation(ode, crossing.before, at_before, forces_at);
    observer_.observe_step(t0, kept, at_start, at_kept, state_at, forces_at, kind);
    ground.stepped(ode, at_kept);
    if (which < 0) continue;
    return ground.on_event(ode, which, t_event, state_at(t_event));
  }
  t_ = t_stop;
  state_ = ode.full(t, q);
  if constexpr (requires { ground.ended_piece(ode, watch.values()); }) {
    ground.ended_piece(ode, watch.values());
  }
  return EventReport{};
}

}  // namespace blockfrag
