// Watches the trajectory as the simulation advances: the extremes the summary reports (found on
// the dense output, not only at step ends) and the time history at a fixed output interval.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "engine/integrate/root_finding.hpp"
#include "engine/modes/modes.hpp"
#include "engine/scene/block_state.hpp"
#include "engine/summary.hpp"
#include "engine/tolerances.hpp"

namespace blockfrag {

class SegmentObserver {
 public:
  SegmentObserver(Summary& summary, BlockGeometry& geometry, double output_interval, double g)
      : summary_(summary), geometry_(geometry), interval_(output_interval), g_(g) {}

  void start(const BlockState& s) {
    x0_ = s.x;
    observe_state(s);
  }

  void observe_state(const BlockState& s) {
    // An impact changes velocities only: the state after it is where the step into it ended,
    // already looked at.
    if (s.x == last_x_ && s.y == last_y_ && s.theta == last_theta_) return;
    last_x_ = s.x;
    last_y_ = s.y;
    last_theta_ = s.theta;
    summary_.max_abs_theta = std::max(summary_.max_abs_theta, std::abs(s.theta));
    summary_.max_abs_slide = std::max(summary_.max_abs_slide, std::abs(s.x - x0_));
    if (!measures_depth_) return;
    const Rotation turn = geometry_.rotation(s.theta);
    double lowest = 0.0;
    for (int i = 0; i < geometry_.corner_count(); ++i) {
      lowest = std::min(lowest, s.y + rotate(geometry_.corner(i), turn).y);
    }
    summary_.max_penetration = std::max(summary_.max_penetration, -lowest / geometry_.size());
  }

  // One step [t0, t1] of a segment in which state_at(t) and forces_at(t) (per unit mass) are
  // defined; extremes of theta and x inside the step are where omega and vx change sign.
  template <class StateAt, class ForcesAt>
  void observe_step(double t0, double t1, const StateAt& state_at, const ForcesAt& forces_at,
                    ModeKind mode) {
    observe_step(t0, t1, state_at(t0), state_at(t1), state_at, forces_at, mode);
  }
  // The same with the states at t0 and t1 given.
  template <class StateAt, class ForcesAt>
  void observe_step(double t0, double t1, const BlockState& a, const BlockState& b,
                    const StateAt& state_at, const ForcesAt& forces_at, ModeKind mode) {
    observe_state(b);
    if (a.omega * b.omega < 0) observe_extremum(t0, t1, a.omega, state_at, &BlockState::omega);
    if (a.vx * b.vx < 0) observe_extremum(t0, t1, a.vx, state_at, &BlockState::vx);
    if (interval_ <= 0) return;
    while (next_output_ <= t1 * (1 + kOutputTimeRounding)) {
      const double t = std::max(next_output_, t0);
      record(t, state_at(t), forces_at(t), mode);
      next_output_ = interval_ * static_cast<double>(++outputs_);
    }
  }

  void finish(double t, const BlockState& s, const ContactForces& forces, ModeKind mode) {
    if (interval_ > 0 && (history_.empty() || history_.back().t < t)) record(t, s, forces, mode);
  }

  // The depth below a flat ground at y = 0 is not measured: a ground of another shape measures
  // its own (a seat's, at every step, from the vertices its guards turned).
  void leave_depth_to_ground() { measures_depth_ = false; }

  double x0() const { return x0_; }
  std::vector<HistoryRow>& history() { return history_; }

 private:
  template <class StateAt>
  void observe_extremum(double t0, double t1, double rate0, const StateAt& state_at,
                        double BlockState::*rate) {
    const double sign = rate0 > 0 ? 1.0 : -1.0;
    const auto f = [&](double t) { return sign * (state_at(t).*rate); };
    // A tolerance below a few ulps of t could never be met.
    const double tolerance = std::max(kStateExtremumTimeTolerance * (t1 - t0),
                                      8 * std::numeric_limits<double>::epsilon() * std::abs(t1));
    const Bracket at = locate_crossing(f, t0, t1, f(t0), f(t1), tolerance);
    observe_state(state_at(at.after));
  }

  void record(double t, const BlockState& s, const ContactForces& f, ModeKind mode) {
    history_.push_back(
        {t, s.x - x0_, s.y, s.theta, s.vx, s.vy, s.omega, mode, f.friction / g_, f.normal / g_});
  }

  Summary& summary_;
  BlockGeometry& geometry_;
  double interval_, g_;
  bool measures_depth_ = true;
  double x0_ = 0.0;
  // The pose last looked at (NaN: none yet).
  double last_x_ = std::numeric_limits<double>::quiet_NaN(), last_y_ = last_x_,
         last_theta_ = last_x_;
  double next_output_ = 0.0;
  long outputs_ = 0;
  std::vector<HistoryRow> history_;
};

}  // namespace blockfrag
