// A block moving on its seat with a fixed set of active contacts, each sticking or slipping one
// way (or none: flight): its contact forces and accelerations, the guards whose zero ends the set
// (docs/physics.md, "Contact on a seat"), and its ODE in the coordinates of a chart.
#pragma once

#include <array>
#include <cstddef>
#include <span>
#include <vector>

#include "engine/contact/planar_contact.hpp"
#include "engine/integrate/ode_state.hpp"
#include "engine/modes/modes.hpp"
#include "engine/motion/ground_motion.hpp"
#include "engine/seat/seat_contacts.hpp"
#include "engine/tolerances.hpp"

namespace blockfrag {

// At most this many contacts at once (engine/contact/contact_lcp.hpp's limit).
inline constexpr int kMaxSeatContacts = 6;
// Guards: overturning, falling, four per active contact, and one per watched vertex or point.
inline constexpr int kSeatGuards = 64;
inline constexpr int kSeatContactGuards = 4;
inline constexpr int kFirstClearanceGuard = 2 + kSeatContactGuards * kMaxSeatContacts;
static_assert(kMaxSeatClearances == kSeatGuards - kFirstClearanceGuard);

struct ActiveContact {
  SeatPair pair;
  ContactState state;  // stick, slip_positive or slip_negative
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

// Contact forces for fixed states (per unit mass): each active contact's normal acceleration is
// zero, a sticking one's tangential too, a slipping one's friction is -s mu times its normal force.
struct FixedStateForces {
  BodyAcceleration acceleration{0.0, 0.0, 0.0};
  std::array<double, kMaxSeatContacts> normal{}, tangent{};
  Vec2 total{0.0, 0.0};  // the sum of the contact forces, world frame
};

struct SeatSystemContext {
  const SeatContacts* contacts;
  const BlockGeometry* geometry;
  const MotionPiece* piece;     // lambda
  const MotionPiece* vertical;  // lambda_v
  double g, mu, fall_depth;     // fall_depth in m
};

class SeatSystem {
 public:
  static constexpr int kGuards = kSeatGuards;

  // `watched_vertices` and `watched_points`: the vertices and points not in an active contact,
  // whose clearance is watched (at most kMaxSeatClearances together).
  SeatSystem(const SeatSystemContext& c, const std::vector<ActiveContact>& active,
             const std::vector<int>& watched_vertices, const std::vector<int>& watched_points);

  std::array<double, kGuards> guards(double t, const BlockState& s) const;
  SeatEvent event(int guard) const { return events_[static_cast<std::size_t>(guard)]; }
  ContactForces forces(double t, const BlockState& s) const;
  FixedStateForces solve(double t, const BlockState& s) const;
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
  const std::vector<int>& watched_vertices() const { return watched_vertices_; }
  double length_scale() const { return c_.geometry->size(); }
  double g() const { return c_.g; }

 private:
  SeatSystemContext c_;
  std::array<ActiveContact, kMaxSeatContacts> active_{};
  int count_ = 0;
  std::vector<int> watched_vertices_, watched_points_;
  std::array<SeatEvent, kGuards> events_{};
};

// The ODE of a block on its seat in a chart's coordinates (engine/seat/seat_chart.hpp).
template <class Chart>
class SeatOde {
 public:
  static constexpr int N = Chart::N;
  static constexpr int kGuards = kSeatGuards;

  SeatOde(const SeatSystem& system, const Chart& chart) : system_(&system), chart_(chart) {}

  const SeatSystem& system() const { return *system_; }
  OdeState<N> scale() const { return chart_.scale(system_->length_scale(), system_->g()); }
  void operator()(double t, const OdeState<N>& q, OdeState<N>& dq) const {
    const BlockState s = chart_.full(t, q);
    dq = chart_.rates(q, s, system_->solve(t, s).acceleration);
  }
  std::array<double, kGuards> guards(double t, const OdeState<N>& q) const {
    return system_->guards(t, chart_.full(t, q));
  }
  SeatEvent event(int guard) const { return system_->event(guard); }
  BlockState full(double t, const OdeState<N>& q) const { return chart_.full(t, q); }
  ContactForces forces(double t, const OdeState<N>& q) const {
    return system_->forces(t, chart_.full(t, q));
  }
  OdeState<N> coordinates(const BlockState& b) const { return chart_.coordinates(b); }
  // No guard's least value over a step is known to be at an end: near zero, each is sampled.
  template <class OneWay>
  std::array<bool, kGuards> least_at_ends(const OdeState<N>&, const OdeState<N>&,
                                          const OneWay&) const {
    return {};
  }

 private:
  const SeatSystem* system_;
  Chart chart_;
};

// The forces of the fixed states at the state s under the applied force per unit mass.
FixedStateForces fixed_state_forces(std::span<const PlanarContact> contacts,
                                    std::span<const ContactState> states, const BlockState& s,
                                    Vec2 applied, double inertia_per_mass, double mu);

}  // namespace blockfrag
