#include "engine/simulate.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <string>
#include <type_traits>

#include "engine/contact/contact_resolution.hpp"
#include "engine/contact/model_choice.hpp"
#include "engine/contact/reduced_contact.hpp"
#include "engine/errors.hpp"
#include "engine/integrate/guard_crossing.hpp"
#include "engine/integrate/root_finding.hpp"
#include "engine/integrate/with_stepper.hpp"
#include "engine/modes/flight.hpp"
#include "engine/modes/modes.hpp"
#include "engine/motion/ground_drift.hpp"
#include "engine/motion/scene_motion.hpp"
#include "engine/scene/scene_validation.hpp"
#include "engine/seat/seat_simulation.hpp"
#include "engine/segment_observer.hpp"
#include "engine/tolerances.hpp"

namespace blockfrag {

namespace {

class Simulation {
 public:
  Simulation(const Scene& scene, double output_interval)
      : scene_(scene),
        geometry_(scene_geometry(scene)),
        motion_(scene_motion(scene)),
        vertical_(scene_vertical_motion(scene)),
        model_(choose_model(scene, motion_, geometry_)),
        block_time_(std::sqrt(geometry_.size() / scene.g)),
        excitation_end_(std::max(motion_.end_of_motion(), vertical_.end_of_motion())),
        resolver_(geometry_, scene.contact, scene.g),
        housner_(geometry_, scene.effects.automatic || scene.effects.impact, scene.g),
        newmark_(geometry_, scene.contact.friction, scene.g),
        observer_(summary_, geometry_, output_interval, scene.g),
        log_impacts_(output_interval > 0) {
    summary_.model = model_;
  }

  void run();
  void finish();
  Summary& summary() { return summary_; }
  std::vector<HistoryRow>& history() { return observer_.history(); }
  std::vector<ImpactRecord>& impact_log() { return impact_log_; }

 private:
  SystemContext context(const MotionPiece& piece) const {
    return {&geometry_, &piece, &vertical_.piece_at(t_), scene_.g, scene_.contact.friction};
  }
  // The one place that says which ODE system integrates the current mode under `piece`: fn gets
  // that system, or the mode itself for rest and for flight without vertical motion (both closed
  // form). Housner's model rocks without the contact-force guards.
  template <class Fn>
  decltype(auto) with_system(const MotionPiece& piece, Fn&& fn) const {
    return std::visit(
        [&](const auto& mode) -> decltype(auto) {
          using M = std::decay_t<decltype(mode)>;
          if constexpr (std::is_same_v<M, SlideMode>) {
            return fn(SlideSystem{context(piece), mode.slip_sign});
          } else if constexpr (std::is_same_v<M, RockMode>) {
            const RockSystem rock{context(piece), mode.pivot, mode.pivot_x};
            return model_ == Model::housner_rocking ? fn(HousnerRockSystem{rock}) : fn(rock);
          } else if constexpr (std::is_same_v<M, SlideRockMode>) {
            return fn(SlideRockSystem{context(piece), mode.pivot, mode.slip_sign});
          } else if constexpr (std::is_same_v<M, FlightMode>) {
            return vertical_.piece_at(t_).is_zero()
                       ? fn(mode)
                       : fn(FlightSystem{context(piece), t_, state_.theta, state_.omega});
          } else {
            static_assert(std::is_same_v<M, RestMode>);
            return fn(mode);
          }
        },
        mode_);
  }
  BlockState initial_state() const;
  // At rest with every excitation over: nothing can move the block again.
  bool at_rest_for_good() const;
  ContactOutcome resolve_contact() const;
  bool mode_holds_under(const MotionPiece& piece) const;
  void enter(const ContactOutcome& outcome);
  void check_budget();
  double step_cap(const MotionPiece& piece) const;
  // How far rest is inside its limits at t (friction and both tipping moments against gravity
  // g (1 + lambda_v), and that gravity positive), in units of g, less kOnsetMargin: rest holds
  // while it is positive.
  double rest_margin(const MotionPiece& piece, const MotionPiece& vertical, double t) const;
  // The |lambda| below which the resting block neither slides nor tips about a corner (at
  // gravity g): Housner's block never slides and Newmark's never tips.
  double rest_friction_limit() const;
  double rest_tip_limit(Corner c) const;
  ContactForces resting_forces(const MotionPiece& piece, double t) const {
    return {-piece.lambda(t) * scene_.g, scene_.g * (1.0 + vertical_.lambda(t))};
  }
  void overturn_at(double t, const BlockState& s);
  ContactForces forces_now() const;

  void advance(const RestMode&, const MotionPiece& piece, double t_stop);
  // Flight without vertical motion: theta, y and x in closed form.
  void advance(const FlightMode&, const MotionPiece& piece, double t_stop);
  template <class System>
  void advance(const System& system, const MotionPiece& piece, double t_stop);
  template <class System, class Stepper>
  void integrate_with(const System& system, Stepper& stepper, const MotionPiece& piece,
                      double t_stop);

  const Scene& scene_;
  BlockGeometry geometry_;
  GroundMotionPieces motion_;
  GroundMotionPieces vertical_;  // lambda_v; zero throughout when the scene has none
  Model model_;
  double block_time_;  // s: sqrt(R/g), asked for at every step cap and flight
  double
      excitation_end_;  // s: the ground, the vertical motion and the dam crest are still after it
  ContactResolver resolver_;
  HousnerRules housner_;
  NewmarkRules newmark_;
  Summary summary_;
  SegmentObserver observer_;
  double t_ = 0.0;
  BlockState state_;
  Mode mode_ = RestMode{};
  bool stopped_ = false;
  std::optional<GuardEvent> last_event_;  // what ended the last integrated stretch, if a guard did
  double rest_since_ = 0.0;               // when the block last came to rest
  double run_end_ = 0.0;                  // where the run stops at the latest
  int stalled_events_ = 0;
  bool log_impacts_;
  std::vector<ImpactRecord> impact_log_;
};

BlockState Simulation::initial_state() const {
  BlockState s;
  s.theta = scene_.initial.theta;
  if (s.theta == 0.0) {
    s.y = geometry_.rest_height();
  } else {
    // Released from rest on the corner that the tilt lowers.
    const Corner pivot = s.theta < 0 ? Corner::right : Corner::left;
    const Vec2 r = geometry_.base_corner_at(pivot, s.theta);
    s.y = -r.y;
  }
  return s;
}

ContactOutcome Simulation::resolve_contact() const {
  const double lambda = motion_.lambda(t_);
  switch (model_) {
    case Model::newmark_sliding: return newmark_.resolve(state_, lambda);
    case Model::housner_rocking:
      if (const auto* rock = std::get_if<RockMode>(&mode_)) {
        if (last_event_ == GuardEvent::corner_lands) {
          return housner_.impact(state_, rock->pivot, lambda);
        }
        ContactOutcome carry_on;
        carry_on.mode = *rock;
        carry_on.state = state_;
        return carry_on;
      }
      return housner_.start(state_, lambda);
    case Model::at_rest:
    case Model::full: break;
    case Model::full_vertical: return resolver_.resolve(state_, lambda, 1.0 + vertical_.lambda(t_));
  }
  return resolver_.resolve(state_, lambda);
}

void Simulation::enter(const ContactOutcome& outcome) {
  ++summary_.events;
  if (outcome.painleve) ++summary_.painleve_events;
  if (outcome.impact) {
    if (log_impacts_) {
      impact_log_.push_back(
          {t_, state_.omega, outcome.state.omega, kinetic_energy_per_mass(geometry_, state_),
           kinetic_energy_per_mass(geometry_, outcome.state), mode_kind(outcome.mode)});
    }
    ++summary_.impacts;
    if (!summary_.first_impact_time) summary_.first_impact_time = t_;
    summary_.max_impact_energy_gain =
        std::max(summary_.max_impact_energy_gain, outcome.impact_energy_gain);
  }
  const bool first = summary_.modes.empty();
  const ModeKind before = mode_kind(mode_);
  if (std::holds_alternative<RestMode>(outcome.mode) && (first || before != ModeKind::rest)) {
    rest_since_ = t_;
  }
  const bool was_rocking =
      std::holds_alternative<RockMode>(mode_) || std::holds_alternative<SlideRockMode>(mode_);
  mode_ = outcome.mode;
  state_ = outcome.state;
  const ModeKind now = mode_kind(mode_);
  if (first || now != before || (was_rocking && outcome.impact)) {
    summary_.modes.push_back({t_, now});
  }
  if ((now == ModeKind::rock || now == ModeKind::slide_rock) && !summary_.rock_start_time) {
    summary_.rock_start_time = t_;
  }
  if ((now == ModeKind::slide || now == ModeKind::slide_rock) && !summary_.slide_start_time) {
    summary_.slide_start_time = t_;
  }
  observer_.observe_state(state_);
  check_budget();
}

void Simulation::check_budget() {
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

double Simulation::step_cap(const MotionPiece& piece) const {
  return std::min({kMaxStepOverBlockTime * block_time_,
                   piece.time_scale() / kStepsPerPieceTimeScale,
                   vertical_.piece_at(t_).time_scale() / kStepsPerPieceTimeScale});
}

void Simulation::overturn_at(double t, const BlockState& s) {
  t_ = t;
  state_ = s;
  state_.theta = geometry_.overturn_theta(s.theta);
  summary_.overturned = true;
  summary_.overturn_time = t;
  observer_.observe_state(state_);
  stopped_ = true;
}

double Simulation::rest_friction_limit() const {
  return model_ == Model::housner_rocking ? std::numeric_limits<double>::infinity()
                                          : scene_.contact.friction;
}

double Simulation::rest_tip_limit(Corner c) const {
  return model_ == Model::newmark_sliding ? std::numeric_limits<double>::infinity()
                                          : geometry_.tip_threshold(c);
}

// The exit is placed where lambda is past a threshold by kOnsetMargin, so the modes it leads to
// see an unambiguous sign; a pulse that only grazes a threshold leaves the block at rest.
double Simulation::rest_margin(const MotionPiece& piece, const MotionPiece& vertical,
                               double t) const {
  const double lambda = piece.lambda(t), factor = 1.0 + vertical.lambda(t);
  return kOnsetMargin + std::min({rest_friction_limit() * factor - std::abs(lambda),
                                  rest_tip_limit(Corner::right) * factor - lambda,
                                  rest_tip_limit(Corner::left) * factor + lambda, factor});
}

void Simulation::advance(const RestMode&, const MotionPiece& piece, double t_stop) {
  const BlockState s = state_;
  const auto state_at = [&](double) { return s; };
  const auto forces_at = [&](double t) { return resting_forces(piece, t); };
  // Without vertical motion rest's margin depends on lambda alone, so its extremes and the stop
  // time are the only places to look; with it, the sum of the two is also sampled at 1/64 of the
  // faster one's time scale.
  const MotionPiece& vertical = vertical_.piece_at(t_);
  const auto margin = [&](double t) { return rest_margin(piece, vertical, t); };
  if (vertical.is_zero() &&
      (piece.is_zero() ||
       piece.max_abs_lambda() <= std::min({rest_friction_limit(), rest_tip_limit(Corner::right),
                                           rest_tip_limit(Corner::left)}) +
                                     kOnsetMargin)) {
    observer_.observe_step(t_, t_stop, state_at, forces_at, ModeKind::rest);
    t_ = t_stop;
    return;
  }
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
  checks.push_back(t_stop);
  double previous = t_;
  double previous_margin = margin(t_);
  for (const double t : checks) {
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
      return;
    }
    previous = t;
    previous_margin = m;
  }
  observer_.observe_step(t_, t_stop, state_at, forces_at, ModeKind::rest);
  t_ = t_stop;
}

void Simulation::advance(const FlightMode&, const MotionPiece& piece, double t_stop) {
  const double g = scene_.g;
  const FlightStart start{state_.y, state_.theta, state_.vy, state_.omega};
  const double t0 = t_;
  const double min_step = kFlightMinStep * block_time_;
  // The flight ends where it lands or overturns. When this stretch ends the run, both are looked
  // for up to where the centre of mass would reach the ground in free fall (a corner lands before
  // that), not up to the run's end: where a run ends then cannot move a landing it reaches, and a
  // run past the settle time gives the settled run's summary.
  const bool ends_run = t_stop >= run_end_;
  double t_end =
      ends_run ? t0 + (start.vy + std::sqrt(start.vy * start.vy + 2.0 * g * start.y)) / g : t_stop;
  bool overturns = false;
  if (start.omega != 0.0) {
    const double tau = (geometry_.overturn_theta(start.omega) - start.theta) / start.omega;
    if (tau > 0 && t0 + tau < t_end) {
      t_end = t0 + tau;
      overturns = true;
    }
  }
  if (const auto landing = first_landing(geometry_, start, g, t_end - t0, min_step)) {
    if (t0 + *landing <= t_end) {
      t_end = t0 + *landing;
      overturns = false;
    }
  }
  if (t_end > t_stop) {  // the run ends first
    t_end = t_stop;
    overturns = false;
  }
  // Only the horizontal drift feels the ground motion, and it has a closed form too.
  const GroundDrift drift(piece, t0);
  const double x0 = state_.x, vx0 = state_.vx;
  const auto pose_at = [&](double t) {
    BlockState s = flight_pose(start, g, t - t0);
    const GroundDrift::Integrals ground = drift.at(t);
    s.x = x0 + vx0 * (t - t0) + g * ground.second;
    s.vx = vx0 + g * ground.first;
    return s;
  };
  // The end is asked for twice (the observer's last part, then the state the flight leaves): its
  // pulse integrals are the dearest part of a chattering block's flight.
  const BlockState end = pose_at(t_end);
  const auto pose = [&](double t) { return t == t_end ? end : pose_at(t); };
  // The observer sees the flight in equal parts no longer than an integrator's step could be,
  // so it finds where x turns inside the flight as it does in the other modes.
  const auto forces_at = [](double) { return ContactForces{0.0, 0.0}; };
  if (!reached(t0, t_end)) {
    const double parts = std::ceil((t_end - t0) / step_cap(piece));
    double from = t0;
    for (double k = 1.0; k <= parts; k += 1.0) {
      const double to = k == parts ? t_end : t0 + (t_end - t0) * (k / parts);
      observer_.observe_step(from, to, pose, forces_at, ModeKind::flight);
      from = to;
    }
  }
  if (overturns) {
    overturn_at(t_end, end);
    return;
  }
  t_ = t_end;
  state_ = end;
}

template <class System>
void Simulation::advance(const System& system, const MotionPiece& piece, double t_stop) {
  with_scene_stepper<System::N>(scene_.solver, system.scale(), [&](auto& stepper) {
    integrate_with(system, stepper, piece, t_stop);
  });
}

// Steps until a guard crosses zero or t_stop; a crossing is located on the dense output and the
// state is left just after it, where the next mode's conditions hold.
template <class System, class Stepper>
void Simulation::integrate_with(const System& system, Stepper& stepper, const MotionPiece& piece,
                                double t_stop) {
  auto q = system.coordinates(state_);
  double t = t_;
  GuardWatch<System::kGuards> watch(system.guards(t, q));
  const double cap = step_cap(piece);
  const auto forces_at = [&](double x) { return system.forces(x, stepper.dense(x)); };
  const auto state_at = [&](double x) { return system.full(x, stepper.dense(x)); };
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
    stepper.step(system, t, q, std::min({t_stop - t, cap, retake_until - t}));
    retake_until = std::numeric_limits<double>::infinity();
    if (reached(t, t_stop)) t = t_stop;
    summary_.steps += stepper.steps() - steps_counted;
    summary_.rhs_evaluations += stepper.rhs_evaluations() - rhs_counted;
    steps_counted = stepper.steps();
    rhs_counted = stepper.rhs_evaluations();
    if ((summary_.steps & kBudgetCheckMask) == 0) check_budget();

    const auto next = system.guards(t, q);
    const auto guards_at = [&](double x) { return system.guards(x, stepper.dense(x)); };
    const auto least_at_ends = [&] {
      return system.least_at_ends(q0, q, [&](int i) { return stepper.moves_one_way(i); });
    };
    const auto crossing = watch.first_crossing(guards_at, t0, t, next, least_at_ends);
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
    const ContactForces contact = forces_at(crossing.before);
    summary_.max_contact_violation = std::max(
        {summary_.max_contact_violation, -contact.normal / scene_.g,
         (std::abs(contact.friction) - scene_.contact.friction * contact.normal) / scene_.g});
    observer_.observe_step(t0, kept, state_at, forces_at, mode_kind(mode_));
    if (which < 0) continue;
    const BlockState at_event = state_at(t_event);
    const GuardEvent event = System::kEvents[static_cast<std::size_t>(which)];
    if (event == GuardEvent::overturns) {
      overturn_at(t_event, at_event);
      return;
    }
    t_ = t_event;
    state_ = at_event;
    last_event_ = event;
    return;
  }
  t_ = t_stop;
  state_ = system.full(t, q);
}

void Simulation::run() {
  state_ = initial_state();
  observer_.start(state_);
  enter(resolve_contact());
  run_end_ = run_end_time(scene_, motion_, vertical_);
  const double t_end = run_end_;
  while (!stopped_ && t_ < t_end) {
    // Settling: once every excitation is over, a block at rest stays at rest.
    if (!scene_.duration && at_rest_for_good()) break;
    const MotionPiece& piece = motion_.piece_at(t_);
    const double t_stop = std::min({t_end, piece.end(), vertical_.piece_at(t_).end()});
    const double t_before = t_;
    last_event_.reset();
    with_system(piece, [&](const auto& system) { advance(system, piece, t_stop); });
    if (stopped_ || t_ >= t_end) break;
    stalled_events_ = t_ == t_before ? stalled_events_ + 1 : 0;
    if (stalled_events_ > kMaxStalledEvents) {
      throw SimulationFailure("no progress: " + std::to_string(kMaxStalledEvents) +
                              " contact changes at t = " + std::to_string(t_) + " s");
    }
    // A piece boundary is not an event: a mode whose contact forces still hold under the next
    // piece goes on. Re-resolving there would lay a block that has only just lifted flat again
    // (its corners are still slower than the settling speed), so a finely tabulated motion
    // could never start it rocking.
    const bool at_piece_end = t_ == t_stop && !last_event_;
    if (at_piece_end && mode_holds_under(motion_.piece_at(t_))) continue;
    enter(resolve_contact());
  }
  finish();
}

bool Simulation::mode_holds_under(const MotionPiece& piece) const {
  return with_system(piece, [&](const auto& system) {
    using S = std::decay_t<decltype(system)>;
    if constexpr (std::is_same_v<S, RestMode>) {
      // A record's knot is not an event: rest goes on where the next piece keeps it inside its
      // limits, as it does inside a piece.
      return rest_margin(piece, vertical_.piece_at(t_), t_) > 0;
    } else if constexpr (std::is_same_v<S, FlightMode>) {
      return true;
    } else {
      const auto guards = system.guards(t_, system.coordinates(state_));
      for (std::size_t i = 0; i < guards.size(); ++i) {
        if (depends_on_ground_motion(S::kEvents[i]) && !(guards[i] > 0)) return false;
      }
      return true;
    }
  });
}

bool Simulation::at_rest_for_good() const {
  return std::holds_alternative<RestMode>(mode_) && t_ >= excitation_end_;
}

// Also called when the scene fails: the summary then tells where it stopped.
void Simulation::finish() {
  summary_.end_time = t_;
  summary_.settled = summary_.status == Status::ok && (summary_.overturned || at_rest_for_good());
  if (summary_.overturned) {
    summary_.settle_time = summary_.overturn_time;
  } else if (summary_.settled) {
    summary_.settle_time = rest_since_;
  }
  summary_.final_theta = state_.theta;
  summary_.final_slide = state_.x - observer_.x0();
  observer_.finish(t_, state_, forces_now(), mode_kind(mode_));
}

ContactForces Simulation::forces_now() const {
  if (stopped_) return {0.0, 0.0};
  const MotionPiece& piece = motion_.piece_at(t_);
  return with_system(piece, [&](const auto& system) -> ContactForces {
    using S = std::decay_t<decltype(system)>;
    if constexpr (std::is_same_v<S, RestMode>) {
      return resting_forces(piece, t_);
    } else if constexpr (std::is_same_v<S, FlightMode>) {
      return {0.0, 0.0};
    } else {
      return system.forces(t_, system.coordinates(state_));
    }
  });
}

SimulationWithHistory run_scene(const Scene& scene, double output_interval) {
  validate_scene(scene);
  if (scene.seat) return simulate_on_seat(scene, output_interval);
  Simulation simulation(scene, output_interval);
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

}  // namespace

Summary simulate(const Scene& scene) { return run_scene(scene, 0.0).summary; }

double scene_run_end_time(const Scene& scene) {
  validate_scene(scene);
  return run_end_time(scene, scene_motion(scene), scene_vertical_motion(scene));
}

SimulationWithHistory simulate_with_history(const Scene& scene, double output_interval) {
  if (!(output_interval > 0)) throw ContractViolation("output interval must be > 0");
  return run_scene(scene, output_interval);
}

}  // namespace blockfrag
