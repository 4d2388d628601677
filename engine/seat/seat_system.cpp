#include "engine/seat/seat_system.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <span>

#include "engine/seat/seated_load.hpp"

namespace blockfrag {

namespace {

// A pose's place and tilt, bit for bit.
std::array<std::uint64_t, 3> pose_bits(const BlockState& s) {
  return {std::bit_cast<std::uint64_t>(s.x), std::bit_cast<std::uint64_t>(s.y),
          std::bit_cast<std::uint64_t>(s.theta)};
}

// Every guard at 1, an unused slot's value. Unrolled, the fill is one store per two slots: a
// loop's, or a copy of a constant array (a string copy, one instruction per slot), cost twice
// that or more (a rocking block's guards, at every step).
std::array<double, SeatSystem::kGuards> unused_guard_values() {
  std::array<double, SeatSystem::kGuards> ones;
#pragma GCC unroll 64
  for (double& one : ones) one = 1.0;
  return ones;
}

// Every guard wanted (a step's end).
const GuardClaims& every_guard() {
  static const GuardClaims every = [] {
    GuardClaims all;
    all.fill(true);
    return all;
  }();
  return every;
}

}  // namespace

SeatSystem::SeatSystem(const SeatSystemContext& c, const std::vector<ActiveContact>& active,
                       const WatchedList& watched_vertices, const WatchedList& watched_points)
    : c_(c),
      vertical_still_(c.vertical->is_zero()),
      watched_vertices_(watched_vertices),
      watched_points_(watched_points) {
  count_ = static_cast<int>(active.size());
  std::copy(active.begin(), active.end(), active_.begin());
  one_sticking_ = count_ == 1 && active_[0].state == ContactState::stick;
  vertex_pivot_ = one_sticking_ && active_[0].pair.kind == ContactKind::block_vertex &&
                  c_.contacts->point_count() == 2;
  // Only the used slots are set (events_ starts at none): a record builds a system at each of its
  // samples, and passes over all 64 slots were a third of a construction.
  unused_.fill(true);
  live_.fill(false);
  // The slots are used in increasing order.
  const auto use = [&](std::size_t slot, SeatEvent event) {
    events_[slot] = event;
    unused_[slot] = false;
    live_[slot] = true;
    live_slots_[static_cast<std::size_t>(live_count_++)] = static_cast<int>(slot);
  };
  use(0, SeatEvent::overturns);
  use(1, SeatEvent::falls);
  for (int i = 0; i < count_; ++i) {
    const ActiveContact& a = active_[static_cast<std::size_t>(i)];
    states_[static_cast<std::size_t>(i)] = a.state;
    // A block vertex's contact normal is its segment's at any pose: a record builds a system at
    // each of its samples, and posing the vertex for it was a fifth of a construction.
    if (a.pair.kind == ContactKind::block_vertex) {
      normals_[static_cast<std::size_t>(i)] = c_.contacts->segment_normal(a.pair.seat);
    }
    const auto base = static_cast<std::size_t>(2 + kSeatContactGuards * i);
    use(base, SeatEvent::lift_off);
    force_slots_[static_cast<std::size_t>(force_slot_count_++)] = static_cast<int>(base);
    if (a.state == ContactState::stick) {
      force_slots_[static_cast<std::size_t>(force_slot_count_++)] = static_cast<int>(base + 1);
    }
    use(base + 1,
        a.state == ContactState::stick ? SeatEvent::friction_limit : SeatEvent::slip_stops);
    // A sticking contact's point does not move along its segment or edge (the type B block
    // rocking on its toe sticks at the seat's end): only slipping ones can leave it.
    if (a.state != ContactState::stick) {
      use(base + 2, SeatEvent::leaves_end);
      use(base + 3, SeatEvent::leaves_end);
    }
  }
  const std::size_t watched = watched_vertices_.size() + watched_points_.size();
  for (std::size_t i = 0; i < watched; ++i) {
    use(static_cast<std::size_t>(kFirstClearanceGuard) + i, SeatEvent::touches);
  }
}

bool SeatSystem::lays_out(const SeatSystemContext& c, const std::vector<ActiveContact>& active,
                          const WatchedList& watched_vertices,
                          const WatchedList& watched_points) const {
  if (c.contacts != c_.contacts || active.size() != static_cast<std::size_t>(count_)) return false;
  for (std::size_t i = 0; i < active.size(); ++i) {
    if (!(active[i].pair == active_[i].pair) || active[i].state != active_[i].state) return false;
  }
  return watched_vertices == watched_vertices_ && watched_points == watched_points_;
}

void SeatSystem::start_piece(const SeatSystemContext& c) {
  c_ = c;
  vertical_still_ = c.vertical->is_zero();
  last_solve_.t = std::numeric_limits<double>::quiet_NaN();
  last_lifted_.t = std::numeric_limits<double>::quiet_NaN();
  lean_.t = std::numeric_limits<double>::quiet_NaN();
  lean_.deepest_set = false;
  turned_.set = false;
}

SeatSystem::Contacts SeatSystem::active_contacts(const BlockState& s) const {
  // Only the active contacts' entries are set and read: zeroing all six was a tenth of a
  // right-hand side's instructions on one contact.
  Contacts contacts;
  for (int i = 0; i < count_; ++i) {
    const auto at = static_cast<std::size_t>(i);
    const SeatPair& pair = active_[at].pair;
    if (pair.kind == ContactKind::block_vertex) {
      contacts[at] = vertex_contact(at, c_.contacts->vertex_at(pair.block, s), s);
    } else {
      contacts[at] = c_.contacts->pose(pair, s).contact;
    }
  }
  return contacts;
}

bool SeatSystem::solved_at(double t, const BlockState& s) const {
  return t == last_solve_.t && std::memcmp(&s, &last_solve_.s, sizeof s) == 0;
}

const FixedStateForces& SeatSystem::solve(double t, const BlockState& s) {
  return solved_at(t, s) ? last_solve_.forces : solve_anew(t, s, active_contacts(s));
}

const FixedStateForces& SeatSystem::solve_slipping(double t, const BlockState& s, Vec2 r) {
  // Two contacts: the vertex on two collinear segments (a flat seat's joint).
  if (count_ != 1) return solve(t, s);
  if (solved_at(t, s)) return last_solve_.forces;
  return solve_one_anew(t, s, vertex_contact(0, {s.x + r.x, s.y + r.y}, s));
}

const FixedStateForces& SeatSystem::solve(double t, const BlockState& s, const Contacts& contacts) {
  return solved_at(t, s) ? last_solve_.forces : solve_anew(t, s, contacts);
}

const FixedStateForces& SeatSystem::solve_anew(double t, const BlockState& s,
                                               const Contacts& contacts) {
  if (count_ == 1) return solve_one_anew(t, s, contacts[0]);
  const auto n = static_cast<std::size_t>(count_);
  const std::span<const PlanarContact> active = std::span(contacts).first(n);
  const std::span<const ContactState> states = std::span(states_).first(n);
  if (count_ >= 2) {
    const SeatedLoadInput in{c_.geometry->inertia_per_mass(),
                             c_.piece->lambda(t),
                             lambda_v(t),
                             c_.g,
                             c_.mu,
                             c_.external};
    last_solve_.forces =
        fixed_state_forces(active, states, s, seated_load(in, s, active, states), c_.mu);
  } else {  // no contact: flight
    const BodyLoad load = c_.external == nullptr ? dry_lifted_load(t) : wet_lifted_load(t, s);
    last_solve_.forces = no_contact_forces(load);
  }
  last_solve_.t = t;
  last_solve_.s = s;
  return last_solve_.forces;
}

const FixedStateForces& SeatSystem::solve_one_anew(double t, const BlockState& s,
                                                   const PlanarContact& contact) {
  const BodyLoad load = c_.external == nullptr ? dry_lifted_load(t) : wet_lifted_load(t, s);
  // The fixed-size solve's forces go straight into the kept ones; where it gives none, the
  // general solve overwrites them whole.
  if (!one_contact_forces(contact, states_[0], s, load, c_.mu, last_solve_.forces)) {
    last_solve_.forces =
        fixed_state_forces(std::span(&contact, 1), std::span(states_).first(1), s, load, c_.mu);
  }
  last_solve_.t = t;
  last_solve_.s = s;
  return last_solve_.forces;
}

const BodyLoad& SeatSystem::wet_lifted_load(double t, const BlockState& s) {
  if (!(t == last_lifted_.t && std::memcmp(&s, &last_lifted_.s, sizeof s) == 0)) {
    last_lifted_.load = body_load(c_.geometry->inertia_per_mass(), c_.piece->lambda(t), lambda_v(t),
                                  c_.g, c_.external, s, Footing::lifted);
    last_lifted_.t = t;
    last_lifted_.s = s;
  }
  return last_lifted_.load;
}

std::array<double, SeatSystem::kGuards> SeatSystem::guards(double t, const BlockState& s) {
  return guards(t, s, every_guard());
}

std::array<double, SeatSystem::kGuards> SeatSystem::guards(double t, const BlockState& s,
                                                           const GuardClaims& wanted) {
  // Calls returned, not a local array: each result is built in the caller's place (an early
  // return of another array than the one built here copied all 64 slots at every call).
  if (!lean_pivot_) return general_guards(t, s, wanted);
  const SineCosine turn = cached_turn(s.theta);
  return lean_pivot_guards(t, s, wanted, turn, lean_arm(active_[0].pair.block, turn));
}

std::array<double, SeatSystem::kGuards> SeatSystem::pivot_guards(double t, const BlockState& s,
                                                                 SineCosine turn, Vec2 r) {
  // A lean pivot is a block vertex's, whose chart turns that vertex (its body) to r as lean_arm
  // does.
  return lean_pivot_ ? lean_pivot_guards(t, s, every_guard(), turn, r) : guards(t, s);
}

std::array<double, SeatSystem::kGuards> SeatSystem::general_guards(double t, const BlockState& s,
                                                                   const GuardClaims& wanted) {
  std::array<double, kGuards> out = unused_guard_values();
  const double R = c_.geometry->size();
  // A sample inside a step mostly follows one clearance (a vertex just over the seat in flight):
  // the overturning margin and the fall's height are found only where followed.
  if (wanted[0]) {
    // Lying on another face is overturning over the seat; past its ends the block falls instead.
    const bool over_seat = s.x >= c_.contacts->seat_point(0).x &&
                           s.x <= c_.contacts->seat_point(c_.contacts->point_count() - 1).x;
    out[0] = over_seat ? c_.contacts->overturn_margin(*c_.geometry, s.theta) : 1.0;
  }
  std::array<Vec2, kMaxSeatClearances>& world = turned_.world;
  c_.contacts->world_vertices(s, world);
  turned_.pose = pose_bits(s);
  turned_.set = true;
  if (wanted[1]) out[1] = c_.contacts->height_over_fall(s, world, c_.fall_depth) / R;
  const auto contact_guards = std::span(wanted).subspan(2, kSeatContactGuards * count_);
  if (one_sticking_) {
    // Its lift-off and friction guards, slots 2 and 3; the contact's other two are unused.
    if (wanted[2] || wanted[3]) set_sticking_guards(t, s, world, out);
  } else if (std::find(contact_guards.begin(), contact_guards.end(), true) !=
             contact_guards.end()) {
    set_contact_guards(
        t, s, std::span(world).first(static_cast<std::size_t>(c_.contacts->vertex_count())), wanted,
        out);
  }
  std::size_t g = static_cast<std::size_t>(kFirstClearanceGuard);
  for (const int i : watched_vertices_) {
    if (wanted[g]) out[g] = c_.contacts->clearance_at(world[static_cast<std::size_t>(i)]) / R;
    ++g;
  }
  for (std::size_t at = 0; at < watched_points_.size(); ++at, ++g) {
    double& clearance = turned_.points[at];
    clearance = std::numeric_limits<double>::quiet_NaN();
    if (!wanted[g]) continue;
    clearance = c_.contacts->point_clearance_within(watched_points_[at], world, R);
    out[g] = clearance / R;
  }
  return out;
}

void SeatSystem::set_contact_guards(double t, const BlockState& s, std::span<const Vec2> world,
                                    const GuardClaims& wanted, std::array<double, kGuards>& out) {
  const double R = c_.geometry->size();
  // The active contacts at s as SeatContacts::pose gives them, from the world vertices: a block
  // vertex's from its vertex alone, a seat point's posed once for its contact and its place along
  // the block's edge (a slipping block's guards, at each sample inside its steps).
  Contacts contacts;
  std::array<SeatContacts::RunPlace, kMaxSeatContacts> on_edge;  // a seat point's place
  for (int i = 0; i < count_; ++i) {
    const auto at = static_cast<std::size_t>(i);
    const SeatPair& pair = active_[at].pair;
    if (pair.kind == ContactKind::block_vertex) {
      contacts[at] = vertex_contact(at, world[static_cast<std::size_t>(pair.block)], s);
    } else {
      const PairPose p = c_.contacts->pose(pair, s, world);
      contacts[at] = p.contact;
      on_edge[at] = {p.along, p.length};
    }
  }
  // Only a lift-off guard and a sticking contact's friction guard read the forces: a sample inside
  // a slipping block's step mostly follows its slip's speed alone (the type B block sliding on its
  // seat's fold under the reservoir, at each of its steps' samples), which the forces, and the
  // water's loads they take, do not change.
  bool forces_read = false;
  for (int k = 0; k < force_slot_count_ && !forces_read; ++k) {
    forces_read = wanted[static_cast<std::size_t>(force_slots_[static_cast<std::size_t>(k)])];
  }
  const FixedStateForces* f = forces_read ? &solve(t, s, contacts) : nullptr;
  const RigidVelocity v{s.vx, s.vy, s.omega};
  const double velocity_scale = std::sqrt(c_.g * R);
  for (int i = 0; i < count_; ++i) {
    const auto at = static_cast<std::size_t>(i);
    const auto base = static_cast<std::size_t>(2 + kSeatContactGuards * i);
    const PlanarContact& c = contacts[at];
    const int slip = slip_sign(active_[at].state);
    if (f != nullptr) {
      out[base] = lift_off_guard(*f, at);
      if (slip == 0) out[base + 1] = friction_guard(*f, at);
    }
    if (slip == 0) continue;
    out[base + 1] = slip * contact_velocity(c, v).tangent / velocity_scale;
    const SeatContacts::RunPlace place =
        active_[at].pair.kind == ContactKind::block_vertex
            ? c_.contacts->place_on_run(active_[at].pair.seat, {s.x + c.r.x, s.y + c.r.y})
            : on_edge[at];
    out[base + 2] = place.along / R;
    out[base + 3] = (place.length - place.along) / R;
  }
}

void SeatSystem::set_sticking_guards(double t, const BlockState& s, std::span<const Vec2> world,
                                     std::array<double, kGuards>& out) {
  const SeatPair& pair = active_[0].pair;
  // A block vertex's contact as active_contacts poses it, a seat point's as pose() does.
  const FixedStateForces& f =
      solved_at(t, s) ? last_solve_.forces
      : pair.kind == ContactKind::block_vertex
          ? solve_one_anew(t, s, vertex_contact(0, world[static_cast<std::size_t>(pair.block)], s))
          : solve_one_anew(t, s, c_.contacts->pose(pair, s, world).contact);
  out[2] = lift_off_guard(f, 0);
  out[3] = friction_guard(f, 0);
}

void SeatSystem::set_clear_of_ends(bool clear) {
  lean_pivot_ = clear && vertex_pivot_;
  if (!lean_pivot_) return;
  const auto points_from = static_cast<int>(kFirstClearanceGuard + watched_vertices_.size());
  lean_live_count_ = 0;
  for (const int slot : std::span(live_slots_).first(static_cast<std::size_t>(live_count_))) {
    if (slot == 1 || slot >= points_from) continue;
    lean_live_slots_[static_cast<std::size_t>(lean_live_count_++)] = slot;
  }
}

SeatSystem::PivotForce SeatSystem::pivot_force_at(double t, const BlockState& s, Vec2 r) {
  const BodyLoad load = c_.external == nullptr ? dry_lifted_load(t) : wet_lifted_load(t, s);
  const double turning = turning_about_pivot(load, s.omega, r);
  // The centre of mass at pivot - r: its acceleration is -(d/dt)^2 r. The force is M a - Q in x
  // and y, the added mass (horizontal) coupling x and theta; dry, M's added parts are zero and add
  // nothing.
  const double w2 = s.omega * s.omega;
  const Vec2 a{turning * r.y + w2 * r.x, -turning * r.x + w2 * r.y};
  const BodyInertia& m = load.inertia;
  const Vec2 force{(1.0 + m.xx) * a.x + m.xtheta * turning - load.force.x, a.y - load.force.y};
  const Vec2 n = normals_[0];
  return {force.x * n.x + force.y * n.y, force.x * n.y - force.y * n.x};
}

std::array<double, SeatSystem::kGuards> SeatSystem::lean_pivot_guards(double t, const BlockState& s,
                                                                      const GuardClaims& wanted,
                                                                      SineCosine turn, Vec2 r) {
  // Not all 64 slots at 1 (a sixth of this, at every step of a rocking block): only the ones a
  // lean pivot keeps at 1 that are read, the fall's and the seat points', which a piece's end keeps
  // for the next piece's watch (SeatSimulation::ended_piece). No one reads the unused slots. A
  // lean pivot's seat is one segment: at most its two points are watched, set one by one (a
  // fill's loop cost more than the stores).
  std::array<double, kGuards> out;
  out[1] = 1.0;
  const std::size_t points = watched_points_.size();
  const std::size_t points_from = kFirstClearanceGuard + watched_vertices_.size();
  if (points > 0) out[points_from] = 1.0;
  if (points > 1) out[points_from + 1] = 1.0;
  if (wanted[0]) out[0] = c_.contacts->overturn_margin(*c_.geometry, s.theta);
  // The pivot's arm serves its force and its own clearance.
  if (wanted[2] || wanted[3]) {
    lean_.force = pivot_force_at(t, s, r);
    lean_.t = t;
    lean_.s = s;
    out[2] = lean_.force.normal / c_.g;
    out[3] = (c_.mu * lean_.force.normal - std::abs(lean_.force.tangent)) / c_.g;
  }
  const double R = c_.geometry->size();
  // The deepest is known where every watched vertex is wanted (a step's end, whose penetration
  // follows).
  bool every = true;
  double deepest = 0.0;
  std::size_t g = static_cast<std::size_t>(kFirstClearanceGuard);
  for (const int i : watched_vertices_) {
    if (wanted[g]) {
      const double c = lean_clearance(s, lean_arm(i, turn));
      out[g] = c / R;
      deepest = std::max(deepest, -c);
    } else {
      every = false;
    }
    ++g;
  }
  lean_.deepest_set = every;
  if (every) {
    lean_.pose = pose_bits(s);
    lean_.deepest = std::max(deepest, -lean_clearance(s, r));
  }
  return out;
}

double SeatSystem::guard(int i, double t, const BlockState& s) {
  const double R = c_.geometry->size();
  const auto vertices = static_cast<int>(watched_vertices_.size());
  const auto points = static_cast<int>(watched_points_.size());
  const int k = i - kFirstClearanceGuard;
  // As guards() computes them: a vertex turned as world_vertices turns it.
  if (k >= 0 && k < vertices) {
    const int vertex = watched_vertices_[static_cast<std::size_t>(k)];
    return c_.contacts->clearance_at(c_.contacts->vertex_at(vertex, s)) / R;
  }
  if (k >= vertices && k < vertices + points) {
    std::array<Vec2, kMaxSeatClearances> world;  // the first vertex_count() set here
    c_.contacts->world_vertices(s, world);
    const int point = watched_points_[static_cast<std::size_t>(k - vertices)];
    return c_.contacts->point_clearance_within(point, world, R) / R;
  }
  return guards(t, s)[static_cast<std::size_t>(i)];
}

Vec2 SeatSystem::lean_arm(int i, SineCosine turn) const {
  return rotate(c_.contacts->body_vertex(i), turn.cos, turn.sin);
}

double SeatSystem::lean_clearance(const BlockState& s, Vec2 r) const {
  return c_.contacts->clearance_at({s.x + r.x, s.y + r.y});
}

double SeatSystem::penetration_anew(const BlockState& s) const {
  // A lean pivot's other vertices lie above the line its watched ones do (HullWatch), and the
  // seat's points are out of the block's reach.
  if (lean_pivot_) {
    const SineCosine turn = cached_turn(s.theta);
    double deepest = std::max(0.0, -lean_clearance(s, lean_arm(active_[0].pair.block, turn)));
    for (const int i : watched_vertices_) {
      deepest = std::max(deepest, -lean_clearance(s, lean_arm(i, turn)));
    }
    return deepest;
  }
  if (!turned_.set || !has_pose_bits(s, turned_.pose)) return c_.contacts->penetration(s);
  const auto n = static_cast<std::size_t>(c_.contacts->vertex_count());
  return c_.contacts->penetration(std::span<const Vec2>(turned_.world).first(n), watched_points_,
                                  turned_.points);
}

bool SeatSystem::contacts_hold(double t, const BlockState& s) {
  if (count_ == 0) return true;
  const FixedStateForces& f = solve(t, s, active_contacts(s));
  for (std::size_t at = 0; at < static_cast<std::size_t>(count_); ++at) {
    if (!(lift_off_guard(f, at) > 0)) return false;
    if (active_[at].state == ContactState::stick && !(friction_guard(f, at) > 0)) return false;
  }
  return true;
}

ContactForces SeatSystem::forces(double t, const BlockState& s) {
  const FixedStateForces f = solve(t, s);
  return {f.total.x, f.total.y};
}

}  // namespace blockfrag
