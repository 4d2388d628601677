// How far the fragility fits' Newton iterations (lognormal_fit.cpp, fragility_surface.cpp) move
// along each step. Their ln L is concave, so near the maximum Newton's whole step is right and
// converges quadratically; a step overshoots where the quadratic model is poor, far from it (from
// the linearised start, or on a steepest-ascent step where the curvature underflows). Halving from
// the whole step and accepting the first length that gains a small fraction of the gain the slope
// predicts (Armijo's test; Nocedal & Wright 2006, ch. 3) is therefore enough: a finer search would
// spend evaluations of ln L, each a pass over the data, on a step the next Newton step corrects
// anyway.
#pragma once

#include <optional>

namespace blockfrag {

// Where a step up a function f starts.
struct AscentStart {
  double value;           // f here
  double value_scale;     // the sum of the magnitudes of f's terms: what f can resolve
  double predicted_gain;  // f's slope along the step, g . d (> 0 for an ascent direction)
  bool newton;            // whether the step is Newton's (else steepest ascent)
};

// The fraction of the predicted gain a step length must gain to be accepted.
inline constexpr double kSufficientGain = 1e-4;
// Each rejected length is halved, down to this one (60 tries): shorter, a step of any sensible
// size no longer moves a coordinate of order one, and only rounding is left to gain.
inline constexpr double kShortestStepLength = 1e-18;
// A Newton step predicting less than this times (value_scale + 1) is taken whole: ln L cannot
// register that gain through the rounding of its terms, so the test would reject the steps that
// finish the climb and the fit would stop short of its tolerance; Newton's step is then trusted,
// its error being quadratic. A steepest-ascent step has no such promise about its length.
inline constexpr double kUnresolvableGain = 1e-13;

// The first of the lengths t = 1, 1/2, 1/4, ... with value_at(t) >= start.value +
// kSufficientGain t start.predicted_gain, where value_at(t) is f at the start moved t times the
// step (t = 1 whatever it gains when the step is Newton's and its gain unresolvable); none when
// even the shortest fails. value_at is last called at the length returned, so it may keep what it
// computed there.
template <class ValueAt>
std::optional<double> backtracking_line_search(const AscentStart& start, ValueAt&& value_at) {
  const bool unresolvable =
      start.newton && start.predicted_gain <= kUnresolvableGain * (start.value_scale + 1.0);
  for (double t = 1.0; t > kShortestStepLength; t *= 0.5) {
    const double value = value_at(t);
    if (unresolvable || value >= start.value + kSufficientGain * t * start.predicted_gain) return t;
  }
  return std::nullopt;
}

}  // namespace blockfrag
