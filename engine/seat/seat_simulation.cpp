#include "engine/seat/seat_simulation.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "engine/integrate/guard_crossing.hpp"
#include "engine/integrate/root_finding.hpp"
#include "engine/integrate/with_stepper.hpp"
#include "engine/scene/seat.hpp"
#include "engine/seat/closed_form_flight.hpp"
#include "engine/seat/hull_watch.hpp"
#include "engine/seat/seat_ground.hpp"
#include "engine/seat/seat_ode.hpp"
#include "engine/sine_cosine.hpp"
#include "engine/tolerances.hpp"

namespace blockfrag {

SeatSystemContext SeatSimulation::system_context(MotionPiece& piece) {
  return {&contacts_,      &geometry_,
          &piece,          &vertical_.piece_at(t_),
          scene_.g,        scene_.contact.friction,
          kFallDepth * R_, external_};
}

SeatSystem& SeatSimulation::build_system(MotionPiece& piece) {
  // Vertices and points in an active contact are not watched for touching: they touch.
  const WatchedList vertices = watched_block_vertices(contacts_, hull_watch_, mode_.active);
  WatchedList points;
  const double near = kSeatContactDrift * R_;
  for (int k = 0; k < contacts_.point_count(); ++k) {
    if (!contacts_.touches_edges(k)) continue;
    const Vec2 p = contacts_.seat_point(k);
    const bool active = std::any_of(mode_.active.begin(), mode_.active.end(), [&](const auto& a) {
      if (a.pair.kind == ContactKind::seat_point) return a.pair.seat == k;
      const Vec2 v = contacts_.vertex_at(a.pair.block, state_);
      // hypot is never below the larger of its arguments: farther than `near` along x or y, the
      // vertex is farther in all (most points, at each piece of a record), without the hypot.
      const double dx = v.x - p.x, dy = v.y - p.y;
      if (std::max(std::abs(dx), std::abs(dy)) > near) return false;
      return std::hypot(dx, dy) <= near;
    });
    if (!active) points.push_back(k);
  }
  return system_for(system_context(piece), vertices, points);
}

SeatSystem& SeatSimulation::system_for(const SeatSystemContext& context,
                                       const WatchedList& vertices, const WatchedList& points) {
  if (system_ && system_->lays_out(context, mode_.active, vertices, points)) {
    system_->start_piece(context);
    return *system_;
  }
  return system_.emplace(context, mode_.active, vertices, points);
}

// The chart of the active contacts (engine/seat/seat_chart.hpp). Contacts of block vertices on
// collinear segments (a flat seat's joint, which a vertex there touches on both sides) act as one
// line: one vertex on it pivots or slips, two or more slide along it.
SeatChart SeatSimulation::chart_of(const SeatMode& mode) const {
  const std::vector<ActiveContact>& active = mode.active;
  // In flight theta is linear in time unless a load turns the block or couples its turning to
  // its sliding (the reservoir's).
  if (active.empty() && external_ != nullptr) return FreeChart{origin_};
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
  // which is off by rounding: a base a few 1e-17 rad off level starts the rock that follows at a
  // tilt below the adaptive stepper's tolerance times its scale, where its first step underflows
  // (ARockFromAStoppedSlideStartsAtRestAsOnTheFlatGround).
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
  MotionPiece& piece = motion_.piece_at(t_);
  MotionPiece& vertical = vertical_.piece_at(t_);
  const auto forces_at = [&](double t) {
    const Vec2 f = load_at(t, state_).force;
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
  const WatchedList& watched = system.watched_vertices();
  if (watched.empty()) return found;
  const double first = contacts_.seat_point(0).x;
  const double last = contacts_.seat_point(contacts_.point_count() - 1).x;
  const double time_tolerance = kEventTimeTolerance * (1.0 + t1);
  const BlockState s0 = state_at(t0), s1 = state_at(t1);
  // No vertex passes an end: the block's centre stays far enough inside both (a flat seat's ends,
  // 1e4 R away, at every step).
  if (contacts_.within_ends(s0) && contacts_.within_ends(s1)) return found;
  std::array<Vec2, kMaxSeatClearances> world0, world1;  // the first vertex_count() set here
  contacts_.world_vertices(s0, world0);
  contacts_.world_vertices(s1, world1);
  for (std::size_t k = 0; k < watched.size(); ++k) {
    const int i = watched[k];
    const double x0 = world0[static_cast<std::size_t>(i)].x;
    const double x1 = world1[static_cast<std::size_t>(i)].x;
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
// within the step it left in, would land inside the seat and late, where the flat ground's
// closed-form flight lands at zero (BounceWithinOneStepLandsWhereTheFlatGroundsDoes). Where the
// vertex rose above the seat (by more than its
// clearance's rounding noise) before the crossing, its landing is where it comes back to zero.
template <class GuardsAt>
SeatSimulation::Crossing SeatSimulation::landing_at_zero(
    const GuardsAt& guards_at, double t0, GuardWatch<SeatSystem::kGuards>::Crossing found,
    double noise) {
  const auto f = [&](double x) { return guard_from(guards_at, found.which, x); };
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

// In flight a guard that was not armed fires only where the watch's samples find it below its
// level (GuardWatch::fires_below), and a bounce that lands and goes on into the block within one
// spacing of them is missed (the type B block's base bouncing off the seat's upstream corner at
// e = 0.039, back on it 0.35 ms into a step sampled every 7.9 ms: the corner went 5e-5 m into the
// block and was still in it where the next crossing was found, the heel passing under the seat's
// end, and the touch there found only the corner, on the upstream face and leaving it; the heel's
// guard refired every 3e-12 s). Sampled up to the crossing as no_earlier_dip samples the armed
// guards, an unarmed clearance below its level landed first: where it came back to zero after
// rising off the seat.
template <class GuardsAt>
SeatSimulation::Crossing SeatSimulation::unarmed_landing_before(
    const SeatSystem& system, const GuardWatch<SeatSystem::kGuards>& watch,
    const GuardsAt& guards_at, double t0, Crossing found, double noise) {
  constexpr std::size_t kFirst = kFirstClearanceGuard;
  const std::size_t end =
      kFirst + system.watched_vertices().size() + system.watched_points().size();
  std::array<bool, SeatSystem::kGuards> wanted{};
  std::array<double, SeatSystem::kGuards> a, fa;  // each one's last sample above zero
  bool any = false;
  // The watched clearances alone: an unwatched slot's arming is not set (a lean pivot's seat
  // points).
  for (const int i : watch.live()) {
    const auto g = static_cast<std::size_t>(i);
    if (g < kFirst || g >= end) continue;
    wanted[g] = i != found.which && !watch.armed(i);
    a[g] = t0;
    fa[g] = watch.values()[g];
    any = any || wanted[g];
  }
  if (!any) return found;
  const double spacing = (found.after - t0) / kInteriorSamples;
  const double tolerance = kEventTimeTolerance * (1.0 + found.after);
  for (int k = 1; k <= kInteriorSamples; ++k) {
    const double x = k == kInteriorSamples ? found.after : t0 + k * spacing;
    const std::array<double, SeatSystem::kGuards> at_x = guards_from(guards_at, x, wanted);
    Crossing first;
    for (std::size_t g = kFirst; g < end; ++g) {
      if (!wanted[g]) continue;
      if (at_x[g] > watch.fires_below(static_cast<int>(g))) {
        if (at_x[g] > 0) {
          a[g] = x;
          fa[g] = at_x[g];
        }
        continue;
      }
      const Crossing landed = landing_between(guards_at, static_cast<int>(g), a[g], fa[g], x,
                                              at_x[g], noise, tolerance);
      if (landed.after < first.after) first = landed;
    }
    if (first.which >= 0) return first;
  }
  return found;
}

// The zero crossing in [a, b] of guard g, f(b) <= 0, after a rise above the noise: where f(a) is
// not above it (a bounce off the seat at the step's start), the spacing is halved towards a until
// it is. None (which -1) where the guard never rose.
template <class GuardsAt>
SeatSimulation::Crossing SeatSimulation::landing_between(const GuardsAt& guards_at, int g, double a,
                                                         double fa, double b, double fb,
                                                         double noise, double tolerance) {
  const auto f = [&](double x) { return guard_from(guards_at, g, x); };
  double probe = b;
  while (!(fa > noise)) {
    probe = 0.5 * (a + probe);
    if (!(probe > a)) return {};
    const double fp = f(probe);
    if (fp > noise) {
      a = probe;
      fa = fp;
    } else if (fp <= 0) {
      b = probe;
      fb = fp;
    }
  }
  const Bracket zero = locate_crossing(f, a, b, fa, fb, tolerance);
  return {g, zero.after, zero.before};
}

// Where a flight's bounce lands at zero clearance, an unarmed clearance the samples missed landed
// first, or a vertex passing a seat's end went under the seat's line first, the crossing the guards
// found is moved there.
template <class Ode, class GuardsAt, class StateAt>
SeatSimulation::Crossing SeatSimulation::refine_crossing(
    const Ode& ode, const GuardWatch<SeatSystem::kGuards>& watch, const GuardsAt& guards_at,
    const StateAt& state_at, double t0, double t1, Crossing found, ModeKind kind) const {
  const SeatSystem& system = ode.system();
  if (kind == ModeKind::flight && found.which >= 0 &&
      system.event(found.which) == SeatEvent::touches) {
    if (!watch.armed(found.which)) {
      found = landing_at_zero(guards_at, t0, found, clearance_noise(state_));
    }
    found = unarmed_landing_before(system, watch, guards_at, t0, found, clearance_noise(state_));
  }
  // Turning about a pivot well inside the seat's ends, no vertex can pass one (a flat seat's).
  if constexpr (std::is_same_v<Ode, SeatOde<PivotChart>>) {
    if (contacts_.within_ends_turning_about(ode.chart().point)) return found;
  }
  const Crossing under = touch_before_an_end(system, state_at, t0, t1);
  if (under.which >= 0 && under.after < found.after) found = under;
  return found;
}

template <class Ode, class ForcesAt>
void SeatSimulation::note_contact_violation(const Ode& ode, double t, const BlockState& s,
                                            const ForcesAt&) {
  SeatSystem& system = ode.system();
  if (system.active_count() == 0) return;
  // How far a contact's force lies outside its cone (below zero, or past friction), in g.
  const auto note = [&](double normal, double tangent) {
    summary_.max_contact_violation =
        std::max({summary_.max_contact_violation, -normal / scene_.g,
                  (std::abs(tangent) - scene_.contact.friction * normal) / scene_.g});
  };
  if (system.lean_pivot()) {
    const SeatSystem::PivotForce f = system.pivot_force(t, s);
    note(f.normal, f.tangent);
    return;
  }
  const FixedStateForces& f = system.solve(t, s);
  for (int i = 0; i < system.active_count(); ++i) {
    const auto at = static_cast<std::size_t>(i);
    note(f.normal[at], f.tangent[at]);
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
  // top corner at theta = pi/2): that is overturning, whichever guard rounding put first.
  if (event == SeatEvent::touches) {
    report.touching = touching(at_event, report);
    if (lies_overturned(at_event, *report.touching)) {
      event = SeatEvent::overturns;
      report.arrived_point = -1;
    }
  }
  // A vertex of a block beside the seat that comes into the seat's range under an end has not
  // touched it: the block has gone down past that end (the type B block falling upstream of its
  // seat, its downstream corner 0.59 m under the seat's end; taken as a touch, no contact was found
  // there, and the vertex's guard fired again 7e-10 s on, without end).
  if (event == SeatEvent::touches && report.arrived_point < 0) {
    const int vertex =
        system.watched_vertices()[static_cast<std::size_t>(which - kFirstClearanceGuard)];
    const double drift = kSeatContactDrift * R_;
    if (contacts_.under_an_end(vertex, at_event, drift, drift)) {
      event = SeatEvent::falls;
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

template <class Ode>
void SeatSimulation::ended_piece(const Ode& ode,
                                 const std::array<double, SeatSystem::kGuards>& guards) {
  // Only the guards watch_at_piece_start takes are kept: copying all 64 slots at each piece was
  // most of keeping them.
  const SeatSystem& system = ode.system();
  piece_end_.s = state_;
  piece_end_.vertices = system.watched_vertices();
  piece_end_.points = system.watched_points();
  piece_end_.guards[0] = guards[0];
  piece_end_.guards[1] = guards[1];
  const auto first_clearance = static_cast<std::size_t>(kFirstClearanceGuard);
  std::copy_n(guards.begin() + first_clearance,
              piece_end_.vertices.size() + piece_end_.points.size(),
              piece_end_.guards.begin() + first_clearance);
  piece_end_ready_ = true;
}

template <class Ode>
GuardWatch<SeatSystem::kGuards> SeatSimulation::watch_at_piece_start(const Ode& ode, double t,
                                                                     const OdeState<Ode::N>& q) {
  const bool from_end = from_piece_end_;
  from_piece_end_ = false;
  if (!from_end) return watch_guards(ode, t, q);
  SeatSystem& system = ode.system();
  const BlockState s = ode.full(t, q);
  const bool same_pose =
      std::bit_cast<std::uint64_t>(s.x) == std::bit_cast<std::uint64_t>(piece_end_.s.x) &&
      std::bit_cast<std::uint64_t>(s.y) == std::bit_cast<std::uint64_t>(piece_end_.s.y) &&
      std::bit_cast<std::uint64_t>(s.theta) == std::bit_cast<std::uint64_t>(piece_end_.s.theta);
  if (!same_pose || !(system.watched_vertices() == piece_end_.vertices) ||
      !(system.watched_points() == piece_end_.points)) {
    return watch_guards(ode, t, q);
  }
  GuardClaims contacts{};
  const auto first_clearance = static_cast<std::size_t>(kFirstClearanceGuard);
  std::fill_n(contacts.begin() + 2, kSeatContactGuards * system.active_count(), true);
  std::array<double, SeatSystem::kGuards> at_start = system.guards(t, s, contacts);
  at_start[0] = piece_end_.guards[0];
  at_start[1] = piece_end_.guards[1];
  const std::size_t watched = piece_end_.vertices.size() + piece_end_.points.size();
  std::copy_n(piece_end_.guards.begin() + first_clearance, watched,
              at_start.begin() + first_clearance);
  return GuardWatch<SeatSystem::kGuards>(at_start, ode.live_slots());
}

bool SeatSimulation::holds_under(MotionPiece& piece) {
  if (mode_.rest) return rest_margin(t_, piece, vertical_.piece_at(t_)) > 0;
  // Where the mode holds, the next piece's advance starts here, in this mode, under this piece:
  // the system that found it holding is that advance's.
  system_ready_ = build_system(piece).contacts_hold(t_, state_);
  return system_ready_;
}

void SeatSimulation::place_at_start() {
  const Vec2 centre = contacts_.rest_centre();
  state_.x = centre.x;
  state_.y = centre.y;
  const double theta = scene_.initial.theta, omega = scene_.initial.omega;
  if (theta != 0.0 || omega != 0.0) {
    // Released turned about its pivot, as the flat ground releases it on a base corner.
    const SeatTilt tilt = tilt_on_seat(scene_.seat->points, scene_block_vertices(scene_), theta,
                                       kContactHeight * R_, omega);
    state_.x = tilt.centre[0];
    state_.y = tilt.centre[1];
    state_.theta = theta;
    if (omega != 0.0) {
      state_.vx = -omega * (tilt.centre[1] - tilt.pivot[1]);
      state_.vy = omega * (tilt.centre[0] - tilt.pivot[0]);
      state_.omega = omega;
    }
  }
  origin_ = {state_.x, centre.y - geometry_.rest_height()};
}

SeatSimulation::EventReport SeatSimulation::advance(MotionPiece& piece, double t_stop) {
  if (mode_.rest) return advance_rest(t_stop);
  from_piece_end_ = system_ready_ && piece_end_ready_;
  piece_end_ready_ = false;
  // A level flight needs no system: it watches no guard.
  const bool closed_form_flight =
      mode_.active.empty() && external_ == nullptr && vertical_.piece_at(t_).is_zero();
  if (closed_form_flight) {
    if (auto landed = fly_over_level_seat(std::get<FlightChart>(chart_of(mode_)), piece, t_stop)) {
      system_ready_ = false;
      return std::move(*landed);
    }
  }
  SeatSystem& moving = system_ready_ ? *system_ : build_system(piece);
  system_ready_ = false;
  const ModeKind kind = kind_of(mode_);
  EventReport report;
  const auto integrate = [&](const auto& ode) {
    with_scene_stepper<std::decay_t<decltype(ode)>::N>(
        scene_.solver, ode.scale(),
        [&](auto& stepper) { report = integrate_with(ode, stepper, piece, t_stop, kind); });
  };
  std::visit(
      [&](const auto& chart) {
        using Chart = std::decay_t<decltype(chart)>;
        if constexpr (std::is_same_v<Chart, PivotChart>) {
          moving.set_clear_of_ends(contacts_.within_ends_turning_about(chart.point));
          integrate(SeatOde<PivotChart>(moving, chart, sweep_for(moving, chart)));
        } else {
          moving.set_clear_of_ends(false);
          const SeatOde ode(moving, chart);
          if constexpr (std::is_same_v<Chart, FlightChart>) {
            if (closed_form_flight) {
              ClosedFormFlight flight(ode.coordinates(state_), state_, piece, t_, scene_.g);
              report = integrate_with(ode, flight, piece, t_stop, kind);
              return;
            }
          }
          integrate(ode);
        }
      },
      chart_of(mode_));
  return report;
}

PivotSweep& SeatSimulation::sweep_for(const SeatSystem& system, const PivotChart& chart) {
  if (!sweep_) {
    sweep_.emplace(system, chart);
  } else if (sweep_->serves(system, chart)) {
    sweep_->rebind(system);
  } else {
    sweep_->reset(system, chart);
  }
  return *sweep_;
}

ContactForces SeatSimulation::forces_now() {
  if (!stopped_ && mode_.rest) {
    const Vec2 f = load_at(t_, state_).force;
    return {-f.x, -f.y};
  }
  if (!stopped_ && !mode_.active.empty()) {
    SeatSystem now = forces_system(motion_.piece_at(t_));
    return now.forces(t_, state_);
  }
  return {0.0, 0.0};
}

SimulationWithHistory simulate_on_seat(const Scene& scene, double output_interval,
                                       const ExternalLoad* external) {
  SeatSimulation simulation(scene, output_interval, external);
  return run_to_end(simulation);
}

}  // namespace blockfrag
