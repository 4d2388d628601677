// Bracketed root finding for event location on dense output.
#pragma once

#include <algorithm>
#include <cmath>

#include "engine/tolerances.hpp"

namespace blockfrag {

struct Bracket {
  double before, after;  // f(before) > 0 >= f(after), after - before within the tolerance
};

// f(a) > 0 >= f(b). Illinois regula falsi: converges superlinearly on smooth guards and never
// leaves the bracket. A secant estimate is kept 1/100 of the bracket (at least half a tolerance)
// inside it: a crossing that close to an end is then bracketed by the next evaluation, a hundred
// times narrower (without this, converging from one side leaves the far end in place and the
// bracket never closes), and an end value that says little (a guard that starts at zero) cannot
// pin the estimate to that end. Bisects when four steps in a row have not halved the bracket
// (kinked or badly scaled guards). Returns the final bracket so callers can take the side after
// the crossing (where the new mode's conditions already hold strictly). Given a value_tolerance, a
// point with -value_tolerance <= f <= 0 also ends it (below the guard's rounding noise its sign
// says nothing more about where the crossing is): then only `after` is close to the crossing.
template <class F>
Bracket locate_crossing(F&& f, double a, double b, double fa, double fb, double time_tolerance,
                        double value_tolerance = 0.0) {
  int side = 0, without_halving = 0;
  double last_halving_width = b - a;
  for (int iteration = 0; iteration < kMaxBracketSteps && b - a > time_tolerance; ++iteration) {
    const double inside = std::max(0.5 * time_tolerance, 0.01 * (b - a));
    double c = 0.5 * (a + b);
    if (without_halving < 4 && fa != fb) {
      c = std::clamp(a + fa * (b - a) / (fa - fb), a + inside, b - inside);
    }
    const double fc = f(c);
    if (fc > 0.0) {
      a = c;
      fa = fc;
      if (side == 1) fb *= 0.5;
      side = 1;
    } else {
      b = c;
      fb = fc;
      if (value_tolerance > 0 && fc >= -value_tolerance) break;
      if (side == -1) fa *= 0.5;
      side = -1;
    }
    if (b - a <= 0.5 * last_halving_width) {
      last_halving_width = b - a;
      without_halving = 0;
    } else {
      ++without_halving;
    }
  }
  return {a, b};
}

}  // namespace blockfrag
