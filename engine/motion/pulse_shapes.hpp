// The formulas of the pulse shapes that are not one sine or cosine
// (engine/motion/near_fault_pulses.hpp says where each comes from), their derivatives for finding
// extrema, and the phase of Makris's type C_n pulse. The lambda formulas are inline:
// MotionPiece::lambda calls them at every stage.
#pragma once

#include <cmath>
#include <functional>
#include <vector>

namespace blockfrag::pulse {

// Ricker: (1 - 2 u^2) exp(-u^2).
inline double ricker(double u) {
  const double u2 = u * u;
  return (1.0 - 2.0 * u2) * std::exp(-u2);
}

// Mavroeidis-Papageorgiou lambda over (Vp Omega / (2 g)) at x = Omega tau, with k = 1/gamma:
//   sin(x + nu) + (1 + k)/2 sin((1 + k) x + nu) + (1 - k)/2 sin((1 - k) x + nu),
// the derivative of -(2/Vp) v = -[1 + cos(k x)] cos(x + nu) in x; at most 2 in magnitude.
inline double mavroeidis_papageorgiou(double x, double k, double nu) {
  return std::sin(x + nu) + 0.5 * (1.0 + k) * std::sin((1.0 + k) * x + nu) +
         0.5 * (1.0 - k) * std::sin((1.0 - k) * x + nu);
}
// Its derivative in x; the derivative of this is at most 2 + 3 k^2 in magnitude (the sum of the
// three terms' amplitudes times their frequencies cubed).
inline double mavroeidis_papageorgiou_slope(double x, double k, double nu) {
  const double up = 1.0 + k, down = 1.0 - k;
  return std::cos(x + nu) + 0.5 * up * up * std::cos(up * x + nu) +
         0.5 * down * down * std::cos(down * x + nu);
}
inline double mavroeidis_papageorgiou_curvature_bound(double k) { return 2.0 + 3.0 * k * k; }

// The phi in (0, pi/2) that brings the ground displacement of the type C_n pulse back to zero:
// the root of 2 cos(phi) - ((2n + 1) pi - 2 phi) sin(phi), found by bisection to round-off.
double makris_c_phase(int n);

// The zeros of f in (t0, t1) where f changes sign, given |f'| <= slope_bound there. The interval
// is cut into cells of at most `cell`, and a cell is split until the bound proves it free of zeros
// (|f| at its ends is too large for f to reach zero in between) or it is narrower than min_width;
// a sign change in such a cell is bisected to round-off. So no zero that changes sign is missed
// unless another lies within min_width of it: for f = lambda', such a pair is a maximum and a
// minimum whose values differ by at most slope_bound min_width^2 / 4. Zeros within min_width of
// t0 or t1 are left to the caller, who checks the ends. Sorted.
std::vector<double> zeros_between(const std::function<double(double)>& f, double slope_bound,
                                  double t0, double t1, double cell, double min_width);

}  // namespace blockfrag::pulse
