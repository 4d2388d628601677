#include "engine/seat/seat_simulation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include <Eigen/Dense>

#include "engine/contact/contact_lcp.hpp"
#include "engine/contact/planar_impact.hpp"
#include "engine/contact/settling.hpp"
#include "engine/errors.hpp"
#include "engine/event_loop.hpp"
#include "engine/integrate/guard_crossing.hpp"
#include "engine/integrate/root_finding.hpp"
#include "engine/integrate/with_stepper.hpp"
#include "engine/motion/scene_motion.hpp"
#include "engine/scene/seat.hpp"
#include "engine/seat/closed_form_flight.hpp"
#include "engine/seat/seat_chart.hpp"
#include "engine/seat/seat_system.hpp"
#include "engine/segment_observer.hpp"
#include "engine/sine_cosine.hpp"
#include "engine/tolerances.hpp"

namespace blockfrag {

namespace {

// Gauss-Newton iterations that put the active contacts' gaps back to zero after an event.
constexpr int kProjectionIterations = 4;
// Halvings of the lambda interval that bracket where rest on a seat ends.
constexpr int kRestThresholdHalvings = 64;
// Relative to g: the contact problem's tolerance (a force outside its cone, an acceleration taken
// for none) where rest's lambda range is found, a tenth of the margin by which rest ends past it.
// The block at rest is laid exactly on its contacts, so the problem's forces there are exact to
// rounding (a few 1e-16 g); at its tolerance between events, 1e-9 g, rest held past its range by
// 3e-9 of lambda (the block pivoting with an acceleration below 1e-9 g counted as still), and the
// block started to rock a few 1e-9 s after the flat ground's closed-form onset, which is
// kOnsetMargin past its threshold.
constexpr double kRestTolerance = 1e-13;
// Two seat segments whose directions' cross product is within this of zero (and whose lines are
// within the contact height) are on one line: a flat seat given as a polyline rounds to 1e-16.
constexpr double kCollinearSine = 1e-12;

bool is_slip(ContactState s) {
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
ModeKind kind_of(const SeatMode& mode) {
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
  SeatSimulation(const Scene& scene, double output_interval)
      : EventLoop(scene, output_interval),
        contacts_(scene_block_vertices(scene), scene.seat->points),
        R_(geometry_.size()),
        velocity_tol_(resting_speed(scene.g, R_)) {
    summary_.model = std::holds_alternative<NoMotion>(scene.vertical_motion) ? Model::full
                                                                             : Model::full_vertical;
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
    bool ended_by_event() const { return by_event; }
  };

  // The ground's part of the event loop (engine/event_loop.hpp).
  void place_at_start();
  void resolve_and_enter(const EventReport& report) { enter(resolve(report), report); }
  EventReport advance(const MotionPiece& piece, double t_stop);
  bool holds_under(const MotionPiece& piece) const;
  bool at_rest() const { return mode_.rest; }
  void observe(const BlockState& s);
  ContactForces forces_now() const;
  ModeKind mode_kind_now() const { return kind_of(mode_); }
  // The observer measures depth below a flat ground at y = 0; on a seat it is the seat's.
  void finish_summary() { summary_.max_penetration = deepest_ / R_; }
  template <class Ode, class GuardsAt, class StateAt>
  Crossing refine_crossing(const Ode& ode, const GuardWatch<SeatSystem::kGuards>& watch,
                           const GuardsAt& guards_at, const StateAt& state_at, double t0, double t1,
                           Crossing found, ModeKind kind) const;
  template <class Ode, class StateAt, class ForcesAt>
  void note_contact_violation(const Ode& ode, double t, const StateAt& state_at, const ForcesAt&);
  template <class StateAt>
  void stepped(const StateAt& state_at, double t) {
    deepest_ = std::max(deepest_, contacts_.penetration(state_at(t)));
  }
  template <class Ode>
  EventReport on_event(const Ode& ode, int which, double t_event, const BlockState& at_event);

  double gravity_factor(double t) const { return 1.0 + vertical_.lambda(t); }
  // The settling speed now, in the gravity the block feels.
  double settle_velocity() const { return settling_speed(scene_.g * gravity_factor(t_), R_); }
  Vec2 applied(double t) const {
    return {motion_.lambda(t) * scene_.g, -scene_.g * gravity_factor(t)};
  }
  SeatSystem system(const MotionPiece& piece) const;
  PlanarContact contact_of(const SeatPair& pair, const BlockState& s) const {
    return contacts_.pose(pair, s).contact;
  }
  // The pairs touching at s, after a stretch that ended as `report` says.
  std::vector<SeatPair> touching(const BlockState& s, const EventReport& report) const;
  // Impacts at the contacts that approach, one at a time as on the flat ground, until none does.
  // impacted: some contact approached.
  bool resolve_impacts(BlockState& s, const std::vector<SeatPair>& touching, bool& impacted);
  bool plastic_landing(const std::vector<SeatPair>& pairs) const;
  SeatMode resolve(const EventReport& report);
  SeatMode logged_mode(const SeatMode& mode, std::size_t logged);
  std::vector<Eigen::RowVector3d> fixed_rows(const std::vector<SeatPair>& pairs,
                                             const std::vector<ContactState>& states,
                                             const BlockState& s) const;
  bool holds_at_rest(const PlanarForces& f, double relative_tolerance) const;
  Eigen::Vector3d least_kinetic_change(const Eigen::MatrixXd& j, const Eigen::VectorXd& b) const;
  void lay_on(const std::vector<SeatPair>& pairs, BlockState& s) const;
  void project_positions(const std::vector<ActiveContact>& active, BlockState& s) const;
  void project(const SeatMode& mode);
  bool rest_holds(double lambda) const;
  void set_rest_thresholds(SeatMode& mode) const;
  // Under the pieces being integrated: at a piece's end its own formula, not the next piece's.
  double rest_margin(double t, const MotionPiece& piece, const MotionPiece& vertical) const;
  void enter(const SeatMode& mode, const EventReport& report);
  void stop_at(double t, const BlockState& s, SeatEvent why);
  EventReport advance_rest(double t_stop);
  // The rounding noise of a vertex's clearance over R near the block's pose s.
  double clearance_noise(const BlockState& s) const {
    return 8 * std::numeric_limits<double>::epsilon() *
           (1.0 + (std::abs(s.x) + std::abs(s.y)) / R_);
  }
  template <class GuardsAt>
  static Crossing landing_at_zero(const GuardsAt& guards_at, double t0, Crossing found,
                                  double noise);
  template <class StateAt>
  Crossing touch_before_an_end(const SeatSystem& system, const StateAt& state_at, double t0,
                               double t1) const;
  SeatChart chart_of(const SeatMode& mode) const;

  SeatContacts contacts_;
  double R_, velocity_tol_;
  SeatMode mode_;
  // Where each block vertex that sticks on a seat segment stuck (its place along the segment, m),
  // kept while it sticks.
  std::vector<std::pair<SeatPair, double>> anchors_;
  std::optional<double> anchor_of(const SeatPair& pair) const {
    const auto it = std::find_if(anchors_.begin(), anchors_.end(),
                                 [&](const auto& anchor) { return anchor.first == pair; });
    return it == anchors_.end() ? std::nullopt : std::optional<double>(it->second);
  }
  Vec2 origin_{0.0, 0.0};  // the charts' (engine/seat/seat_chart.hpp)
  double deepest_ = 0.0;   // m: the block's largest penetration of the seat seen
};

SeatSystem SeatSimulation::system(const MotionPiece& piece) const {
  const SeatSystemContext context{&contacts_,     &geometry_,
                                  &piece,         &vertical_.piece_at(t_),
                                  scene_.g,       scene_.contact.friction,
                                  kFallDepth * R_};
  // Vertices and points in an active contact are not watched for touching: they touch.
  std::vector<int> vertices, points;
  const double near = kSeatContactDrift * R_;
  for (int i = 0; i < contacts_.vertex_count(); ++i) {
    const bool active = std::any_of(mode_.active.begin(), mode_.active.end(), [&](const auto& a) {
      return a.pair.kind == ContactKind::block_vertex && a.pair.block == i;
    });
    if (!active) vertices.push_back(i);
  }
  for (int k = 0; k < contacts_.point_count(); ++k) {
    if (!contacts_.touches_edges(k)) continue;
    const Vec2 p = contacts_.seat_point(k);
    const bool active = std::any_of(mode_.active.begin(), mode_.active.end(), [&](const auto& a) {
      if (a.pair.kind == ContactKind::seat_point) return a.pair.seat == k;
      const Vec2 v = contacts_.vertex_at(a.pair.block, state_);
      return std::hypot(v.x - p.x, v.y - p.y) <= near;
    });
    if (!active) points.push_back(k);
  }
  return SeatSystem(context, mode_.active, vertices, points);
}

// The chart of the active contacts (engine/seat/seat_chart.hpp). Contacts of block vertices on
// collinear segments (a flat seat's joint, which a vertex there touches on both sides) act as one
// line: one vertex on it pivots or slips, two or more slide along it.
SeatChart SeatSimulation::chart_of(const SeatMode& mode) const {
  const std::vector<ActiveContact>& active = mode.active;
  if (active.empty()) return FlightChart{origin_, t_, state_.theta, state_.omega};
  const ActiveContact& first = active.front();
  const bool sticks = first.state == ContactState::stick;
  if (active.size() == 1 && sticks && first.pair.kind == ContactKind::seat_point) {
    const Vec2 p = contacts_.seat_point(first.pair.seat);
    const SineCosine turn = sine_cosine(-state_.theta);
    return PivotChart{p, rotate({p.x - state_.x, p.y - state_.y}, turn.cos, turn.sin)};
  }
  const bool one_line = std::all_of(active.begin(), active.end(), [&](const ActiveContact& a) {
    if (a.pair.kind != ContactKind::block_vertex || (a.state == ContactState::stick) != sticks) {
      return false;
    }
    const SeatLine line = contacts_.segment_line(a.pair.seat);
    const SeatLine base = contacts_.segment_line(first.pair.seat);
    const double cross = line.direction.x * base.direction.y - line.direction.y * base.direction.x;
    return std::abs(cross) <= kCollinearSine &&
           std::abs(line.offset - base.offset) <= kContactHeight * R_;
  });
  if (!one_line) return FreeChart{origin_};
  SeatLine line = contacts_.segment_line(first.pair.seat);
  const bool one_vertex = std::all_of(active.begin(), active.end(), [&](const ActiveContact& a) {
    return a.pair.block == first.pair.block;
  });
  const Vec2 body = contacts_.body_vertex(first.pair.block);
  const Vec2 vertex = contacts_.vertex_at(first.pair.block, state_);
  const double along = vertex.x * line.direction.x + vertex.y * line.direction.y;
  if (one_vertex && sticks) {
    return PivotChart{{along * line.direction.x + line.offset * line.normal.x,
                       along * line.direction.y + line.offset * line.normal.y},
                      body};
  }
  if (sticks) return FreeChart{origin_};
  line.offset -= origin_.x * line.normal.x + origin_.y * line.normal.y;
  if (one_vertex) return SlipChart{origin_, line, body};
  // Sliding, the block is turned so that its vertices on the line lie on it, and held there: its
  // tilt and offset come from the geometry, not from the state the events' projections left,
  // which is off by rounding (a flat base 1.8e-17 rad off level, where the flat ground lays it at
  // 0 exactly; the rock that followed started at a tilt below the adaptive stepper's tolerance
  // times its scale, and its first step underflowed at tolerance 1e-12: random-0499).
  const auto second = std::find_if(active.begin(), active.end(), [&](const ActiveContact& a) {
    return a.pair.block != first.pair.block;
  });
  const Vec2 other = contacts_.body_vertex(second->pair.block);
  const Vec2 edge{other.x - body.x, other.y - body.y};
  double theta = std::atan2(line.direction.y, line.direction.x) - std::atan2(edge.y, edge.x);
  theta -= std::numbers::pi * std::round((theta - state_.theta) / std::numbers::pi);
  const SineCosine turn = sine_cosine(theta);
  const Vec2 r = rotate(body, turn.cos, turn.sin);
  return SlideChart{origin_, line, line.offset - (r.x * line.normal.x + r.y * line.normal.y),
                    theta};
}

std::vector<SeatPair> SeatSimulation::touching(const BlockState& s,
                                               const EventReport& report) const {
  const double tight = kContactHeight * R_;
  std::vector<SeatPair> out;
  std::optional<SeatPair> left;
  if (report.force && report.force->event == SeatEvent::leaves_end) left = report.force->pair;
  for (const SeatPair& pair :
       contacts_.touching(s, kSeatContactDrift * R_, left, report.arrived_point)) {
    const bool was_active = std::any_of(mode_.active.begin(), mode_.active.end(),
                                        [&](const ActiveContact& a) { return a.pair == pair; });
    // Another pair touches when it is closer than a new contact's tolerance, or in the seat (a
    // drifted contact can leave a vertex under the line of the segment it has just left).
    if (was_active || contacts_.pose(pair, s).gap <= tight) out.push_back(pair);
  }
  if (out.size() > static_cast<std::size_t>(kMaxSeatContacts)) {
    throw SimulationFailure("more than " + std::to_string(kMaxSeatContacts) +
                            " contacts with the seat at once at t = " + std::to_string(t_) + " s");
  }
  return out;
}

bool SeatSimulation::resolve_impacts(BlockState& s, const std::vector<SeatPair>& pairs,
                                     bool& impacted) {
  const double k2 = geometry_.inertia_per_mass();
  const double mu = scene_.contact.friction;
  for (int round = 0; round < kMaxImpactRounds; ++round) {
    std::vector<PlanarContact> all;
    double fastest = 0.0;
    int first = -1;
    for (const SeatPair& pair : pairs) {
      all.push_back(contact_of(pair, s));
      const double u_n = contact_velocity(all.back(), velocity_of(s)).normal;
      if (u_n < -velocity_tol_ && u_n < fastest) {
        fastest = u_n;
        first = static_cast<int>(all.size()) - 1;
      }
    }
    if (first < 0) return true;
    impacted = true;
    if (round == 0) {
      ++summary_.impacts;
      if (!summary_.first_impact_time) summary_.first_impact_time = t_;
    }
    const double before = kinetic_energy_per_mass(geometry_, s);
    const BlockState start = s;
    // A landing slower than the settling speed while another contact touches lays the block on
    // its contacts, their slip kept: the flat ground's rule for a corner landing that slowly while
    // the other touches (it lays the block flat, keeping its base's slip). Taken as an impact, the
    // landing is plastic and the other contact, turning about it, can leave faster than the
    // settling speed: a chain of ever smaller bounces that the flat ground ended went on
    // (random-0640 of the flat-seat cross-check: three more impacts and 1.2e-4 s to its rest).
    const bool laid = pairs.size() >= 2 && -fastest < settle_velocity();
    if (laid) {
      lay_on(pairs, s);
    } else {
      const double e = landing_restitution(scene_.contact.restitution, fastest, settle_velocity());
      const PlanarImpactInput one{
          {all[static_cast<std::size_t>(first)]}, velocity_of(s), k2, mu, e, R_};
      PlanarImpact impact = resolve_contact_impact(one);
      set_velocity(s, impact.after);
      // The paper's law at the contact that hits first, as on the flat ground; when that drives
      // another touching contact into the seat (a flat landing), all take their impulses together.
      bool others_approach = false;
      for (std::size_t i = 0; i < all.size(); ++i) {
        if (static_cast<int>(i) == first) continue;
        others_approach =
            others_approach || contact_velocity(all[i], velocity_of(s)).normal < -velocity_tol_;
      }
      if (others_approach) {
        const PlanarImpact together = simultaneous_impact({all, velocity_of(start), k2, mu, e, R_});
        if (together.determinacy != Determinacy::unique) ++summary_.painleve_events;
        // No consistent choice of impulses together (two pairs of one contact point, a block vertex
        // on a seat point, whose geometries differ by the contact tolerance): the first contact's
        // impact stands, and the next round takes any contact it leaves approaching.
        if (together.determinacy != Determinacy::inconsistent) {
          s = start;
          set_velocity(s, together.after);
        }
      }
    }
    const double after = kinetic_energy_per_mass(geometry_, s);
    if (before > 0) {
      summary_.max_impact_energy_gain =
          std::max(summary_.max_impact_energy_gain, (after - before) / before);
    }
    if (log_impacts_) {
      impact_log_.push_back({t_, start.omega, s.omega, before, after, ModeKind::flight});
    }
    if (laid) return true;
  }
  return false;
}

// Whether the fastest of the pairs that approach the seat lands plastically (none approaching: no):
// where it would bounce off slower than the settling speed (settling.hpp), as on the flat ground. A
// fold vertex of the type B block, sliding and turning in flight, bounced at e = 0.3 in flights of
// 2e-6 s, was found 1e-11 m inside the seat after each and landed again as fast as before, without
// end (record suite sample 116).
bool SeatSimulation::plastic_landing(const std::vector<SeatPair>& pairs) const {
  double fastest = 0.0;
  for (const SeatPair& pair : pairs) {
    fastest =
        std::min(fastest, contact_velocity(contact_of(pair, state_), velocity_of(state_)).normal);
  }
  return fastest < -velocity_tol_ &&
         lands_plastically(scene_.contact.restitution, fastest, settle_velocity());
}

SeatMode SeatSimulation::resolve(const EventReport& report) {
  const std::vector<SeatPair> pairs = touching(state_, report);
  // Between events the contacts hold only at the acceleration level: the integrator lets their
  // gaps and velocities drift, to its tolerance. The contact problem at the event reads contact
  // velocities against 1e-9 sqrt(gR), well below an adaptive solver's drift, so it is solved on the
  // state put back on the contacts that were active and still touch (the projection enter() makes
  // after the event, made before it too): a drifted pivot does not count as leaving.
  SeatMode holding;
  holding.rest = mode_.rest;
  for (const ActiveContact& a : mode_.active) {
    if (std::find(pairs.begin(), pairs.end(), a.pair) != pairs.end()) holding.active.push_back(a);
  }
  project(holding);
  // A plastic landing (e = 0, or a rebound slower than the settling speed) while another contact
  // holds: the impact is taken where every touching contact is on the seat, the block's velocity
  // left as it is. The event's crossing is located just past the gap's zero, the landing corner a
  // little inside the seat and the block turned past the pose where both touch; taken from there,
  // each landing of a rocking block at e = 0 gave back potential energy of that order (1e-12 of
  // g R), and the impacts' losses met it in a cycle of landings just faster than the settling speed
  // (random-0206 of the flat-seat cross-check: an impact every 2.4e-6 s without end). A bouncing
  // block is left where it is: raised out of the seat at every bounce, it would gain that energy.
  if (!holding.active.empty() && plastic_landing(pairs)) {
    std::vector<ActiveContact> on_seat;
    for (const SeatPair& pair : pairs) on_seat.push_back({pair, ContactState::stick});
    project_positions(on_seat, state_);
  }
  BlockState s = state_;
  const std::size_t logged = impact_log_.size();
  bool impacted = false;
  if (!resolve_impacts(s, pairs, impacted)) {
    throw SimulationFailure("impacts on the seat do not end at t = " + std::to_string(t_) + " s");
  }
  // An impact where two contacts or more touch, after which none of them moves faster than the
  // settling speed, lays the block at rest (the flat ground's lay_flat, and its rule that a corner
  // landing, or leaving after the impact, slower than that speed settles the block): it ends a Zeno
  // sequence of ever smaller bounces in finite time. Whatever the landing's speed: a landing just
  // faster than the settling speed whose impact leaves the other contact slower would rock on in
  // swings too small for the touch guard to see (rock_stocky, e = 0: in at 1.13 times the
  // settling speed, out at 0.47 times it, an impact every microsecond without end). A block that
  // still slides along the seat is laid on its contacts instead, as the flat ground's lay_flat
  // keeps its slide: their normal velocities to zero, their slip kept (lay_on). Laid at rest, a
  // block sliding at 1.4 m/s and rocking from corner to corner in ever smaller swings made an
  // impact every microsecond without end (random-0796 of the flat-seat cross-check, e = 0); left
  // as it was, a block whose other corner lifted slower than the settling speed rocked on where
  // the flat ground slides, and its slide ended 1.3e-5 R from the flat ground's (random-0395,
  // e = 0.55).
  bool landed = impacted && pairs.size() >= 2, sliding = false;
  const double settle = settle_velocity();
  for (const SeatPair& pair : pairs) {
    const ContactVelocity u = contact_velocity(contact_of(pair, s), velocity_of(s));
    landed = landed && std::abs(u.normal) <= settle;
    sliding = sliding || std::abs(u.tangent) > settle;
  }
  if (landed && !sliding) s.vx = s.vy = s.omega = 0.0;
  if (landed && sliding) {
    const double before = kinetic_energy_per_mass(geometry_, s);
    lay_on(pairs, s);
    if (before > 0) {
      summary_.max_impact_energy_gain =
          std::max(summary_.max_impact_energy_gain,
                   (kinetic_energy_per_mass(geometry_, s) - before) / before);
    }
  }
  // The contacts that can carry force: touching and not leaving.
  std::vector<SeatPair> carrying;
  PlanarForcesInput in{{},
                       velocity_of(s),
                       geometry_.inertia_per_mass(),
                       applied(t_),
                       scene_.contact.friction,
                       velocity_tol_,
                       scene_.g,
                       R_};
  for (const SeatPair& pair : pairs) {
    const PlanarContact c = contact_of(pair, s);
    if (contact_velocity(c, velocity_of(s)).normal > velocity_tol_) continue;
    carrying.push_back(pair);
    in.contacts.push_back(c);
  }
  SeatMode mode;
  state_ = s;
  if (carrying.empty()) return logged_mode(mode, logged);
  PlanarForces forces = resolve_contact_forces(in);
  if (forces.determinacy != Determinacy::unique) ++summary_.painleve_events;
  const bool still = std::abs(s.vx) <= velocity_tol_ && std::abs(s.vy) <= velocity_tol_ &&
                     R_ * std::abs(s.omega) <= velocity_tol_;
  // Just past a lift-off or slip-start guard, or where rest ended, the block cannot stay put,
  // whatever the tolerance of the contact problem lets it choose. Rest's range is of lambda over
  // the gravity factor 1 + lambda_v, the contact problem's tolerance is of the accelerations: with
  // a factor below 1 the problem at the event could still find rest, and the block went back to
  // rest, past its range, at every event (random-0126 of the flat-seat cross-check, at 0.87 g).
  if (still && holds_at_rest(forces, in.tolerance) && !report.force && !report.rest_ended) {
    // At rest every touching contact is kept: where rest ends is found on all of them.
    mode.rest = true;
    for (const SeatPair& pair : carrying) mode.active.push_back({pair, ContactState::stick});
    state_.vx = state_.vy = state_.omega = 0.0;
    return logged_mode(mode, logged);
  }
  // A still block that may not stay put (its rest has just ended, or a guard said a contact's
  // force left its cone) moves the way the first choice that lets it says. The contact problem's
  // tolerance also accepts choices that pin it, with forces a tolerance outside their cones; held
  // there, the individual forces of a statically indeterminate set (two corners sticking on a flat
  // seat) are not unique, the guards follow one arbitrary distribution, and the block swapped
  // which corner slips at every event without moving (random-0835 of the flat-seat cross-check:
  // 10,000 events within 1e-11 s).
  if (still && pins_body(fixed_rows(carrying, forces.states, s), R_)) {
    in.must_move = true;
    // Where rest ended the block is still laid exactly on its contacts, lambda kOnsetMargin past
    // the end of rest's range: the choice is made at the tolerance that range was found at. At the
    // contact problem's own tolerance a block with mu = b / h exactly (the suite's
    // mu_equals_a_over_b) took a rock its sticking pivot's friction could not hold, 1e-12 g
    // outside its cone, and slipped 4e-13 s later; the flat ground's closed forms slide it.
    if (report.rest_ended) in.tolerance = kRestTolerance;
    PlanarForces moving = resolve_contact_forces(in);
    if (moving.determinacy == Determinacy::inconsistent && report.rest_ended) {
      in.tolerance = PlanarForcesInput{}.tolerance;
      moving = resolve_contact_forces(in);
    }
    if (moving.determinacy != Determinacy::inconsistent) forces = moving;
  }
  for (std::size_t i = 0; i < carrying.size(); ++i) {
    ContactState state = forces.states[i];
    // The contact problem accepts forces a tolerance outside their cone (1e-9 g): just past the
    // guard that said the force left it, it can still choose the old state. The guard's crossing
    // decides then, as the flat ground's closed forms do: the contact lifts off, or slips against
    // its friction.
    if (report.force && report.force->pair == carrying[i]) {
      const auto before =
          std::find_if(mode_.active.begin(), mode_.active.end(),
                       [&](const ActiveContact& a) { return a.pair == carrying[i]; });
      if (before != mode_.active.end() && before->state == state) {
        if (report.force->event == SeatEvent::lift_off) {
          state = ContactState::off;
        } else if (state == ContactState::stick) {
          state = forces.tangent[i] > 0 ? ContactState::slip_negative : ContactState::slip_positive;
        }
      }
    }
    if (state != ContactState::off) mode.active.push_back({carrying[i], state});
  }
  // Pinned: the active contacts' normal velocities and the sticking ones' tangential velocities
  // leave the block no freedom.
  std::vector<ContactState> states;
  std::vector<SeatPair> active;
  for (const ActiveContact& a : mode.active) {
    active.push_back(a.pair);
    states.push_back(a.state);
  }
  mode.pinned = pins_body(fixed_rows(active, states, s), R_);
  return logged_mode(mode, logged);
}

// The rows of the contact values held fixed in these states at the pose: each carrying contact's
// normal velocity, and a sticking one's tangential velocity.
std::vector<Eigen::RowVector3d> SeatSimulation::fixed_rows(const std::vector<SeatPair>& pairs,
                                                           const std::vector<ContactState>& states,
                                                           const BlockState& s) const {
  std::vector<Eigen::RowVector3d> rows;
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    if (states[i] == ContactState::off) continue;
    const PlanarContact c = contact_of(pairs[i], s);
    rows.push_back(contact_row(c, c.normal));
    if (states[i] == ContactState::stick) rows.push_back(contact_row(c, contact_tangent(c)));
  }
  return rows;
}

SeatMode SeatSimulation::logged_mode(const SeatMode& mode, std::size_t logged) {
  for (std::size_t i = logged; i < impact_log_.size(); ++i)
    impact_log_[i].mode_after = kind_of(mode);
  return mode;
}

// No contact slips and the block does not accelerate (to the contact problem's tolerance, relative
// to g): the one test of rest, at an event and where rest's lambda range ends.
bool SeatSimulation::holds_at_rest(const PlanarForces& f, double relative_tolerance) const {
  const double tolerance = relative_tolerance * scene_.g;
  return std::none_of(f.states.begin(), f.states.end(), is_slip) &&
         std::abs(f.acceleration.x_dd) <= tolerance && std::abs(f.acceleration.y_dd) <= tolerance &&
         R_ * std::abs(f.acceleration.theta_dd) <= tolerance;
}

// The change dq with J dq = b that is least in the kinetic metric dx^2 + dy^2 + k^2 dtheta^2 (k the
// radius of gyration): the change impulses at the contacts would make. Least in the plain
// (x, y, theta) norm instead, a rotation is cheap and turns the block about its centre, sliding
// every contact point along its segment (far past a fold, at the type B block's height).
Eigen::Vector3d SeatSimulation::least_kinetic_change(const Eigen::MatrixXd& j,
                                                     const Eigen::VectorXd& b) const {
  const double k = std::sqrt(geometry_.inertia_per_mass());
  Eigen::MatrixXd scaled = j;
  scaled.col(2) /= k;
  Eigen::Vector3d change = scaled.completeOrthogonalDecomposition().solve(b);
  change(2) /= k;
  return change;
}

// Sets the pairs' normal velocities to zero with the least change in the kinetic metric, then,
// among the changes that leave those velocities alone, brings the pairs' slip along the seat back
// as near to what it was as they allow: on a flat seat, the flat ground's lay_flat, which keeps
// the base's slip velocity. With the kinetic metric alone (the centre's velocity kept) a block
// rocking as it slid went on at its slip plus omega times its height, 6e-5 R further than on the
// flat ground (SlidingBlockRockingAtZeroRestitutionIsLaidOnTheSeat).
void SeatSimulation::lay_on(const std::vector<SeatPair>& pairs, BlockState& s) const {
  const auto k = static_cast<Eigen::Index>(pairs.size());
  Eigen::MatrixXd normal(k, 3), tangent(k, 3);
  Eigen::VectorXd u(k);
  for (Eigen::Index i = 0; i < k; ++i) {
    const PlanarContact c = contact_of(pairs[static_cast<std::size_t>(i)], s);
    normal.row(i) = contact_row(c, c.normal);
    tangent.row(i) = contact_row(c, contact_tangent(c));
    u(i) = contact_velocity(c, velocity_of(s)).normal;
  }
  const Eigen::Vector3d least = least_kinetic_change(normal, -u);
  Eigen::Vector3d dv = least;
  // Within the changes that keep the normal velocities, the one that takes the slip back. The
  // normals are the seat's or the block's edges' (turned by the block's tilt, within the contact
  // height over R): their rank is taken to the seat's contact drift, as pins_body takes it.
  const Eigen::Vector3d theta_over_length(1, 1, 1 / R_);
  Eigen::FullPivLU<Eigen::MatrixXd> lu(normal * theta_over_length.asDiagonal());
  lu.setThreshold(kSeatContactDrift);
  if (lu.rank() < 3) {
    const Eigen::MatrixXd free = theta_over_length.asDiagonal() * lu.kernel();
    const Eigen::MatrixXd slip_change = tangent * free;
    dv += free * slip_change.completeOrthogonalDecomposition().solve(-tangent * dv);
  }
  // Taking the slip back can add kinetic energy; the least change never does (keeps_slip).
  const BlockState before = s;
  const auto apply = [&](const Eigen::Vector3d& change) {
    s = before;
    s.vx += change(0);
    s.vy += change(1);
    s.omega += change(2);
  };
  apply(dv);
  if (!keeps_slip(kinetic_energy_per_mass(geometry_, before),
                  kinetic_energy_per_mass(geometry_, s))) {
    apply(least);
  }
}

// Puts the contacts' gaps back to zero: the least change of the pose.
void SeatSimulation::project_positions(const std::vector<ActiveContact>& active,
                                       BlockState& s) const {
  if (active.empty()) return;
  // A sticking vertex goes back to where it stuck, too: held by its velocity alone, it crept
  // along the seat by the integrator's error (a block rocking on its corner at an adaptive
  // tolerance of 1e-8 came to rest 1e-8 to 1e-7 R from the flat ground's place, where the
  // flat ground's pivot does not move).
  std::vector<std::pair<SeatPair, double>> anchored;
  for (const ActiveContact& a : active) {
    if (a.state != ContactState::stick) continue;
    if (const auto place = anchor_of(a.pair)) anchored.emplace_back(a.pair, *place);
  }
  const auto k = static_cast<Eigen::Index>(active.size());
  const auto rows = k + static_cast<Eigen::Index>(anchored.size());
  for (int iteration = 0; iteration < kProjectionIterations; ++iteration) {
    Eigen::MatrixXd j(rows, 3);
    Eigen::VectorXd gap(rows);
    for (Eigen::Index i = 0; i < k; ++i) {
      const PairPose p = contacts_.pose(active[static_cast<std::size_t>(i)].pair, s);
      j.row(i) = contact_row(p.contact, p.contact.normal);
      gap(i) = p.gap;
    }
    for (std::size_t a = 0; a < anchored.size(); ++a) {
      const PairPose p = contacts_.pose(anchored[a].first, s);
      const auto i = k + static_cast<Eigen::Index>(a);
      j.row(i) = contact_row(p.contact, contact_tangent(p.contact));
      gap(i) = p.along - anchored[a].second;
    }
    if (gap.cwiseAbs().maxCoeff() <= std::numeric_limits<double>::epsilon() * R_) break;
    const Eigen::Vector3d dq = least_kinetic_change(j, -gap);
    s.x += dq(0);
    s.y += dq(1);
    s.theta += dq(2);
  }
}

// Puts the active contacts' gaps back to zero (the least change) and their normal
// velocities (and a sticking one's tangential velocity) too.
void SeatSimulation::project(const SeatMode& mode) {
  if (mode.active.empty()) return;
  project_positions(mode.active, state_);
  // A chart that holds the contacts takes only the rates they leave free (the flat ground's modes
  // too: a rock takes theta' and drops a stopped slide's residual slip). Projected, that residual
  // (5.7e-15 m/s, where the slide's stop was located) went into theta', the rock started turning
  // at 5e-15 rad/s where the flat ground's starts at 0, and at tolerance 1e-10 the adaptive
  // stepper's first step, scaled by the state over its derivative, underflowed (random-0499).
  if (mode.rest || !std::holds_alternative<FreeChart>(chart_of(mode))) return;
  std::vector<Eigen::RowVector3d> rows;
  std::vector<double> velocities;
  for (const ActiveContact& a : mode.active) {
    const PlanarContact c = contact_of(a.pair, state_);
    const ContactVelocity u = contact_velocity(c, velocity_of(state_));
    rows.push_back(contact_row(c, c.normal));
    velocities.push_back(u.normal);
    if (a.state == ContactState::stick) {
      rows.push_back(contact_row(c, contact_tangent(c)));
      velocities.push_back(u.tangent);
    }
  }
  Eigen::MatrixXd j(static_cast<Eigen::Index>(rows.size()), 3);
  Eigen::VectorXd u(static_cast<Eigen::Index>(rows.size()));
  for (std::size_t i = 0; i < rows.size(); ++i) {
    j.row(static_cast<Eigen::Index>(i)) = rows[i];
    u(static_cast<Eigen::Index>(i)) = velocities[i];
  }
  const Eigen::Vector3d dv = least_kinetic_change(j, -u);
  state_.vx += dv(0);
  state_.vy += dv(1);
  state_.omega += dv(2);
}

// Whether the block at rest on its active contacts stays at rest under lambda (with g).
bool SeatSimulation::rest_holds(double lambda) const {
  PlanarForcesInput in{{},
                       {0.0, 0.0, 0.0},
                       geometry_.inertia_per_mass(),
                       {lambda * scene_.g, -scene_.g},
                       scene_.contact.friction,
                       velocity_tol_,
                       scene_.g,
                       R_};
  in.tolerance = kRestTolerance;
  for (const ActiveContact& a : mode_.active) in.contacts.push_back(contact_of(a.pair, state_));
  // The first consistent choice decides rest; whether others disagree does not matter here.
  return holds_at_rest(resolve_contact_forces(in, LcpSearch::first_consistent), in.tolerance);
}

// The lambda range of rest: rest holds on an interval of lambda (the contact forces that balance
// the load form a convex cone), found by doubling then halving from lambda = 0 each way.
void SeatSimulation::set_rest_thresholds(SeatMode& mode) const {
  const auto edge = [&](double direction) {
    double inside = 0.0, outside = direction;
    while (rest_holds(outside)) {
      inside = outside;
      if (std::abs(outside) >= kRestSearchLimit)
        return direction * std::numeric_limits<double>::infinity();
      outside *= 2.0;
    }
    for (int i = 0; i < kRestThresholdHalvings && std::abs(outside - inside) > 0.0; ++i) {
      const double middle = 0.5 * (inside + outside);
      if (middle == inside || middle == outside) break;
      (rest_holds(middle) ? inside : outside) = middle;
    }
    return inside;
  };
  mode.rest_high = edge(1.0);
  mode.rest_low = edge(-1.0);
}

double SeatSimulation::rest_margin(double t, const MotionPiece& piece,
                                   const MotionPiece& vertical) const {
  const double lambda = piece.lambda(t), factor = 1.0 + vertical.lambda(t);
  return kOnsetMargin +
         std::min({mode_.rest_high * factor - lambda, lambda - mode_.rest_low * factor, factor});
}

void SeatSimulation::enter(const SeatMode& next, const EventReport& report) {
  const bool first = summary_.modes.empty();
  const ModeKind before = kind_of(mode_);
  mode_ = next;
  project(mode_);
  if (mode_.rest) {
    // Laid on its contacts, a resting block can touch the seat where it did not at the event: a
    // corner 2e-9 R above it while the block was turned 3e-9 rad (random-0193 of the flat-seat
    // cross-check at tolerance 1e-12, at rest on its right corner and the joint under its base).
    // Rest's range is found on every contact it rests on; found without the left corner, it ended
    // when lambda changed sign, and the three contacts, pinned, swapped which one slips 10,000
    // times within 1e-7 s.
    for (const SeatPair& pair : touching(state_, report)) {
      const bool active = std::any_of(mode_.active.begin(), mode_.active.end(),
                                      [&](const ActiveContact& a) { return a.pair == pair; });
      if (!active) mode_.active.push_back({pair, ContactState::stick});
    }
    set_rest_thresholds(mode_);
  }
  std::vector<std::pair<SeatPair, double>> anchors;
  for (const ActiveContact& a : mode_.active) {
    if (a.state != ContactState::stick || a.pair.kind != ContactKind::block_vertex) continue;
    anchors.emplace_back(a.pair, anchor_of(a.pair).value_or(contacts_.pose(a.pair, state_).along));
  }
  anchors_ = std::move(anchors);
  entered(before, kind_of(mode_), first, false);
}

void SeatSimulation::observe(const BlockState& s) {
  observer_.observe_state(s);
  deepest_ = std::max(deepest_, contacts_.penetration(s));
}

void SeatSimulation::stop_at(double t, const BlockState& s, SeatEvent why) {
  t_ = t;
  state_ = s;
  if (why == SeatEvent::overturns) {
    state_.theta = contacts_.overturn_theta(geometry_, s.theta);
    summary_.overturned = true;
    summary_.overturn_time = t;
  } else {
    summary_.fell = true;
    summary_.fell_time = t;
  }
  observer_.observe_state(state_);
  stopped_ = true;
}

// At rest the block does not move; rest ends where lambda leaves the rest range (by the onset
// margin).
SeatSimulation::EventReport SeatSimulation::advance_rest(double t_stop) {
  const MotionPiece& piece = motion_.piece_at(t_);
  const MotionPiece& vertical = vertical_.piece_at(t_);
  const auto forces_at = [&](double t) {
    const Vec2 f = applied(t);
    return ContactForces{-f.x, -f.y};
  };
  EventReport report;
  if (EventLoop::advance_rest(
          piece, t_stop, false, [&](double t) { return rest_margin(t, piece, vertical); },
          forces_at)) {
    report.by_event = true;
    report.rest_ended = true;
  }
  return report;
}

// A watched vertex's clearance is its height over the seat between the seat's ends and its distance
// from the nearer end past them: it jumps from below zero to above where a vertex under a segment's
// line passes that segment's end, and one step can hold the whole dip, which the guard's samples
// then miss (the type B block turning downstream about its fold, its toe at the seat's downstream
// end: the toe reached the incline 3e-6 s into a 1.6e-4 s step and was past the seat's end 6e-6 s
// later; the block went on turning, its face 0.17 m into the incline, held by nothing). Where a
// watched vertex passes an end in the step, its height just inside the end says whether it went
// under the line there; if it did, its touch is located on that height, before the end.
template <class StateAt>
SeatSimulation::Crossing SeatSimulation::touch_before_an_end(const SeatSystem& system,
                                                             const StateAt& state_at, double t0,
                                                             double t1) const {
  Crossing found;
  const double first = contacts_.seat_point(0).x;
  const double last = contacts_.seat_point(contacts_.point_count() - 1).x;
  const double time_tolerance = kEventTimeTolerance * (1.0 + t1);
  const std::vector<int>& watched = system.watched_vertices();
  for (std::size_t k = 0; k < watched.size(); ++k) {
    const int i = watched[k];
    const double x0 = contacts_.vertex_at(i, state_at(t0)).x;
    const double x1 = contacts_.vertex_at(i, state_at(t1)).x;
    if (x0 < first || x0 > last || (x1 >= first && x1 <= last)) continue;
    // Inside the seat's range > 0: how far the vertex is from the end it passes.
    const double end = x1 > last ? last : first;
    const auto inside = [&](double x) {
      return (x1 > last ? end - contacts_.vertex_at(i, state_at(x)).x
                        : contacts_.vertex_at(i, state_at(x)).x - end);
    };
    const double inside0 = std::abs(x0 - end);
    if (!(inside0 > 0)) continue;
    const double passes =
        locate_crossing(inside, t0, t1, inside0, inside(t1), time_tolerance).before;
    const auto height = [&](double x) { return contacts_.vertex_clearance(i, state_at(x)) / R_; };
    const double h0 = height(t0), h_end = height(passes);
    if (!(h0 > kArmingMargin) || h_end > 0) continue;
    const Bracket touch = locate_crossing(height, t0, passes, h0, h_end, time_tolerance);
    if (touch.after < found.after) {
      found = {kFirstClearanceGuard + static_cast<int>(k), touch.after, touch.before};
    }
  }
  return found;
}

// A bounce's landing in flight, found by a guard that was not armed when the flight began: the
// vertex that bounced off the seat arms only at a step's end once above kArmingMargin R, and
// unarmed it fires that far inside the seat. A bounce that rises less than the margin, or lands
// within the step it left in (random-0246 of the flat-seat cross-check: a flight of 5e-5 s rising
// 2e-9 R inside a 2.5e-4 s RK4 step), landed 1e-12 R inside the seat, 6e-9 s late, where the flat
// ground's closed-form flight lands at zero, and the next impact's velocities differed from the
// flat ground's by 1e-8 of sqrt(g R). Where the vertex rose above the seat (by more than its
// clearance's rounding noise) before the crossing, its landing is where it comes back to zero.
template <class GuardsAt>
SeatSimulation::Crossing SeatSimulation::landing_at_zero(
    const GuardsAt& guards_at, double t0, GuardWatch<SeatSystem::kGuards>::Crossing found,
    double noise) {
  const auto i = static_cast<std::size_t>(found.which);
  const auto f = [&](double x) { return guards_at(x)[i]; };
  const double spacing = (found.after - t0) / kInteriorSamples;
  bool rose = false;
  double last = t0, f_last = 0.0;
  for (int k = 1; k <= kInteriorSamples; ++k) {
    const double x = k == kInteriorSamples ? found.after : t0 + k * spacing;
    const double fx = f(x);
    if (rose && fx <= 0) {
      const Bracket zero =
          locate_crossing(f, last, x, f_last, fx, kEventTimeTolerance * (1.0 + found.after));
      return {found.which, zero.after, zero.before};
    }
    rose = rose || fx > noise;
    last = x;
    f_last = fx;
  }
  return found;
}

// Where a flight's bounce lands at zero clearance, or a vertex passing a seat's end went under the
// seat's line first, the crossing the guards found is moved there.
template <class Ode, class GuardsAt, class StateAt>
SeatSimulation::Crossing SeatSimulation::refine_crossing(
    const Ode& ode, const GuardWatch<SeatSystem::kGuards>& watch, const GuardsAt& guards_at,
    const StateAt& state_at, double t0, double t1, Crossing found, ModeKind kind) const {
  const SeatSystem& system = ode.system();
  if (kind == ModeKind::flight && found.which >= 0 && !watch.armed(found.which) &&
      system.event(found.which) == SeatEvent::touches) {
    found = landing_at_zero(guards_at, t0, found, clearance_noise(state_));
  }
  const Crossing under = touch_before_an_end(system, state_at, t0, t1);
  if (under.which >= 0 && under.after < found.after) found = under;
  return found;
}

template <class Ode, class StateAt, class ForcesAt>
void SeatSimulation::note_contact_violation(const Ode& ode, double t, const StateAt& state_at,
                                            const ForcesAt&) {
  const SeatSystem& system = ode.system();
  if (system.active_count() == 0) return;
  const FixedStateForces f = system.solve(t, state_at(t));
  for (int i = 0; i < system.active_count(); ++i) {
    const auto at = static_cast<std::size_t>(i);
    summary_.max_contact_violation =
        std::max({summary_.max_contact_violation, -f.normal[at] / scene_.g,
                  (std::abs(f.tangent[at]) - scene_.contact.friction * f.normal[at]) / scene_.g});
  }
}

template <class Ode>
SeatSimulation::EventReport SeatSimulation::on_event(const Ode& ode, int which, double t_event,
                                                     const BlockState& at_event) {
  const SeatSystem& system = ode.system();
  SeatEvent event = system.event(which);
  EventReport report;
  report.by_event = true;
  report.arrived_point = event == SeatEvent::touches ? system.watched_point(which) : -1;
  // The face next to the base lands as the block reaches the overturning tilt (a rectangle's
  // top corner at theta = pi/2): that is overturning, whichever guard rounding put first. The
  // tilt is read with every touching contact put back on the seat: the active ones have drifted
  // (by the integrator's error, far more than 1e-9 rad at an adaptive tolerance of 1e-8), and a
  // pivot sunk into the seat lets the face's far corner touch before the tilt is reached.
  if (event == SeatEvent::touches) {
    std::vector<ActiveContact> landed;
    for (const SeatPair& pair : touching(at_event, report)) {
      landed.push_back({pair, ContactState::stick});
    }
    BlockState on_seat = at_event;
    project_positions(landed, on_seat);
    if (contacts_.overturn_margin(geometry_, on_seat.theta) <= kContactHeight) {
      event = SeatEvent::overturns;
      report.arrived_point = -1;
    }
  }
  if (event == SeatEvent::lift_off || event == SeatEvent::friction_limit ||
      event == SeatEvent::leaves_end) {
    const auto contact = static_cast<std::size_t>((which - 2) / kSeatContactGuards);
    report.force = ForceEvent{mode_.active[contact].pair, event};
  }
  if (event == SeatEvent::overturns || event == SeatEvent::falls) {
    stop_at(t_event, at_event, event);
    return {};
  }
  t_ = t_event;
  state_ = at_event;
  return report;
}

bool SeatSimulation::holds_under(const MotionPiece& piece) const {
  if (mode_.rest) return rest_margin(t_, piece, vertical_.piece_at(t_)) > 0;
  const SeatSystem next = system(piece);
  const auto guards = next.guards(t_, state_);
  for (int i = 0; i < SeatSystem::kGuards; ++i) {
    const SeatEvent e = next.event(i);
    if ((e == SeatEvent::lift_off || e == SeatEvent::friction_limit) &&
        !(guards[static_cast<std::size_t>(i)] > 0)) {
      return false;
    }
  }
  return true;
}

void SeatSimulation::place_at_start() {
  const Vec2 centre = contacts_.rest_centre();
  state_.x = centre.x;
  state_.y = centre.y;
  if (scene_.initial.theta != 0.0) {
    // Released from rest turned about its pivot, as the flat ground releases it on a base corner.
    const double theta = scene_.initial.theta;
    const Vertex turned =
        tilt_on_seat(scene_.seat->points, scene_block_vertices(scene_), theta, kContactHeight * R_)
            .centre;
    state_.x = turned[0];
    state_.y = turned[1];
    state_.theta = theta;
  }
  origin_ = {state_.x, centre.y - geometry_.rest_height()};
}

SeatSimulation::EventReport SeatSimulation::advance(const MotionPiece& piece, double t_stop) {
  if (mode_.rest) return advance_rest(t_stop);
  const SeatSystem moving = system(piece);
  const ModeKind kind = kind_of(mode_);
  EventReport report;
  std::visit(
      [&](const auto& chart) {
        const SeatOde ode(moving, chart);
        if constexpr (std::is_same_v<std::decay_t<decltype(chart)>, FlightChart>) {
          if (vertical_.piece_at(t_).is_zero()) {
            ClosedFormFlight flight(ode.coordinates(state_), state_, piece, t_, scene_.g);
            report = integrate_with(ode, flight, piece, t_stop, kind);
            return;
          }
        }
        with_scene_stepper<decltype(ode)::N>(scene_.solver, ode.scale(), [&](auto& stepper) {
          report = integrate_with(ode, stepper, piece, t_stop, kind);
        });
      },
      chart_of(mode_));
  return report;
}

ContactForces SeatSimulation::forces_now() const {
  if (!stopped_ && mode_.rest) {
    const Vec2 f = applied(t_);
    return {-f.x, -f.y};
  }
  if (!stopped_ && !mode_.active.empty()) {
    const SeatSystem now = system(motion_.piece_at(t_));
    return now.forces(t_, state_);
  }
  return {0.0, 0.0};
}

}  // namespace

SimulationWithHistory simulate_on_seat(const Scene& scene, double output_interval) {
  SeatSimulation simulation(scene, output_interval);
  return run_to_end(simulation);
}

}  // namespace blockfrag
