// Bracketed root finding for event location on dense output.
#pragma once

#include <cmath>

namespace blockfrag {

struct Bracket {
  double before, after;  // f(before) > 0 >= f(after), after - before within the tolerance
};

// f(a) > 0 >= f(b). Illinois regula falsi with a bisection fallback: converges superlinearly on
// smooth guards and never leaves the bracket. Returns the final bracket so callers can take the
// side after the crossing (where the new mode's conditions already hold strictly).
template <class F>
Bracket locate_crossing(F&& f, double a, double b, double fa, double fb, double time_tolerance) {
  int side = 0;
  for (int iteration = 0; iteration < 200 && b - a > time_tolerance; ++iteration) {
    double c = (fa - fb) != 0.0 ? a + fa * (b - a) / (fa - fb) : 0.5 * (a + b);
    const double width = b - a;
    // Bisect when the secant lands too close to an end: keeps the bracket shrinking.
    if (!(c > a + 0.01 * width && c < b - 0.01 * width)) c = 0.5 * (a + b);
    const double fc = f(c);
    if (fc > 0.0) {
      a = c;
      fa = fc;
      if (side == 1) fb *= 0.5;
      side = 1;
    } else {
      b = c;
      fb = fc;
      if (side == -1) fa *= 0.5;
      side = -1;
    }
  }
  return {a, b};
}

}  // namespace blockfrag
