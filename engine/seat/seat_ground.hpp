// The seat's ground in the one event loop (engine/event_loop.hpp): a block on a polyline seat, its
// contact sets integrated in their charts (engine/seat/seat_chart.hpp) and resolved at events by
// the complementarity problem of engine/contact/contact_lcp.hpp. Internal to the engine: its
// member functions are defined in seat_simulation.cpp (the loop's hooks and the integration),
// seat_resolution.cpp (what happens at an event) and seat_projection.cpp (putting the block back
// on its contacts, laying it, and rest's range).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

#include <Eigen/Dense>

#include "engine/contact/body_load.hpp"
#include "engine/contact/contact_lcp.hpp"
#include "engine/contact/settling.hpp"
#include "engine/event_loop.hpp"
#include "engine/scene/seat.hpp"
#include "engine/seat/hull_watch.hpp"
#include "engine/seat/seat_chart.hpp"
#include "engine/seat/seat_system.hpp"

namespace blockfrag {

inline bool is_slip(ContactState s) {
  return s == ContactState::slip_positive || s == ContactState::slip_negative;
}

// The mode between two events: the active contacts and their states (none: flight); at rest the
// block does not move while lambda / (1 + lambda_v) stays within [rest_low, rest_high].
struct SeatMode {
  std::vector<ActiveContact> active;
  bool rest = false;
  double rest_low = 0.0, rest_high = 0.0;
  // The contacts leave the block no freedom: it cannot move, only wait for a force guard (just
  // past where rest ended, inside the contact problem's tolerance).
  bool pinned = false;
};

// Rest, or pinned; no contact: flight; one contact: rock when it sticks, slide-rock
// when it slips; several: slide when all slip, slide-rock when some do, rock otherwise (a vertex
// sticking in the fold, on both its segments).
inline ModeKind kind_of(const SeatMode& mode) {
  if (mode.rest) return ModeKind::rest;
  if (mode.pinned) return ModeKind::rest;
  if (mode.active.empty()) return ModeKind::flight;
  const auto slipping = std::count_if(mode.active.begin(), mode.active.end(),
                                      [](const ActiveContact& a) { return is_slip(a.state); });
  if (mode.active.size() == 1) return slipping == 1 ? ModeKind::slide_rock : ModeKind::rock;
  if (slipping == static_cast<long>(mode.active.size())) return ModeKind::slide;
  return slipping > 0 ? ModeKind::slide_rock : ModeKind::rock;
}

class SeatSimulation : public EventLoop<SeatSimulation> {
 public:
  // `external`: what acts on the block besides gravity, the ground and the seat (none: the dry
  // block); it must outlive the simulation.
  SeatSimulation(const Scene& scene, double output_interval, const ExternalLoad* external = nullptr)
      : EventLoop(scene, output_interval),
        external_(external),
        contacts_(scene_block_vertices(scene), scene.seat->points),
        level_(contacts_.level()),
        hull_watch_(contacts_.point_count() == 2 ? HullWatch(body_vertices(contacts_))
                                                 : HullWatch()),
        R_(geometry_.size()),
        velocity_tol_(resting_speed(scene.g, R_)) {
    summary_.model = std::holds_alternative<NoMotion>(scene.vertical_motion) ? Model::full
                                                                             : Model::full_vertical;
    // finish_summary reports the seat's depth in place of the flat ground's.
    observer_.leave_depth_to_ground();
  }

 private:
  friend class EventLoop<SeatSimulation>;
  using Crossing = GuardWatch<SeatSystem::kGuards>::Crossing;

  // A contact whose force reached zero or its cone's edge, or that left its segment's or edge's
  // end.
  struct ForceEvent {
    SeatPair pair;
    SeatEvent event;
  };
  // What ended an integrated stretch, for the resolution at its end.
  struct EventReport {
    bool by_event = false;            // a guard's crossing, or lambda leaving rest's range
    std::optional<ForceEvent> force;  // the contact whose guard ended it, if one did
    bool rest_ended = false;          // lambda left rest's range
    int arrived_point = -1;           // the seat point that reached the block, if one did
    // The pairs touching at the event, where the event found them (a touch's overturning check):
    // the resolution's, at the same pose and mode.
    std::optional<std::vector<SeatPair>> touching;
    bool ended_by_event() const { return by_event; }
  };

  // The ground's part of the event loop (engine/event_loop.hpp).
  void place_at_start();
  void resolve_and_enter(const EventReport& report) {
    piece_end_ready_ = false;
    enter(resolve(report), report);
  }
  EventReport advance(MotionPiece& piece, double t_stop);
  bool holds_under(MotionPiece& piece);
  bool at_rest() const { return mode_.rest; }
  void observe(const BlockState& s);
  ContactForces forces_now();
  ModeKind mode_kind_now() const { return kind_of(mode_); }
  // The observer measures depth below a flat ground at y = 0; on a seat it is the seat's.
  void finish_summary() { summary_.max_penetration = deepest_ / R_; }
  template <class Ode, class GuardsAt, class StateAt>
  Crossing refine_crossing(const Ode& ode, const GuardWatch<SeatSystem::kGuards>& watch,
                           const GuardsAt& guards_at, const StateAt& state_at, double t0, double t1,
                           Crossing found, ModeKind kind) const;
  // The contact laws at time t, in the state s.
  template <class Ode, class ForcesAt>
  void note_contact_violation(const Ode& ode, double t, const BlockState& s, const ForcesAt&);
  // A step kept, ending in the state s.
  template <class Ode>
  void stepped(const Ode& ode, const BlockState& s) {
    deepest_ = std::max(deepest_, ode.penetration(s));
  }
  template <class Ode>
  EventReport on_event(const Ode& ode, int which, double t_event, const BlockState& at_event);
  // The guards at the end of a stretch that reached its piece's end, at state_, kept for the next
  // piece's start where the mode holds.
  template <class Ode>
  void ended_piece(const Ode& ode, const std::array<double, SeatSystem::kGuards>& guards);
  // The guard watch at an advance's start: where the mode held at the last piece's end and the
  // block's pose there is the same, bit for bit, the guards of its pose alone (overturning,
  // falling, the clearances) are the last piece's end values, and only the contacts' are found.
  template <class Ode>
  GuardWatch<SeatSystem::kGuards> watch_at_piece_start(const Ode& ode, double t,
                                                       const OdeState<Ode::N>& q);

  double gravity_factor(double t) { return 1.0 + vertical_.lambda(t); }
  // The settling speed now, in the gravity the block feels.
  double settle_velocity() { return settling_speed(scene_.g * gravity_factor(t_), R_); }
  // The load on the block at time t in the state s (engine/contact/body_load.hpp), standing as
  // the current mode has it.
  BodyLoad load_at(double t, const BlockState& s) {
    return body_load(geometry_.inertia_per_mass(), motion_.lambda(t), vertical_.lambda(t), scene_.g,
                     external_, s, footing_of(mode_));
  }
  static Footing footing_of(const SeatMode& mode) {
    return mode.rest || mode.active.size() >= 2 ? Footing::seated : Footing::lifted;
  }
  // The kinetic energy per unit mass, the added mass's included.
  double kinetic_energy(const BlockState& s) {
    return 0.5 * load_at(t_, s).inertia.twice_kinetic(velocity_of(s));
  }
  SeatSystemContext system_context(MotionPiece& piece);
  // The system of the current mode under `piece` at t_ and state_, built into system_.
  SeatSystem& build_system(MotionPiece& piece);
  // SeatSystem(context, mode_.active, vertices, points) in system_: the last system started on the
  // piece where it lays its guards out so.
  SeatSystem& system_for(const SeatSystemContext& context, const WatchedList& vertices,
                         const WatchedList& points);
  // The system of the current mode for its contact forces alone, watching no vertex or point: what
  // a piece boundary asks of the mode, at each sample of a record.
  SeatSystem forces_system(MotionPiece& piece) {
    return SeatSystem(system_context(piece), mode_.active, {}, {});
  }
  // The sweep of `system` turning on `chart`: the last one built where it serves them, rebound.
  PivotSweep& sweep_for(const SeatSystem& system, const PivotChart& chart);
  PlanarContact contact_of(const SeatPair& pair, const BlockState& s) const {
    return contacts_.pose(pair, s).contact;
  }
  // The pairs touching at s, after a stretch that ended as `report` says.
  std::vector<SeatPair> touching(const BlockState& s, const EventReport& report) const;
  // Impacts at the contacts that approach, one at a time as on the flat ground, until none does.
  // impacted: some contact approached.
  bool resolve_impacts(BlockState& s, const std::vector<SeatPair>& touching, bool& impacted);
  // resolve_impacts' steps: the pairs' contacts and the one that approaches fastest (first: -1
  // where none approaches), and the impact at that one by the scene's restitution.
  struct Approach {
    const std::vector<PlanarContact>& all;
    double fastest;
    int first;
  };
  Approach fastest_approach(const std::vector<PlanarContact>& contacts, const BlockState& s) const;
  void landing_impact(BlockState& s, const Approach& approach, const BlockState& start,
                      const BodyInertia& inertia);
  bool plastic_landing(const std::vector<SeatPair>& pairs);
  SeatMode resolve(const EventReport& report);
  // The named steps of resolve (engine/seat/seat_resolution.cpp).
  struct CarryingContacts {
    std::vector<SeatPair> pairs;
    PlanarForcesInput problem;
  };
  void put_back_on_held_contacts(const std::vector<SeatPair>& pairs);
  SeatMode contact_states(const std::vector<SeatPair>& pairs, const EventReport& report,
                          std::size_t logged);
  void settle_or_lay(BlockState& s, const std::vector<SeatPair>& pairs, bool impacted);
  CarryingContacts carrying_contacts(const std::vector<SeatPair>& pairs);
  SeatMode rest_on(const std::vector<SeatPair>& carrying);
  PlanarForces choice_that_moves(PlanarForcesInput problem, const EventReport& report,
                                 const PlanarForces& pinned) const;
  SeatMode states_after_guard(const std::vector<SeatPair>& carrying, const PlanarForces& forces,
                              const EventReport& report) const;
  std::vector<Eigen::RowVector3d> fixed_rows(const SeatMode& mode) const;
  SeatMode logged_mode(const SeatMode& mode, std::size_t logged);
  std::vector<Eigen::RowVector3d> fixed_rows(const std::vector<SeatPair>& pairs,
                                             const std::vector<ContactState>& states,
                                             const BlockState& s) const;
  bool holds_at_rest(const PlanarForces& f, double relative_tolerance) const;
  // Whether the still block of `problem` rests, lambda well inside the flat ground's rest range.
  bool rests_inside_level_range(const PlanarForcesInput& problem);
  Eigen::Vector3d least_kinetic_change(const Eigen::MatrixXd& j, const Eigen::VectorXd& b,
                                       const BodyInertia& inertia) const;
  void lay_on(const std::vector<SeatPair>& pairs, BlockState& s);
  void project_positions(const std::vector<ActiveContact>& active, BlockState& s) const;
  // Whether the block landing at s on the `touching` pairs lies on its face next to the base
  // (overturned), its tilt read with those pairs put back on the seat.
  bool lies_overturned(const BlockState& s, const std::vector<SeatPair>& touching) const;
  // lies_overturned for a landing on a level seat, clear of its ends, whose touching pairs are
  // block vertices; their projection is not made where it cannot tilt the block that far.
  bool lies_overturned_on_level(const BlockState& s, const std::vector<SeatPair>& touching) const;
  void project(const SeatMode& mode);
  // `decompositions`: the contact problem's, kept over the rest range's search.
  bool rest_holds(double lambda, LcpDecompositions& decompositions) const;
  // The same on these pairs.
  bool rest_holds(const std::vector<SeatPair>& pairs, double lambda,
                  LcpDecompositions& decompositions) const;
  // A force event of a still block whose resolution brings back, at the same pose, the contact
  // set the last event left (two guards handing the block back and forth).
  bool swaps_back(const SeatMode& resolved, const EventReport& report) const;
  void set_rest_thresholds(SeatMode& mode);
  // Under the pieces being integrated: at a piece's end its own formula, not the next piece's.
  double rest_margin(double t, MotionPiece& piece, MotionPiece& vertical) const;
  void enter(const SeatMode& mode, const EventReport& report);
  void stop_at(double t, const BlockState& s, SeatEvent why);
  EventReport advance_rest(double t_stop);
  // A dry flight without vertical motion over a level seat, inside its ends by t_stop: flown as the
  // flat ground flies (flight_end), its landing found on the block's corners and reported as its
  // lowest vertex's touching guard. None where it does not apply
  // (engine/seat/seat_level_flight.cpp).
  std::optional<EventReport> fly_over_level_seat(const FlightChart& chart, MotionPiece& piece,
                                                 double t_stop);
  // The least clearance of the block's vertices at s (the lowest one's).
  double lowest_clearance(const BlockState& s) const;
  // The rounding noise of a vertex's clearance over R near the block's pose s.
  double clearance_noise(const BlockState& s) const {
    return 8 * std::numeric_limits<double>::epsilon() *
           (1.0 + (std::abs(s.x) + std::abs(s.y)) / R_);
  }
  template <class GuardsAt>
  static Crossing landing_at_zero(const GuardsAt& guards_at, double t0, Crossing found,
                                  double noise);
  template <class GuardsAt>
  static Crossing unarmed_landing_before(const SeatSystem& system,
                                         const GuardWatch<SeatSystem::kGuards>& watch,
                                         const GuardsAt& guards_at, double t0, Crossing found,
                                         double noise);
  template <class GuardsAt>
  static Crossing landing_between(const GuardsAt& guards_at, int g, double a, double fa, double b,
                                  double fb, double noise, double tolerance);
  template <class StateAt>
  Crossing touch_before_an_end(const SeatSystem& system, const StateAt& state_at, double t0,
                               double t1) const;
  SeatChart chart_of(const SeatMode& mode) const;

  const ExternalLoad* external_;
  SeatContacts contacts_;
  std::optional<double> level_;  // the seat's height where it is level (contacts_.level())
  HullWatch hull_watch_;         // the block's hull on a one-segment seat, which alone asks for it
  double R_, velocity_tol_;
  SeatMode mode_;
  // The pairs active before the last event, and the pose at it.
  std::vector<SeatPair> left_at_last_event_;
  BlockState last_event_pose_{};
  // Where each block vertex that sticks on a seat segment stuck (its place along the segment, m),
  // kept while it sticks.
  std::vector<std::pair<SeatPair, double>> anchors_;
  std::optional<double> anchor_of(const SeatPair& pair) const {
    const auto it = std::find_if(anchors_.begin(), anchors_.end(),
                                 [&](const auto& anchor) { return anchor.first == pair; });
    return it == anchors_.end() ? std::nullopt : std::optional<double>(it->second);
  }
  std::optional<PivotSweep> sweep_;  // the last built (sweep_for)
  // The last system built; ready: built by holds_under for the advance that follows it.
  std::optional<SeatSystem> system_;
  bool system_ready_ = false;
  // The guards ended_piece kept, the pose they were found at and the watched vertices and points
  // they were found for; ready: since the last advance's end, and read only by the advance after
  // holds_under (from_piece_end_).
  struct PieceEnd {
    BlockState s;
    std::array<double, SeatSystem::kGuards> guards;  // the pose's alone: 0, 1, the clearances
    WatchedList vertices, points;
  };
  PieceEnd piece_end_{};
  bool piece_end_ready_ = false, from_piece_end_ = false;
  Vec2 origin_{0.0, 0.0};  // the charts' (engine/seat/seat_chart.hpp)
  double deepest_ = 0.0;   // m: the block's largest penetration of the seat seen
};

}  // namespace blockfrag
