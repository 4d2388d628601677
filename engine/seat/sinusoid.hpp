// f(theta) = c + a cos(theta) + b sin(theta): a point's coordinate, its height over a line or its
// squared distance from another point, while the block turns about a fixed point; and whether a
// step's range of theta holds such a function's minimum, for the seat's guards
// (engine/seat/seat_ends.cpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>

#include "engine/sine_cosine.hpp"
#include "engine/tolerances.hpp"

namespace blockfrag {

struct Sinusoid {
  double c, a, b;

  double at(SineCosine turn) const { return c + a * turn.cos + b * turn.sin; }
  double slope_at(SineCosine turn) const { return b * turn.cos - a * turn.sin; }
  Sinusoid operator-() const { return {-c, -a, -b}; }
};

// A step's range of theta, [lo, hi], widened by kThetaStepMarginRad either way where it asks
// whether a sinusoid's minimum lies in it.
class ThetaStep {
 public:
  ThetaStep(double lo, double hi) : ThetaStep(lo, hi, sine_cosine(lo), sine_cosine(hi)) {}
  // lo_turn and hi_turn: sine_cosine(lo) and sine_cosine(hi), known to the caller.
  ThetaStep(double lo, double hi, SineCosine lo_turn, SineCosine hi_turn)
      : lo_(lo_turn),
        hi_(hi_turn),
        // sin and cos the margin further out: cos(margin) is 1 and sin(margin) the margin in
        // doubles.
        lo_wide_{lo_.sin - kThetaStepMarginRad * lo_.cos, lo_.cos + kThetaStepMarginRad * lo_.sin},
        hi_wide_{hi_.sin + kThetaStepMarginRad * hi_.cos, hi_.cos - kThetaStepMarginRad * hi_.sin},
        wide_(hi - lo + 2 * kThetaStepMarginRad >= std::numbers::pi) {}

  SineCosine lo() const { return lo_; }
  SineCosine hi() const { return hi_; }
  // Whether f has a local minimum in the widened range: a range shorter than half a turn holds at
  // most one of its extremes, a minimum where its slope goes from <= 0 to >= 0 across the range.
  bool holds_minimum(const Sinusoid& f) const {
    if (f.a == 0.0 && f.b == 0.0) return false;
    return wide_ || (f.slope_at(lo_wide_) <= 0 && f.slope_at(hi_wide_) >= 0);
  }
  // The least and largest value of f over [lo, hi] (exact where no extreme lies inside).
  double least(const Sinusoid& f) const {
    return holds_minimum(f) ? f.c - std::hypot(f.a, f.b) : std::min(f.at(lo_), f.at(hi_));
  }
  double largest(const Sinusoid& f) const { return -least(-f); }
  // least(f) and largest(f) to the bit, each slope and value found once: -f's are f's negated
  // exactly, so -f holds a minimum where f's slopes say it holds a maximum.
  struct Extent {
    double least, largest;
  };
  Extent extent(const Sinusoid& f) const {
    bool holds_min = wide_, holds_max = wide_;
    if (f.a == 0.0 && f.b == 0.0) {
      holds_min = holds_max = false;
    } else if (!wide_) {
      const double slope_lo = f.slope_at(lo_wide_), slope_hi = f.slope_at(hi_wide_);
      holds_min = slope_lo <= 0 && slope_hi >= 0;
      holds_max = slope_lo >= 0 && slope_hi <= 0;
    }
    if (holds_min && holds_max) {
      const double swing = std::hypot(f.a, f.b);
      return {f.c - swing, f.c + swing};
    }
    const double at_lo = f.at(lo_), at_hi = f.at(hi_);
    return {holds_min ? f.c - std::hypot(f.a, f.b) : std::min(at_lo, at_hi),
            holds_max ? f.c + std::hypot(f.a, f.b) : std::max(at_lo, at_hi)};
  }

 private:
  SineCosine lo_, hi_, lo_wide_, hi_wide_;
  bool wide_;
};

}  // namespace blockfrag
