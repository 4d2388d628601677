// The ODE of a block on its seat in a chart's coordinates, apart from the system (seat_system.hpp
// is at its size limit).
#pragma once

#include <algorithm>
#include <array>
#include <limits>
#include <optional>
#include <span>
#include <type_traits>
#include <variant>

#include "engine/integrate/ode_state.hpp"
#include "engine/scene/block_state.hpp"
#include "engine/seat/seat_chart.hpp"
#include "engine/seat/seat_system.hpp"
#include "engine/seat/turn_cache.hpp"
#include "engine/sine_cosine.hpp"

namespace blockfrag {

// The ODE of a block on its seat in a chart's coordinates (engine/seat/seat_chart.hpp). It holds
// its system, which remembers the last forces solved, as the integration's one working copy, and
// turning about a pivot, the pivot's sweep (which must outlive it).
template <class Chart>
class SeatOde {
 public:
  static constexpr int N = Chart::N;
  static constexpr int kGuards = kSeatGuards;

  SeatOde(SeatSystem& system, const Chart& chart) requires(!std::is_same_v<Chart, PivotChart>)
      : system_(&system), chart_(chart) {}
  SeatOde(SeatSystem& system, const PivotChart& chart,
          PivotSweep& sweep) requires std::is_same_v<Chart, PivotChart>
      : system_(&system), chart_(chart), sweep_(&sweep) {}

  SeatSystem& system() const { return *system_; }
  const Chart& chart() const { return chart_; }
  OdeState<N> scale() const { return chart_.scale(system_->length_scale(), system_->g()); }
  void operator()(double t, const OdeState<N>& q, OdeState<N>& dq) const {
    if constexpr (std::is_same_v<Chart, PivotChart>) {
      const Vec2 r = chart_.fresh_arm(q[0]);
      const auto state = [&] { return chart_.full_at_arm(q, r); };
      if (const std::optional<double> turning = system_->pivot_turning(t, r, q[1], state)) {
        dq = {q[1], *turning};
        return;
      }
      const BlockState s = state();
      dq = chart_.rates(q, s, system_->solve(t, s).acceleration);
    } else if constexpr (std::is_same_v<Chart, SlipChart>) {
      const Vec2 r = chart_.fresh_arm(q[0]);
      const BlockState s = chart_.full_at_arm(q, r);
      dq = chart_.rates_at_arm(q, r, system_->solve_slipping(t, s, r).acceleration);
    } else {
      const BlockState s = chart_.full(t, q);
      dq = chart_.rates(q, s, system_->solve(t, s).acceleration);
    }
  }
  std::array<double, kGuards> guards(double t, const OdeState<N>& q) const {
    if constexpr (std::is_same_v<Chart, PivotChart>) {
      // As full() turns the arm, once for the state and the guards.
      const SineCosine turn = cached_turn(q[0]);
      const Vec2 r = rotate(chart_.body, turn.cos, turn.sin);
      return system_->pivot_guards(t, chart_.full_at_arm(q, r), turn, r);
    } else {
      return system_->guards(t, chart_.full(t, q));
    }
  }
  double guard(int i, double t, const OdeState<N>& q) const {
    return system_->guard(i, t, chart_.full(t, q));
  }
  std::array<double, kGuards> guards(double t, const OdeState<N>& q,
                                     const GuardClaims& wanted) const {
    return system_->guards(t, chart_.full(t, q), wanted);
  }
  GuardClaims live_guards() const { return system_->live_guards(); }
  std::span<const int> live_slots() const { return system_->live_slots(); }
  SeatEvent event(int guard) const { return system_->event(guard); }
  BlockState full(double t, const OdeState<N>& q) const { return chart_.full(t, q); }
  ContactForces forces(double t, const OdeState<N>& q) const {
    return system_->forces(t, chart_.full(t, q));
  }
  OdeState<N> coordinates(const BlockState& b) const { return chart_.coordinates(b); }
  double penetration(const BlockState& s) const { return system_->penetration(s); }
  // The claims of the guards `asked` names over a step from q0 at t0 to q1 at t1 (a guard claimed
  // is least at one of its ends, so no sample inside can find it lower): one_way(i) says whether
  // coordinate i of the dense output moves one way.
  template <class OneWay>
  GuardClaims guard_claims(double t0, double t1, const OdeState<N>& q0, const OdeState<N>& q1,
                           const OneWay& one_way, const GuardClaims& asked) const {
    if constexpr (std::is_same_v<Chart, PivotChart>) {
      if (!one_way(0)) return system_->unused_guards();
      return sweep_->claims(q0[0], q1[0], asked);
    } else if constexpr (std::is_same_v<Chart, SlipChart>) {
      return system_->slip_claims(chart_, q0, q1, {one_way(0), one_way(2), one_way(3)}, asked);
    } else if constexpr (std::is_same_v<Chart, SlideChart>) {
      return system_->slide_claims(
          chart_.full(0.0, q0), chart_.full(0.0, q1), one_way(0), one_way(1),
          system_->slide_forces_one_way(t0, t1, chart_.line.direction.y), asked);
    } else if constexpr (std::is_same_v<Chart, FlightChart>) {
      return system_->free_claims(chart_.full(chart_.t0, q0).x, chart_.full(chart_.t0, q1).x,
                                  one_way(0), true);
    } else {
      return system_->free_claims(chart_.full(0.0, q0).x, chart_.full(0.0, q1).x, one_way(0),
                                  one_way(2));
    }
  }
  // The same with the guards at the step's ends as guards() found them (at0 at q0, at1 at q1),
  // which turning about a pivot tell whether a watched point is inside the block there.
  template <class OneWay>
  GuardClaims guard_claims(double t0, double t1, const OdeState<N>& q0, const OdeState<N>& q1,
                           const OneWay& one_way, const std::array<double, kGuards>& at0,
                           const std::array<double, kGuards>& at1, const GuardClaims& asked) const {
    if constexpr (std::is_same_v<Chart, PivotChart>) {
      if (!one_way(0)) return system_->unused_guards();
      return sweep_->claims(q0[0], q1[0], asked, at0, at1);
    } else {
      return guard_claims(t0, t1, q0, q1, one_way, asked);
    }
  }
  // In flight, adds to `claims` the clearances among `asked` that a step from (t0, q0) to (t1, q1)
  // cannot bring to zero, the guards at its start `at_start`: spread(i) bounds how far coordinate i
  // of the step's dense output strays from the chord between its ends.
  template <class Spread>
  void claim_swept_clear(double t0, double t1, const OdeState<N>& q0, const OdeState<N>& q1,
                         const Spread& spread, const std::array<double, kGuards>& at_start,
                         const GuardClaims& asked, GuardClaims& claims) const
      requires(std::is_same_v<Chart, FlightChart> || std::is_same_v<Chart, FreeChart>) {
    // A coordinate's dense output lies within spread(i) of the range between its ends.
    const auto range = [&](double a, double b, double strays, double& lo, double& hi) {
      lo = std::min(a, b) - strays;
      hi = std::max(a, b) + strays;
    };
    const BlockState s0 = chart_.full(t0, q0), s1 = chart_.full(t1, q1);
    SweptMotion swept{s0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    constexpr bool kFlight = std::is_same_v<Chart, FlightChart>;
    range(s0.x, s1.x, spread(0), swept.x_lo, swept.x_hi);
    range(s0.y, s1.y, spread(kFlight ? 2 : 1), swept.y_lo, swept.y_hi);
    // In a FlightChart theta is linear in time.
    range(s0.theta, s1.theta, kFlight ? 0.0 : spread(2), swept.theta_lo, swept.theta_hi);
    if (!(swept.x_hi - swept.x_lo + swept.y_hi - swept.y_lo + swept.theta_hi - swept.theta_lo <
          std::numeric_limits<double>::infinity())) {
      return;
    }
    system_->claim_swept_clear(swept, at_start, asked, claims);
  }

 private:
  using Sweep = std::conditional_t<std::is_same_v<Chart, PivotChart>, PivotSweep*, std::monostate>;

  SeatSystem* system_;
  Chart chart_;
  Sweep sweep_{};
};

SeatOde(SeatSystem&, const PivotChart&, PivotSweep&)->SeatOde<PivotChart>;

}  // namespace blockfrag
