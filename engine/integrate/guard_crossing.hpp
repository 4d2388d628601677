// Where inside one step a mode's guards first cross zero: the guards are positive while the mode
// holds, and the step's dense output says where one stops being so.
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <span>

#include "engine/integrate/root_finding.hpp"
#include "engine/tolerances.hpp"

namespace blockfrag {

// Guard i at x: guards_at(i, x) where the guards offer one alone (a seat's clearances, each a pass
// over the block's vertices or edges), else the one of all of them that guards_at(x) gives.
template <class GuardsAt>
double guard_from(const GuardsAt& guards_at, int i, double x) {
  if constexpr (requires { guards_at(i, x); }) {
    return guards_at(i, x);
  } else {
    return guards_at(x)[static_cast<std::size_t>(i)];
  }
}

// The guards `wanted` names at x (the others unset): guards_at(x, wanted) where the guards offer
// some alone, else all of them.
template <class GuardsAt, std::size_t G>
std::array<double, G> guards_from(const GuardsAt& guards_at, double x,
                                  const std::array<bool, G>& wanted) {
  if constexpr (requires { guards_at(x, wanted); }) {
    return guards_at(x, wanted);
  } else {
    return guards_at(x);
  }
}

// The indices of the true entries of `flags`, in order, into `out` (the first of it); returns how
// many. Read eight flags a word, a bool's byte being 0 or 1, so that a word's true flags are its
// set bits: a watch is set up at every motion piece (a record's every sample) over a seat's 64
// guard slots, most of them unused, and a pass over each flag was most of setting it up.
template <std::size_t G>
int set_indices(const std::array<bool, G>& flags, std::array<int, G>& out) {
  static_assert(sizeof(bool) == 1);
  int count = 0;
  std::size_t at = 0;
  for (; at + 8 <= G; at += 8) {
    std::uint64_t word;
    std::memcpy(&word, flags.data() + at, sizeof word);
    for (; word != 0; word &= word - 1) {
      out[static_cast<std::size_t>(count++)] = static_cast<int>(at) + std::countr_zero(word) / 8;
    }
  }
  for (; at < G; ++at) {
    if (flags[at]) out[static_cast<std::size_t>(count++)] = static_cast<int>(at);
  }
  return count;
}

// How each guard is watched. Armed: clearly positive, fires at zero. Unarmed: not clearly positive,
// fires once clearly below both zero and its start, whether or not it rose clearly above zero first
// (a corner that lifts by less than the margin and comes back must still land), and fires at zero
// once it has risen and armed. A guard that starts a hair below zero is unarmed too: a corner the
// contact tolerance left under the ground, turned further down by the new mode, must land there;
// one that never fired until it armed sank through the ground.
template <int G>
class GuardWatch {
 public:
  explicit GuardWatch(const std::array<double, G>& at_start) : GuardWatch(at_start, all_live()) {}
  // Only the guards `live` names are watched: the others (unused slots of a system's guards) are
  // positive throughout and never cross.
  GuardWatch(const std::array<double, G>& at_start, const std::array<bool, G>& live)
      : value_(at_start), live_count_(set_indices(live, live_)) {
    arm_live();
  }
  // The same with the live guards named by their indices, in increasing order (a seat's system
  // lists them as it lays its slots out).
  GuardWatch(const std::array<double, G>& at_start, std::span<const int> live)
      : value_(at_start), live_count_(static_cast<int>(live.size())) {
    std::copy(live.begin(), live.end(), live_.begin());
    arm_live();
  }

  struct Crossing {
    int which = -1;  // the guard that crossed first, -1 if none
    double after = std::numeric_limits<double>::infinity();  // just past the crossing
    double before = 0.0;  // the last time the mode's conditions hold
  };

  // The first crossing in the step [t0, t1] whose guards at t1 are `next`; guards_at(x) evaluates
  // all guards on the step's dense output (and guards_at(i, x), where given, guard i alone: root
  // finding and the dip search ask for one). least_at_ends(asked) says which of the guards `asked`
  // names are known to be least at an end of this step, or to stay positive throughout it (so no
  // sample inside can find them at or below zero);
  // it is asked only for guards near zero that would be looked inside though clearly positive at
  // both ends, and such a guard that it names is not: the samples were most of a rocking block's
  // guard evaluations, and they find exactly what they found before.
  template <class GuardsAt, class LeastAtEnds>
  Crossing first_crossing(const GuardsAt& guards_at, double t0, double t1,
                          const std::array<double, G>& next, const LeastAtEnds& least_at_ends) {
    const double time_tolerance = kEventTimeTolerance * (1.0 + t1);
    Crossing found;
    found.before = t1;
    Scan& scan = scan_;
    if (start_scan(scan, t0, t1, next, least_at_ends)) sample_inside(scan, guards_at, t0, t1);
    // A guard not bracketed is clearly positive at the step's end (its fb).
    for (const int i : bracketed(scan)) {
      if (scan.fb[i] > 0) continue;
      const auto f = [&](double x) { return guard_from(guards_at, i, x) + scan.offset[i]; };
      const Bracket located =
          locate_crossing(f, scan.a[i], scan.b[i], scan.fa[i], scan.fb[i], time_tolerance);
      if (located.after < found.after) found = {i, located.after, located.before};
    }
    if (found.which >= 0) found = no_earlier_dip(guards_at, t0, found, time_tolerance);
    return found;
  }

  // Whether guard i was armed at the step's start: a guard that was not fires below -offset.
  bool armed(int i) const { return armed_[i]; }
  // The level guard i fires at: zero armed, -offset unarmed.
  double fires_below(int i) const { return armed_[i] ? 0.0 : -unarmed_offset_[i]; }
  // The guards at the step's start (the live ones' values; the others are not to be read).
  const std::array<double, G>& values() const { return value_; }

  // The step is kept: its end values become the next step's start.
  void advance(const std::array<double, G>& next) {
    if constexpr (G > kCopiedWhole) {
      // Only the live guards' values are read: copying all G was half of this on a seat (G = 64,
      // most slots unused).
      for (const int i : live()) {
        armed_[i] = armed_[i] || next[i] > kArmingMargin;
        value_[i] = next[i];
      }
    } else {
      for (const int i : live()) armed_[i] = armed_[i] || next[i] > kArmingMargin;
      value_ = next;
    }
  }

  // The guards watched, in increasing order: only their entries are set.
  std::span<const int> live() const {
    return std::span(live_).first(static_cast<std::size_t>(live_count_));
  }

 private:
  static std::array<bool, G> all_live() {
    std::array<bool, G> live;
    live.fill(true);
    return live;
  }
  // Only the live guards' entries are set, and only theirs are read: a watch is set up at every
  // motion piece (a record's every sample), most of a seat's 64 guard slots unused.
  void arm_live() {
    for (const int i : live()) {
      armed_[i] = value_[i] > kArmingMargin;
      // A start below -kArmingMargin (an unarmed guard's event leaves it there) must go lower
      // still to fire: fired at once (its value at the start already past the margin), a corner
      // rising at 3e-7 m/s that gravity brings back within 6e-8 s started flight after flight
      // 1e-15 s apart.
      unarmed_offset_[i] = std::max(kArmingMargin, -value_[i] * (1 + kUnarmedFurtherDrop));
    }
  }

  // A step's look at its live guards: each one's bracket [a, b] of its last sample above zero and
  // its first at or below (offset added), whether it is looked inside, and its samples inside up to
  // its first at or below zero (the first seen_count). Kept from step to step (scan_), each live
  // guard's entries set before they are read: zeroed at every step, G (kInteriorSamples + 1)
  // doubles were a quarter of the instructions of a block rocking on a seat (G = 64), and its
  // brackets alone 2.5 %.
  struct Scan {
    std::array<double, G> offset, a, fa, b, fb;
    // All G read as the guards wanted at a sample: the unused slots stay false.
    std::array<bool, G> sampled{};
    std::array<bool, G> looked_inside;
    std::array<std::array<double, kInteriorSamples + 1>, G> seen;
    std::array<int, G> seen_count;
    // The guards whose bracket is set, in order (the first bracketed_count): only they can be
    // sampled, looked inside or at or below zero at the step's end.
    std::array<int, G> bracketed;
    int bracketed_count = 0;
  };
  static std::span<const int> bracketed(const Scan& scan) {
    return std::span(scan.bracketed).first(static_cast<std::size_t>(scan.bracketed_count));
  }

  // The step's ends, and which guards are looked inside; returns whether any is. Of an armed guard
  // clearly positive at both ends (most of a seat's, at most steps) only its end value is read
  // after: its bracket, its samples and its question to least_at_ends are left unset.
  template <class LeastAtEnds>
  bool start_scan(Scan& scan, double t0, double t1, const std::array<double, G>& next,
                  const LeastAtEnds& least_at_ends) const {
    std::array<bool, G> asked{};
    bool any_asked = false;
    int count = 0;
    for (const int i : live()) {
      // Most guards at most steps: far from zero at both ends (and so armed), neither sampled nor
      // looked inside; only the end value is read after.
      if (value_[i] >= kNearZero && next[i] >= kNearZero) {
        scan.fb[i] = next[i];
        scan.sampled[i] = false;
        scan.looked_inside[i] = false;
        continue;
      }
      scan.offset[i] = armed_[i] ? 0.0 : unarmed_offset_[i];
      const double fa = std::max(value_[i] + scan.offset[i], std::numeric_limits<double>::min());
      scan.fb[i] = next[i] + scan.offset[i];
      const double least = std::min(fa, scan.fb[i]);
      // A guard close to zero may dip below it and come back inside one step: look inside.
      scan.sampled[i] = !armed_[i] || least < kNearZero;
      if (!scan.sampled[i] && scan.fb[i] > 0) {
        scan.looked_inside[i] = false;
        continue;
      }
      scan.a[i] = t0;
      scan.fa[i] = fa;
      scan.b[i] = t1;
      // Clearly positive: above the guards' rounding noise by far.
      asked[i] = scan.sampled[i] && least > 0.5 * kArmingMargin;
      any_asked = any_asked || asked[i];
      scan.bracketed[static_cast<std::size_t>(count++)] = i;
    }
    scan.bracketed_count = count;
    const std::array<bool, G> claimed = any_asked ? least_at_ends(asked) : std::array<bool, G>{};
    bool any_sampled = false;
    for (const int i : bracketed(scan)) {
      scan.sampled[i] = scan.sampled[i] && !(asked[i] && claimed[i]);
      scan.looked_inside[i] = scan.sampled[i];
      scan.seen[i][0] = scan.fa[i];
      scan.seen_count[i] = 1;
      any_sampled = any_sampled || scan.sampled[i];
    }
    return any_sampled;
  }

  // One evaluation of all guards per interior sample serves every guard that is looked inside.
  template <class GuardsAt>
  void sample_inside(Scan& scan, const GuardsAt& guards_at, double t0, double t1) const {
    bool any_sampled = true;
    for (int k = 1; any_sampled && k < kInteriorSamples; ++k) {
      const double x = t0 + (t1 - t0) * k / kInteriorSamples;
      // Only the guards still sampled are read.
      const std::array<double, G> at_x = guards_from(guards_at, x, scan.sampled);
      any_sampled = false;
      for (const int i : bracketed(scan)) {
        if (!scan.sampled[i]) continue;
        const double fx = at_x[i] + scan.offset[i];
        scan.seen[i][scan.seen_count[i]++] = fx;
        if (fx <= 0) {
          scan.b[i] = x;
          scan.fb[i] = fx;
          scan.sampled[i] = false;
          continue;
        }
        scan.a[i] = x;
        scan.fa[i] = fx;
        any_sampled = true;
      }
    }
    for (const int i : bracketed(scan)) {
      if (!scan.looked_inside[i]) continue;
      if (scan.sampled[i]) scan.seen[i][scan.seen_count[i]++] = scan.fb[i];
      find_dip_between_samples(guards_at, i, t0, (t1 - t0) / kInteriorSamples, scan.offset[i],
                               scan.seen[i], scan.seen_count[i], scan.a[i], scan.fa[i], scan.b[i],
                               scan.fb[i]);
    }
  }

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
      for (const int i : live()) {
        if (i == first_found || !armed_[i] || at_x[i] > 0) continue;
        const auto f = [&](double y) { return guard_from(guards_at, i, y); };
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
      const double fx = guard_from(guards_at, i, x) + offset;
      if (fx > 0) continue;
      a = t0 + (shift < 0 ? k - 1 : k) * spacing;
      fa = shift < 0 ? left : mid;
      b = x;
      fb = fx;
      return;
    }
  }

  // A system of at most this many guards (the flat ground's modes' few) has its values copied
  // whole at each step: one copy costs less than a loop over them.
  static constexpr int kCopiedWhole = 8;

  // Only the live guards' entries are set and read: a watch is made at every motion piece, and
  // zeroing its arrays and its scan's (some 3.5 kB on a seat) was most of making it.
  std::array<double, G> value_;
  std::array<double, G> unarmed_offset_;  // an unarmed guard fires below minus this
  std::array<bool, G> armed_;
  std::array<int, G> live_;  // the guards watched, in order (the first live_count_)
  int live_count_ = 0;
  Scan scan_;
};

}  // namespace blockfrag
