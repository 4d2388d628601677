#include "engine/simulate.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <type_traits>

#include "engine/contact/contact_resolution.hpp"
#include "engine/contact/model_choice.hpp"
#include "engine/contact/reduced_contact.hpp"
#include "engine/event_loop.hpp"
#include "engine/integrate/with_stepper.hpp"
#include "engine/modes/flight.hpp"
#include "engine/modes/modes.hpp"
#include "engine/motion/ground_drift.hpp"
#include "engine/motion/scene_motion.hpp"
#include "engine/scene/scene_validation.hpp"
#include "engine/seat/seat_simulation.hpp"
#include "engine/tolerances.hpp"
#include "engine/water/reservoir_load.hpp"

namespace blockfrag {

namespace {

class FlatGroundSimulation : public EventLoop<FlatGroundSimulation> {
 public:
  FlatGroundSimulation(const Scene& scene, double output_interval)
      : EventLoop(scene, output_interval),
        model_(choose_model(scene, motion_, geometry_)),
        resolver_(geometry_, scene.contact, scene.g),
        housner_(geometry_, scene.effects.automatic || scene.effects.impact, scene.g,
                 scene.contact.rocking_restitution),
        newmark_(geometry_, scene.contact.friction, scene.g) {
    summary_.model = model_;
  }

 private:
  friend class EventLoop<FlatGroundSimulation>;

  SystemContext context(MotionPiece& piece) {
    return {&geometry_, &piece, &vertical_.piece_at(t_), scene_.g, scene_.contact.friction};
  }
  // The one place that says which ODE system integrates the current mode under `piece`: fn gets
  // that system, or the mode itself for rest and for flight without vertical motion (both closed
  // form). Housner's model rocks without the contact-force guards.
  template <class Fn>
  decltype(auto) with_system(MotionPiece& piece, Fn&& fn) {
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

  // The ground's part of the event loop (engine/event_loop.hpp).
  struct EventReport {
    std::optional<GuardEvent> event;  // the guard's event that ended the stretch, if one did
    bool ended_by_event() const { return event.has_value(); }
  };
  void place_at_start() { state_ = initial_state(); }
  void resolve_and_enter(const EventReport& report) { enter(resolve_contact(report)); }
  EventReport advance(MotionPiece& piece, double t_stop) {
    return with_system(piece, [&](const auto& system) { return advance(system, piece, t_stop); });
  }
  bool holds_under(MotionPiece& piece);
  bool at_rest() const { return std::holds_alternative<RestMode>(mode_); }
  void observe(const BlockState& s) { observer_.observe_state(s); }
  ContactForces forces_now();
  ModeKind mode_kind_now() const { return mode_kind(mode_); }
  void finish_summary() {}
  // The flat ground's guards find its crossings as they are.
  template <class System, class Crossing, class GuardsAt, class StateAt>
  Crossing refine_crossing(const System&, const GuardWatch<System::kGuards>&, const GuardsAt&,
                           const StateAt&, double, double, Crossing found, ModeKind) const {
    return found;
  }
  template <class System, class ForcesAt>
  void note_contact_violation(const System&, double t, const BlockState&,
                              const ForcesAt& forces_at) {
    const ContactForces contact = forces_at(t);
    summary_.max_contact_violation = std::max(
        {summary_.max_contact_violation, -contact.normal / scene_.g,
         (std::abs(contact.friction) - scene_.contact.friction * contact.normal) / scene_.g});
  }
  template <class System>
  void stepped(const System&, const BlockState&) {}
  template <class System>
  EventReport on_event(const System&, int which, double t_event, const BlockState& at_event);

  BlockState initial_state();
  ContactOutcome resolve_contact(const EventReport& report);
  void enter(const ContactOutcome& outcome);
  // How far rest is inside its limits at t (friction and both tipping moments against gravity
  // g (1 + lambda_v), and that gravity positive), in units of g, less kOnsetMargin: rest holds
  // while it is positive.
  double rest_margin(MotionPiece& piece, MotionPiece& vertical, double t) const;
  // The |lambda| below which the resting block neither slides nor tips about a corner (at
  // gravity g): Housner's block never slides and Newmark's never tips.
  double rest_friction_limit() const;
  double rest_tip_limit(Corner c) const;
  ContactForces resting_forces(MotionPiece& piece, double t) {
    return {-piece.lambda(t) * scene_.g, scene_.g * (1.0 + vertical_.lambda(t))};
  }
  void overturn_at(double t, const BlockState& s);

  EventReport advance(const RestMode&, MotionPiece& piece, double t_stop);
  // Flight without vertical motion: theta, y and x in closed form.
  EventReport advance(const FlightMode&, MotionPiece& piece, double t_stop);
  template <class System>
  EventReport advance(const System& system, MotionPiece& piece, double t_stop);

  Model model_;
  ContactResolver resolver_;
  HousnerRules housner_;
  NewmarkRules newmark_;
  Mode mode_ = RestMode{};
};

BlockState FlatGroundSimulation::initial_state() {
  BlockState s;
  s.theta = scene_.initial.theta;
  const double omega = scene_.initial.omega;
  if (s.theta == 0.0 && omega == 0.0) {
    s.y = geometry_.rest_height();
    return s;
  }
  // Released on the corner that the tilt lowers (or the turning keeps down), turning about it.
  const Vec2 r = geometry_.base_corner_at(release_pivot(s.theta, omega), s.theta);
  s.y = -r.y;
  if (omega != 0.0) {
    s.vx = omega * r.y;
    s.vy = -omega * r.x;
    s.omega = omega;
  }
  return s;
}

ContactOutcome FlatGroundSimulation::resolve_contact(const EventReport& report) {
  const double lambda = motion_.lambda(t_);
  switch (model_) {
    case Model::newmark_sliding: return newmark_.resolve(state_, lambda);
    case Model::housner_rocking:
      if (const auto* rock = std::get_if<RockMode>(&mode_)) {
        if (report.event == GuardEvent::corner_lands) {
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

void FlatGroundSimulation::enter(const ContactOutcome& outcome) {
  if (outcome.painleve) ++summary_.painleve_events;
  if (outcome.impact) {
    if (log_impacts_) {
      impact_log_.push_back(
          {t_, state_.omega, outcome.state.omega, kinetic_energy_per_mass(geometry_, state_),
           kinetic_energy_per_mass(geometry_, outcome.state), mode_kind(outcome.mode)});
    }
    ++summary_.impacts;
    if (!summary_.first_impact_time) summary_.first_impact_time = t_;
  }
  summary_.max_impact_energy_gain =
      std::max(summary_.max_impact_energy_gain, outcome.impact_energy_gain);
  const bool first = summary_.modes.empty();
  const ModeKind before = mode_kind(mode_);
  const bool was_rocking =
      std::holds_alternative<RockMode>(mode_) || std::holds_alternative<SlideRockMode>(mode_);
  mode_ = outcome.mode;
  state_ = outcome.state;
  entered(before, mode_kind(mode_), first, was_rocking && outcome.impact);
}

void FlatGroundSimulation::overturn_at(double t, const BlockState& s) {
  t_ = t;
  state_ = s;
  state_.theta = geometry_.overturn_theta(s.theta);
  summary_.overturned = true;
  summary_.overturn_time = t;
  observer_.observe_state(state_);
  stopped_ = true;
}

double FlatGroundSimulation::rest_friction_limit() const {
  return model_ == Model::housner_rocking ? std::numeric_limits<double>::infinity()
                                          : scene_.contact.friction;
}

double FlatGroundSimulation::rest_tip_limit(Corner c) const {
  return model_ == Model::newmark_sliding ? std::numeric_limits<double>::infinity()
                                          : geometry_.tip_threshold(c);
}

// The exit is placed where lambda is past a threshold by kOnsetMargin, so the modes it leads to
// see an unambiguous sign; a pulse that only grazes a threshold leaves the block at rest.
double FlatGroundSimulation::rest_margin(MotionPiece& piece, MotionPiece& vertical,
                                         double t) const {
  const double lambda = piece.lambda(t), factor = 1.0 + vertical.lambda(t);
  return kOnsetMargin + std::min({rest_friction_limit() * factor - std::abs(lambda),
                                  rest_tip_limit(Corner::right) * factor - lambda,
                                  rest_tip_limit(Corner::left) * factor + lambda, factor});
}

FlatGroundSimulation::EventReport FlatGroundSimulation::advance(const RestMode&, MotionPiece& piece,
                                                                double t_stop) {
  MotionPiece& vertical = vertical_.piece_at(t_);
  const bool holds_throughout =
      vertical.is_zero() &&
      (piece.is_zero() ||
       piece.max_abs_lambda() <= std::min({rest_friction_limit(), rest_tip_limit(Corner::right),
                                           rest_tip_limit(Corner::left)}) +
                                     kOnsetMargin);
  advance_rest(
      piece, t_stop, holds_throughout, [&](double t) { return rest_margin(piece, vertical, t); },
      [&](double t) { return resting_forces(piece, t); });
  return {};
}

FlatGroundSimulation::EventReport FlatGroundSimulation::advance(const FlightMode&,
                                                                MotionPiece& piece, double t_stop) {
  const double g = scene_.g;
  const FlightStart start{state_.y, state_.theta, state_.vy, state_.omega};
  const double t0 = t_;
  const FlightEnd ends =
      flight_end(geometry_, start, g, t0, t_stop, t_stop >= run_end_, kFlightMinStep * block_time_);
  const double t_end = ends.t;
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
  observe_flight(
      t0, t_end, [&](double t) { return t == t_end ? end : pose_at(t); }, piece);
  if (ends.overturns) {
    overturn_at(t_end, end);
    return {};
  }
  t_ = t_end;
  state_ = end;
  return {};
}

template <class System>
FlatGroundSimulation::EventReport FlatGroundSimulation::advance(const System& system,
                                                                MotionPiece& piece, double t_stop) {
  EventReport report;
  with_scene_stepper<System::N>(scene_.solver, system.scale(), [&](auto& stepper) {
    report = integrate_with(system, stepper, piece, t_stop, mode_kind(mode_));
  });
  return report;
}

template <class System>
FlatGroundSimulation::EventReport FlatGroundSimulation::on_event(const System&, int which,
                                                                 double t_event,
                                                                 const BlockState& at_event) {
  const GuardEvent event = System::kEvents[static_cast<std::size_t>(which)];
  if (event == GuardEvent::overturns) {
    overturn_at(t_event, at_event);
    return {};
  }
  t_ = t_event;
  state_ = at_event;
  return {event};
}

bool FlatGroundSimulation::holds_under(MotionPiece& piece) {
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

ContactForces FlatGroundSimulation::forces_now() {
  if (stopped_) return {0.0, 0.0};
  MotionPiece& piece = motion_.piece_at(t_);
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
  if (reservoir_wets(scene)) return simulate_under_reservoir(scene, output_interval);
  if (scene.seat) return simulate_on_seat(scene, output_interval);
  FlatGroundSimulation simulation(scene, output_interval);
  return run_to_end(simulation);
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
