// f(theta) = c + a cos(theta) + b sin(theta): a point's coordinate, its height over a line or its
// squared distance from another point, while the block turns about a fixed point. Where such a
// function is least, and whether a step's range of theta holds that place, for the seat's guards
// (engine/seat/seat_ends.cpp).
#pragma once

#include <cmath>
#include <limits>
#include <numbers>

#include "engine/sine_cosine.hpp"

namespace blockfrag {

inline constexpr double kFullTurn = 2 * std::numbers::pi;

struct Sinusoid {
  double c, a, b;

  double at(SineCosine turn) const { return c + a * turn.cos + b * turn.sin; }
  Sinusoid operator-() const { return {-c, -a, -b}; }
  double amplitude() const { return std::hypot(a, b); }
  // Where f is least, in [0, 2 pi); NaN for a constant.
  double least_at() const {
    if (a == 0.0 && b == 0.0) return std::numeric_limits<double>::quiet_NaN();
    const double at = std::atan2(-b, -a);
    return at < 0 ? at + kFullTurn : at;
  }
};

// The angles theta in [lo, hi] widened by kMargin either way, modulo a full turn. The margin (rad)
// keeps a claim that no extreme lies inside a step true where rounding moves the extreme's place
// by a few ulps.
class AngleRange {
 public:
  static constexpr double kMargin = 1e-9;

  AngleRange(double lo, double hi)
      : start_(lo - kMargin - kFullTurn * std::floor((lo - kMargin) / kFullTurn)),
        span_(hi - lo + 2 * kMargin) {}
  // Whether the range holds angle (in [0, 2 pi); NaN: never).
  bool holds(double angle) const {
    if (!(span_ < kFullTurn)) return !std::isnan(angle);
    double d = angle - start_;
    if (d < 0) d += kFullTurn;
    return d <= span_;
  }

 private:
  double start_, span_;
};

}  // namespace blockfrag
