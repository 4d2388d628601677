// Where inside one step a mode's guards first cross zero: the guards are positive while the mode
// holds, and the step's dense output says where one stops being so.
#pragma once

#include <algorithm>
#include <array>
#include <limits>

#include "engine/integrate/root_finding.hpp"
#include "engine/tolerances.hpp"

namespace blockfrag {

// How each guard is watched. Armed: clearly positive, fires at zero. Unarmed: not clearly positive,
// fires once clearly below both zero and its start, whether or not it rose clearly above zero first
// (a corner that lifts by less than the margin and comes back must still land), and fires at zero
// once it has risen and armed. A guard that starts a hair below zero is unarmed too: a corner the
// contact tolerance left under the ground, turned further down by the new mode, must land there;
// one that never fired until it armed sank through the ground.
template <int G>
class GuardWatch {
 public:
  explicit GuardWatch(const std::array<double, G>& at_start) : value_(at_start) {
    for (int i = 0; i < G; ++i) {
      armed_[i] = at_start[i] > kArmingMargin;
      // A start below -kArmingMargin (an unarmed guard's event leaves it there) must go lower
      // still to fire: fired at once (its value at the start already past the margin), a corner
      // rising at 3e-7 m/s that gravity brings back within 6e-8 s started flight after flight
      // 1e-15 s apart.
      unarmed_offset_[i] = std::max(kArmingMargin, -at_start[i] * (1 + kUnarmedFurtherDrop));
    }
  }

  struct Crossing {
    int which = -1;  // the guard that crossed first, -1 if none
    double after = std::numeric_limits<double>::infinity();  // just past the crossing
    double before = 0.0;  // the last time the mode's conditions hold
  };

  // The first crossing in the step [t0, t1] whose guards at t1 are `next`; guards_at(x) evaluates
  // all guards on the step's dense output. least_at_ends() says which guards are known to be
  // least at an end of this step (so no sample inside can find them lower); it is asked only when
  // a guard near zero would be looked inside, and a guard clearly positive at both ends that it
  // names is not: the samples were most of a rocking block's guard evaluations, and they find
  // exactly what they found before.
  template <class GuardsAt, class LeastAtEnds>
  Crossing first_crossing(const GuardsAt& guards_at, double t0, double t1,
                          const std::array<double, G>& next,
                          const LeastAtEnds& least_at_ends) const {
    const double time_tolerance = kEventTimeTolerance * (1.0 + t1);
    Crossing found;
    found.before = t1;
    // Set for every guard below before they are read (the samples up to seen_count only), so not
    // zeroed first: G (kInteriorSamples + 1) doubles zeroed at every step were a quarter of the
    // instructions of a block rocking on a seat (G = 64).
    std::array<double, G> offset, a, fa, b, fb;
    std::array<bool, G> sampled, looked_inside;
    // The samples of each guard looked inside, up to its first one at or below zero.
    std::array<std::array<double, kInteriorSamples + 1>, G> seen;
    std::array<int, G> seen_count;
    bool any_sampled = false;
    bool ends_known = false;
    std::array<bool, G> least_at_end{};
    for (int i = 0; i < G; ++i) {
      offset[i] = armed_[i] ? 0.0 : unarmed_offset_[i];
      a[i] = t0;
      fa[i] = std::max(value_[i] + offset[i], std::numeric_limits<double>::min());
      b[i] = t1;
      fb[i] = next[i] + offset[i];
      // A guard close to zero may dip below it and come back inside one step: look inside.
      sampled[i] = !armed_[i] || std::min(fa[i], fb[i]) < kNearZero;
      // Clearly positive: above the guards' rounding noise by far.
      if (sampled[i] && std::min(fa[i], fb[i]) > 0.5 * kArmingMargin) {
        if (!ends_known) {
          least_at_end = least_at_ends();
          ends_known = true;
        }
        sampled[i] = !least_at_end[i];
      }
      looked_inside[i] = sampled[i];
      seen[i][0] = fa[i];
      seen_count[i] = 1;
      any_sampled = any_sampled || sampled[i];
    }
    // One evaluation of all guards per interior sample serves every guard that is looked inside.
    for (int k = 1; any_sampled && k < kInteriorSamples; ++k) {
      const double x = t0 + (t1 - t0) * k / kInteriorSamples;
      const std::array<double, G> at_x = guards_at(x);
      any_sampled = false;
      for (int i = 0; i < G; ++i) {
        if (!sampled[i]) continue;
        const double fx = at_x[i] + offset[i];
        seen[i][seen_count[i]++] = fx;
        if (fx <= 0) {
          b[i] = x;
          fb[i] = fx;
          sampled[i] = false;
          continue;
        }
        a[i] = x;
        fa[i] = fx;
        any_sampled = true;
      }
    }
    for (int i = 0; i < G; ++i) {
      if (!looked_inside[i]) continue;
      if (sampled[i]) seen[i][seen_count[i]++] = fb[i];
      find_dip_between_samples(guards_at, i, t0, (t1 - t0) / kInteriorSamples, offset[i], seen[i],
                               seen_count[i], a[i], fa[i], b[i], fb[i]);
    }
    for (int i = 0; i < G; ++i) {
      if (fb[i] > 0) continue;
      const auto f = [&](double x) { return guards_at(x)[i] + offset[i]; };
      const Bracket located = locate_crossing(f, a[i], b[i], fa[i], fb[i], time_tolerance);
      if (located.after < found.after) found = {i, located.after, located.before};
    }
    if (found.which >= 0) found = no_earlier_dip(guards_at, t0, found, time_tolerance);
    return found;
  }

  // Whether guard i was armed at the step's start: a guard that was not fires below -offset.
  bool armed(int i) const { return armed_[i]; }

  // The step is kept: its end values become the next step's start.
  void advance(const std::array<double, G>& next) {
    for (int i = 0; i < G; ++i) armed_[i] = armed_[i] || next[i] > kArmingMargin;
    value_ = next;
  }

 private:
  // Before accepting an event, make sure no other armed guard dipped below zero earlier in the
  // step (near a singular boundary forces can swing through zero and back between samples).
  template <class GuardsAt>
  Crossing no_earlier_dip(const GuardsAt& guards_at, double t0, Crossing found,
                          double time_tolerance) const {
    std::array<double, G> before = value_;
    const double t_found = found.after;
    const int first_found = found.which;
    double x_before = t0;
    for (int k = 1; k <= kInteriorSamples; ++k) {
      const double x = t0 + (t_found - t0) * k / kInteriorSamples;
      const std::array<double, G> at_x = guards_at(x);
      bool dipped = false;
      for (int i = 0; i < G; ++i) {
        if (i == first_found || !armed_[i] || at_x[i] > 0) continue;
        const auto f = [&](double y) { return guards_at(y)[i]; };
        const Bracket located = locate_crossing(f, x_before, x, before[i], at_x[i], time_tolerance);
        if (located.after < found.after) found = {i, located.after, located.before};
        dipped = true;
      }
      if (dipped) break;
      before = at_x;
      x_before = x;
    }
    return found;
  }

  // Samples a few milliseconds apart can straddle a dip below zero that is narrower than their
  // spacing (a rocking block's other corner turning back 2.9e-7 R under the ground inside a
  // 28 ms step). Where a sample is lower than both neighbours, the parabola through the three
  // places the minimum; if it predicts a dip, the guard is evaluated there, and a value at or
  // below zero brackets the crossing from the sample before it.
  template <class GuardsAt>
  static void find_dip_between_samples(const GuardsAt& guards_at, int i, double t0, double spacing,
                                       double offset,
                                       const std::array<double, kInteriorSamples + 1>& seen,
                                       int count, double& a, double& fa, double& b, double& fb) {
    for (int k = 1; k + 1 < count; ++k) {
      const double left = seen[k - 1], mid = seen[k], right = seen[k + 1];
      if (!(mid < left && mid < right)) continue;
      const double curvature = left - 2 * mid + right;
      const double shift = 0.5 * (left - right) / curvature;  // in spacings, within +-1/2
      const double predicted = mid - 0.25 * (left - right) * shift;
      if (predicted > 0.25 * mid) continue;
      const double x = t0 + (k + shift) * spacing;
      const double fx = guards_at(x)[i] + offset;
      if (fx > 0) continue;
      a = t0 + (shift < 0 ? k - 1 : k) * spacing;
      fa = shift < 0 ? left : mid;
      b = x;
      fb = fx;
      return;
    }
  }

  std::array<double, G> value_;
  std::array<double, G> unarmed_offset_{};  // an unarmed guard fires below minus this
  std::array<bool, G> armed_{};
};

}  // namespace blockfrag
