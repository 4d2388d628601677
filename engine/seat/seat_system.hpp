// A block moving on its seat with a fixed set of active contacts, each sticking or slipping one
// way (or none: flight): its contact forces and accelerations, the guards whose zero ends the set
// (docs/physics.md, "Contact on a seat"). Its ODE in a chart's coordinates: seat_ode.hpp.
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <span>
#include <vector>

#include "engine/contact/planar_contact.hpp"
#include "engine/integrate/ode_state.hpp"
#include "engine/modes/modes.hpp"
#include "engine/motion/ground_motion.hpp"
#include "engine/seat/fixed_state_forces.hpp"
#include "engine/seat/pivot_turning.hpp"
#include "engine/seat/seat_chart.hpp"
#include "engine/seat/seat_contacts.hpp"
#include "engine/seat/sinusoid.hpp"
#include "engine/seat/watched_list.hpp"
#include "engine/sine_cosine.hpp"
#include "engine/tolerances.hpp"

namespace blockfrag {

// Guards: overturning, falling, four per active contact, and one per watched vertex or point.
inline constexpr int kSeatGuards = 64;
inline constexpr int kSeatContactGuards = 4;
inline constexpr int kFirstClearanceGuard = 2 + kSeatContactGuards * kMaxSeatContacts;
static_assert(kMaxSeatClearances == kSeatGuards - kFirstClearanceGuard);

struct ActiveContact {
  SeatPair pair;
  ContactState state;  // stick, slip_positive or slip_negative
};

// Per guard: whether it is known not to reach zero inside a step where it is positive at both
// ends (a claim: its least value over the step is at an end, or it stays positive throughout); or,
// as a question, which guards are asked about.
using GuardClaims = std::array<bool, kSeatGuards>;

// Where a step can take the block, as the step's dense output (which the guards are sampled on)
// takes it: its centre within [x_lo, x_hi] x [y_lo, y_hi], its tilt within [theta_lo, theta_hi];
// `start` is its state at the step's start.
struct SweptMotion {
  BlockState start;
  double x_lo, x_hi, y_lo, y_hi, theta_lo, theta_hi;
};

// What a guard reaching zero means on a seat.
enum class SeatEvent {
  none,            // an unused guard slot
  overturns,       // the block lies on another face
  falls,           // past a seat's end, the block has dropped below it
  lift_off,        // an active contact's normal force reaches zero
  friction_limit,  // a sticking contact's friction reaches mu times its normal force
  slip_stops,      // a slipping contact's tangential velocity reaches zero
  leaves_end,      // an active contact's point reaches its segment's or edge's end
  touches,         // a block vertex reaches the seat or a seat point reaches the block
};

// The pieces remember their last lambda, so a system (const while it integrates) reaches them
// through non-const pointers; the simulation owns them.
struct SeatSystemContext {
  const SeatContacts* contacts;
  const BlockGeometry* geometry;
  MotionPiece* piece;                      // lambda
  MotionPiece* vertical;                   // lambda_v
  double g, mu, fall_depth;                // fall_depth in m
  const ExternalLoad* external = nullptr;  // none: the dry block
};

class SeatSystem {
 public:
  static constexpr int kGuards = kSeatGuards;

  // `watched_vertices` and `watched_points`: the vertices and points not in an active contact,
  // whose clearance is watched (at most kMaxSeatClearances together).
  SeatSystem(const SeatSystemContext& c, const std::vector<ActiveContact>& active,
             const WatchedList& watched_vertices, const WatchedList& watched_points);

  // Whether a system built from these would lay its guards out as this one does: the same seat,
  // active contacts (in order, in the same states) and watched vertices and points.
  bool lays_out(const SeatSystemContext& c, const std::vector<ActiveContact>& active,
                const WatchedList& watched_vertices, const WatchedList& watched_points) const;
  // This system under the context c (another motion piece), as a system built anew there: whatever
  // it remembered of the last forces solved or loads found is forgotten. Where lays_out(c, ...)
  // holds, it is then SeatSystem(c, ...): a record builds a system at each of its samples, most
  // of them laid out as the last.
  void start_piece(const SeatSystemContext& c);

  // Not const: each remembers the last forces solved (a step's end is asked for by its guards, by
  // the next step's first stage and by the checks of its forces).
  std::array<double, kGuards> guards(double t, const BlockState& s);
  // guards(t, s)[i], a watched vertex's or point's clearance without the others.
  double guard(int i, double t, const BlockState& s);
  // The guards `wanted` names as guards(t, s) finds them; the others' values are not to be read
  // (the samples inside a step read only the guards they follow).
  std::array<double, kGuards> guards(double t, const BlockState& s, const GuardClaims& wanted);
  // guards(t, s) turning on a PivotChart whose turn at s is `turn` and arm r: a lean pivot's guards
  // take them, not turning the block again (a step's end).
  std::array<double, kGuards> pivot_guards(double t, const BlockState& s, SineCosine turn, Vec2 r);
  ContactForces forces(double t, const BlockState& s);
  // Whether every active contact's lift-off and friction guards are positive at (t, s), as
  // guards() finds them, without the clearances: what a piece boundary asks of the mode.
  bool contacts_hold(double t, const BlockState& s);
  // How deep the block is in the seat at s (SeatContacts::penetration), from the vertices guards()
  // turned where it last turned them at s: a step's end, whose penetration follows its guards
  // (inline where a lean pivot's did: the call was most of it).
  double penetration(const BlockState& s) const {
    if (lean_pivot_ && lean_.deepest_set && has_pose_bits(s, lean_.pose)) return lean_.deepest;
    return penetration_anew(s);
  }
  const FixedStateForces& solve(double t, const BlockState& s);
  // solve(t, s) on a SlipChart, r the slipping vertex's arm at s as the chart turns it (as
  // SeatContacts::vertex_at turns it): its contact is posed from r, not turned again (every
  // right-hand side of a slipping block).
  const FixedStateForces& solve_slipping(double t, const BlockState& s, Vec2 r);
  // theta'' of the block turning about the fixed point at r from its centre of mass, where one
  // sticking contact holds it there (a PivotChart's); none with two contacts or more. The contact
  // force does no work on the turning: with J = d(x, y, theta)/d theta = (r_y, -r_x, 1) and the
  // constraint's acceleration c = (r_x, r_y, 0) omega^2, Lagrange's equation
  // J^T (M (J theta'' + c) - Q) = 0 gives theta'' without solving for the force, which only the
  // guards ask for, at a step's ends.
  // Not const: the load it finds is the one the guards' solve at a step's end needs next (a step
  // ends by this, at its end).
  std::optional<double> pivot_turning(double t, const BlockState& s, Vec2 r) {
    return pivot_turning(t, r, s.omega, [&]() -> const BlockState& { return s; });
  }
  // The same at the state state_at() builds, its omega given: built only under a load that reads
  // it (the reservoir's). The dry block's turning reads omega alone, so that a dry pivot's
  // right-hand sides build no state.
  template <class StateAt>
  std::optional<double> pivot_turning(double t, Vec2 r, double omega, const StateAt& state_at) {
    if (count_ != 1) return std::nullopt;
    if (c_.external == nullptr) return dry_turning_about_pivot(dry_lifted_load(t), omega, r);
    return turning_about_pivot(wet_lifted_load(t, state_at()), omega, r);
  }
  // Whether the block turns about its pivot clear of the seat's ends (SeatContacts::
  // within_ends_turning_about, asked once per pivot). On a one-segment seat a block vertex sticking
  // there is then the flat ground's rocking block, and its guards are found as the flat ground
  // finds them: its contact force in closed form from pivot_turning, the watched vertices' heights
  // alone, the seat's ends and the fall out of reach (their guards 1).
  void set_clear_of_ends(bool clear);
  bool lean_pivot() const { return lean_pivot_; }
  // The pivot's normal and tangential force (per unit mass, along its segment's normal and
  // contact_tangent) at (t, s) on a lean pivot: M a of the centre of mass turning about the fixed
  // pivot, less the load. It is the fixed-state solve's, to its rounding.
  struct PivotForce {
    double normal, tangent;
  };
  // Inline where the guards found it (a step's end, checked again): the call was most of it.
  PivotForce pivot_force(double t, const BlockState& s) {
    if (t == lean_.t && std::memcmp(&s, &lean_.s, sizeof s) == 0) return lean_.force;
    return pivot_force_at(t, s, lean_arm(active_[0].pair.block, cached_turn(s.theta)));
  }
  SeatEvent event(int guard) const { return events_[static_cast<std::size_t>(guard)]; }
  // The guards whose slot is used (the others are 1 throughout).
  GuardClaims live_guards() const { return live_; }
  // The same as their slots, in order: a guard watch takes them at each motion piece. On a lean
  // pivot, without the fall's and the seat points', which stay 1.
  std::span<const int> live_slots() const {
    return lean_pivot_
               ? std::span(lean_live_slots_).first(static_cast<std::size_t>(lean_live_count_))
               : std::span(live_slots_).first(static_cast<std::size_t>(live_count_));
  }
  // The seat point a touching guard watches, or -1 (a block vertex's guard, or another guard).
  int watched_point(int guard) const {
    const int k = guard - kFirstClearanceGuard - static_cast<int>(watched_vertices_.size());
    return k >= 0 && k < static_cast<int>(watched_points_.size())
               ? watched_points_[static_cast<std::size_t>(k)]
               : -1;
  }
  int active_count() const { return count_; }
  // The block vertices whose clearance is watched; vertex k of them has guard
  // kFirstClearanceGuard + k.
  const WatchedList& watched_vertices() const { return watched_vertices_; }
  // The seat points whose clearance is watched, after the vertices.
  const WatchedList& watched_points() const { return watched_points_; }
  double length_scale() const { return c_.geometry->size(); }
  double g() const { return c_.g; }

  // The claims (GuardClaims) of the guards `asked` names over a step (engine/seat/seat_ends.cpp),
  // made only where they are exactly true of guards() (docs/physics.md, "Contact on a seat"); a
  // guard not asked is not looked at. Turning about a fixed point: PivotSweep.
  // A vertex slipping along a seat segment's line on `chart` from q0 to q1, its tilt, place and
  // rate along the line moving one way or not (`moves`):
  struct SlipMoves {
    bool theta, place, rate;
  };
  GuardClaims slip_claims(const SlipChart& chart, const OdeState<SlipChart::N>& q0,
                          const OdeState<SlipChart::N>& q1, SlipMoves moves,
                          const GuardClaims& asked) const;
  // Sliding without turning between the states s0 and s1, its place and rate likewise, and its
  // contacts' normal forces moving one way or not (slide_forces_one_way):
  GuardClaims slide_claims(const BlockState& s0, const BlockState& s1, bool place_one_way,
                           bool rate_one_way, bool forces_one_way, const GuardClaims& asked) const;
  // Whether, sliding from t0 to t1 along a line whose direction's y is `rise`, each contact's
  // normal force moves one way. The contact problem's matrix is the slide's, unchanged, and its
  // right-hand side is affine in lambda where the loads do not depend on the place: without water
  // (gravity and the ground's inertia act at the centre of mass at any pose), and with water on a
  // level slide (rise 0: the block keeps its height and tilt, and the water's loads move with it)
  // whose crack the contact forces do not open (SeatedCrack::unaffected). There, while lambda
  // moves one way and lambda_v is zero, so does each normal force.
  bool slide_forces_one_way(double t0, double t1, double rise) const;
  // Any other motion, the centre of mass's x from x0 to x1 (in flight theta is linear in time: it
  // moves one way):
  GuardClaims free_claims(double x0, double x1, bool x_one_way, bool theta_one_way) const;
  // The guards whose slot is unused: their value is 1 throughout.
  GuardClaims unused_guards() const { return unused_; }
  // Adds to `claims` the watched clearances among `asked` that stay positive over a step moving
  // the block by at most `swept`, the guards at the step's start `at_start`
  // (engine/seat/seat_swept_claims.cpp).
  void claim_swept_clear(const SweptMotion& swept, const std::array<double, kGuards>& at_start,
                         const GuardClaims& asked, GuardClaims& claims) const;

 private:
  friend class PivotSweep;

  // Guards 0 and 1 (overturning, falling) while the centre of mass's x stays within [x_lo, x_hi]
  // and theta within [theta_lo, theta_hi] (moving one way when theta_one_way), the lowest vertex
  // linear in a parameter moving one way when vertices_linear.
  void claim_overturn_and_fall(double x_lo, double x_hi, bool theta_one_way, bool vertices_linear,
                               GuardClaims& claims) const;
  // A slipping contact's guards, where its tangential velocity is a positive multiple of the
  // chart's rate and its place along its run is linear in the chart's place.
  void claim_contact_guards(bool place_one_way, bool rate_one_way, GuardClaims& claims) const;
  // The lift-off guards of the slipping contacts (their normal forces moving one way).
  void claim_lift_offs(GuardClaims& claims) const;
  // A watched vertex whose x stays in [x_lo, x_hi]: where the segments there make a valley, its
  // clearance is the least of its heights over their lines, and is least at an end when each of
  // those is (height_least_at_ends(k) for the line of segment k, whose slope is finite).
  // Whether the clearance of a vertex staying within [x_lo, x_hi] x [y_lo, y_hi] stays positive.
  bool stays_clear_of_seat(double x_lo, double x_hi, double y_lo, double y_hi) const;
  template <class HeightLeastAtEnds>
  bool clearance_least_at_ends(double x_lo, double x_hi,
                               const HeightLeastAtEnds& height_least_at_ends) const;

  // Active contact `at`'s lift-off guard (its normal force) and a sticking one's friction guard
  // (how far its friction is inside the cone), in g.
  double lift_off_guard(const FixedStateForces& f, std::size_t at) const {
    return f.normal[at] / c_.g;
  }
  double friction_guard(const FixedStateForces& f, std::size_t at) const {
    return (c_.mu * f.normal[at] - std::abs(f.tangent[at])) / c_.g;
  }
  // The active contacts' guards (four each from slot 2) among those `wanted` names into `out` (the
  // others may be left unset); `world`: the block's vertices at s (SeatContacts::world_vertices).
  void set_contact_guards(double t, const BlockState& s, std::span<const Vec2> world,
                          const GuardClaims& wanted, std::array<double, kGuards>& out);
  // set_contact_guards where the one active contact sticks (a block turning on its pivot, at every
  // step's end): its contact alone posed and solved, without the passes over the contacts.
  void set_sticking_guards(double t, const BlockState& s, std::span<const Vec2> world,
                           std::array<double, kGuards>& out);
  // Whether s's place and tilt are `b`, word by word: array's != calls memcmp, whose cost for 24
  // bytes depends on where they lie (a step's end, at every step).
  static bool has_pose_bits(const BlockState& s, const std::array<std::uint64_t, 3>& b) {
    using std::bit_cast;
    return bit_cast<std::uint64_t>(s.x) == b[0] && bit_cast<std::uint64_t>(s.y) == b[1] &&
           bit_cast<std::uint64_t>(s.theta) == b[2];
  }
  // penetration(s) where the guards did not find it.
  double penetration_anew(const BlockState& s) const;
  // pivot_force with the pivot's arm at s given (lean_arm).
  PivotForce pivot_force_at(double t, const BlockState& s, Vec2 r);
  // Block vertex i less the centre of mass, the block turned by `turn`: for the pivot, its arm as
  // its chart turns it (PivotChart::arm).
  Vec2 lean_arm(int i, SineCosine turn) const;
  // The clearance at s of the block vertex whose lean_arm is r.
  double lean_clearance(const BlockState& s, Vec2 r) const;
  // guards(t, s, wanted) elsewhere.
  std::array<double, kGuards> general_guards(double t, const BlockState& s,
                                             const GuardClaims& wanted);
  // guards(t, s, wanted) on a lean pivot (set_clear_of_ends), the block turned by `turn` and the
  // pivot's arm r (lean_arm).
  std::array<double, kGuards> lean_pivot_guards(double t, const BlockState& s,
                                                const GuardClaims& wanted, SineCosine turn, Vec2 r);
  // The active contacts at s (the first count_ set), as SeatContacts::pose gives them: a block
  // vertex's is its world vertex less the centre of mass on its segment's fixed normal, found
  // without pose()'s gap and place (every right-hand side of a slipping or sliding block).
  using Contacts = std::array<PlanarContact, kMaxSeatContacts>;
  Contacts active_contacts(const BlockState& s) const;
  // Active contact `at`, a block vertex's, with that vertex at p in the world frame.
  PlanarContact vertex_contact(std::size_t at, Vec2 p, const BlockState& s) const {
    return {{p.x - s.x, p.y - s.y}, normals_[at], ContactKind::block_vertex};
  }
  // Whether the last forces solved are at this time and state.
  bool solved_at(double t, const BlockState& s) const;
  // The forces with the active contacts at s given; solve_anew does not look at the last.
  const FixedStateForces& solve(double t, const BlockState& s, const Contacts& contacts);
  const FixedStateForces& solve_anew(double t, const BlockState& s, const Contacts& contacts);
  // solve_anew with one active contact, `contact`.
  const FixedStateForces& solve_one_anew(double t, const BlockState& s,
                                         const PlanarContact& contact);
  // The load on the block lifted from its seat (one contact or none) under the external load at
  // time t in the state s, kept for the next call at the same time and state.
  const BodyLoad& wet_lifted_load(double t, const BlockState& s);
  // The same for the dry block, at any state: cheaper to find again than to look up.
  BodyLoad dry_lifted_load(double t) const {
    return dry_body_load(c_.geometry->inertia_per_mass(), c_.piece->lambda(t), lambda_v(t), c_.g);
  }
  // lambda_v at t. The loads take it only as 1 + lambda_v, which a zero of either sign leaves 1:
  // without vertical motion (most scenes) the piece's formula is not asked at each new time (a
  // rocking block's right-hand sides, at two new times a step).
  double lambda_v(double t) const { return vertical_still_ ? 0.0 : c_.vertical->lambda(t); }

  SeatSystemContext c_;
  bool vertical_still_;  // c_.vertical is zero throughout
  std::array<ActiveContact, kMaxSeatContacts> active_{};
  std::array<ContactState, kMaxSeatContacts>
      states_{};                                  // active_'s states, as the solves take them
  std::array<Vec2, kMaxSeatContacts> normals_{};  // a block vertex's contact normal: its segment's
  int count_ = 0;
  bool one_sticking_ = false;  // one active contact, sticking
  bool vertex_pivot_ = false;  // that contact a block vertex's on a one-segment seat
  bool lean_pivot_ = false;    // and turning clear of the seat's ends (set_clear_of_ends)
  // What lean_pivot_guards last found of the pivot's force, at what time and state (a step's end,
  // whose contact check asks again), and of the deepest of the pivot and the watched vertices, at
  // what pose (the step's penetration).
  struct LeanPivot {
    double t = std::numeric_limits<double>::quiet_NaN();
    BlockState s;
    PivotForce force{0.0, 0.0};
    std::array<std::uint64_t, 3> pose{};
    bool deepest_set = false;
    double deepest = 0.0;
  };
  LeanPivot lean_;
  std::array<int, kGuards> lean_live_slots_;  // live_slots() on a lean pivot, the first
  int lean_live_count_ = 0;                   // lean_live_count_
  WatchedList watched_vertices_, watched_points_;
  std::array<SeatEvent, kGuards> events_{};
  GuardClaims unused_, live_;            // live_: the used slots, each unused_'s negation
  std::array<int, kGuards> live_slots_;  // the used slots in order, the first live_count_
  int live_count_ = 0;
  // The slots of the guards made of the contact forces (each active contact's lift-off guard, and a
  // sticking one's friction guard), the first force_slot_count_.
  std::array<int, 2 * kMaxSeatContacts> force_slots_;
  int force_slot_count_ = 0;
  // The last forces solved, and the time and state they were solved at.
  struct Solved {
    double t = std::numeric_limits<double>::quiet_NaN();
    BlockState s;
    FixedStateForces forces;
  };
  Solved last_solve_;
  // The block's vertices where guards() last turned it (the first vertex_count()), that pose's
  // x, y and theta, bit for bit, and the watched points' clearances found there (in m, as
  // point_clearance_within finds them, in the watched points' order; NaN where not asked for).
  struct TurnedBlock {
    std::array<std::uint64_t, 3> pose{};
    bool set = false;
    std::array<Vec2, kMaxSeatClearances> world;
    std::array<double, kMaxSeatClearances> points;
  };
  TurnedBlock turned_;
  // The last wet lifted load found, and the time and state it was found at.
  struct Loaded {
    double t = std::numeric_limits<double>::quiet_NaN();
    BlockState s;
    BodyLoad load{{0.0, 0.0}, 0.0, 1.0};
  };
  Loaded last_lifted_;
};

// Which guards are least at an end of a step while the block turns about a fixed point (a
// PivotChart), theta moving one way (engine/seat/seat_ends.cpp). Each guard it claims is made of
// sinusoids of theta (a vertex's x and its heights over the seat's lines or its distance from an
// end, a seat point's squared distances from the block's vertices and its distances from their
// edges' lines), set up once per chart; a step evaluates them and their slopes at its ends.
class PivotSweep {
 public:
  PivotSweep(const SeatSystem& system, const PivotChart& chart);
  // Not const: the turn at a step's end is kept for the next step's start.
  GuardClaims claims(double theta0, double theta1, const GuardClaims& asked);
  // The same, the guards at theta0 and theta1 given (at0, at1) as SeatSystem::guards finds them on
  // the chart: a watched point's sign there, not a pass over the block's edges, says whether it is
  // inside the block at the step's lower end (every step of a rocking block).
  GuardClaims claims(double theta0, double theta1, const GuardClaims& asked,
                     const std::array<double, kSeatGuards>& at0,
                     const std::array<double, kSeatGuards>& at1);
  // Whether the sweep serves `system` turning on `chart`: the same pivot, the same watched
  // vertices and points. A record starts a motion piece at each of its samples, and each piece a
  // system; building its sweep anew was 6 % of the type B block's run under a record.
  bool serves(const SeatSystem& system, const PivotChart& chart) const;
  // The claims then read `system` (its active contacts, the guards it uses).
  void rebind(const SeatSystem& system) { system_ = &system; }
  // The sweep of `system` turning on `chart`, as PivotSweep(system, chart) sets it up.
  void reset(const SeatSystem& system, const PivotChart& chart);

 private:
  // The sinusoids of a vertex or point lie in sinusoids_ from `first` on: one block for all, built
  // at every pivot a record's piece turns on.
  struct Vertex {
    Sinusoid x;
    std::size_t first;             // its height over each seat segment's line
    std::array<Sinusoid, 2> ends;  // squared distance from the seat's first and last points
  };
  // On a seat of one segment, a watched vertex's: whether it stays over the segment, by far more
  // than the end margin and the rounding of its extent, at every tilt (its claim is then its
  // height's alone), and the tilts within which every step's vertex_claim holds, as
  // set_claimed_range found them at the last step whose claim was worked out (none at first).
  struct VertexRange {
    bool over_one_segment = false;
    double claimed_lo = std::numeric_limits<double>::infinity();
    double claimed_hi = -std::numeric_limits<double>::infinity();
  };
  struct Point {
    int k;              // the seat point
    std::size_t first;  // its squared distance from each block vertex, then its signed distance
                        // from each block edge's line
    // The tilts within which every step's point_claim holds, as set_claimed_range found them at
    // the last step whose claim was worked out (none at first).
    double claimed_lo = std::numeric_limits<double>::infinity();
    double claimed_hi = -std::numeric_limits<double>::infinity();
  };
  std::span<const Sinusoid> heights(const Vertex& v) const {
    return {sinusoids_.data() + v.first, segment_count_};
  }
  std::span<const Sinusoid> corners(const Point& p) const {
    return {sinusoids_.data() + p.first, block_vertex_count_};
  }
  std::span<const Sinusoid> lines(const Point& p) const {
    return {sinusoids_.data() + p.first + block_vertex_count_, block_vertex_count_};
  }
  void set_edge_normals();
  void add_point(int k);
  bool vertex_claim(const ThetaStep& step, const Vertex& vertex) const;
  bool point_claim(const ThetaStep& step, const Point& point) const;
  // point_claim over the step [lo, hi], from the point's claimed range where the step lies in it;
  // else worked out, and where it holds, the range set anew about the step's end theta_end.
  bool claims_point(const ThetaStep& step, double lo, double hi, Point& point, double theta_end,
                    SineCosine end_turn) const;
  void set_claimed_range(Point& point, double theta, SineCosine turn) const;
  // vertex_claim of a vertex over one segment, for a step outside its claimed range; where it
  // holds, the range set anew about the step's end theta_end.
  bool claims_vertex(const ThetaStep& step, const Vertex& vertex, VertexRange& range,
                     double theta_end, SineCosine end_turn) const;
  void set_claimed_range(const Vertex& vertex, VertexRange& range, double theta,
                         SineCosine turn) const;
  // claims(), inside_at_lo(lo, point, g) saying whether a point whose clearance is otherwise
  // claimed (guard g) is inside the block at the step's lower tilt lo.
  template <class InsideAtLo>
  GuardClaims claims_with(double theta0, double theta1, const GuardClaims& asked,
                          const InsideAtLo& inside_at_lo);
  // sine_cosine(theta): the last step's end is the next one's start.
  SineCosine turn_at(double theta) const;

  const SeatSystem* system_ = nullptr;  // rebound to each piece's system; the rest serves them all
  const SeatContacts* contacts_ = nullptr;
  PivotChart chart_;
  WatchedList watched_vertices_, watched_points_;
  Sinusoid centre_x_;
  std::vector<Vertex> vertices_;
  std::vector<Point> points_;
  std::vector<VertexRange> vertex_ranges_;  // vertices_'s, on a seat of one segment only
  std::size_t segment_count_ = 0, block_vertex_count_ = 0;
  std::vector<Sinusoid> sinusoids_;
  // The block's edges' unit inward normals (edge j from vertex j to the next), found for the seat
  // contacts edge_normals_of_.
  std::vector<Vec2> edge_normals_;
  const SeatContacts* edge_normals_of_ = nullptr;
  // The tilt (its bits) at the end of the last step claims() was asked about, and its turn.
  std::uint64_t last_end_ = 0;
  SineCosine last_end_turn_{0.0, 1.0};
};

}  // namespace blockfrag
