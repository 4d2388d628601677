#include "engine/motion/pulse_shapes.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "engine/errors.hpp"
#include "engine/tolerances.hpp"

namespace blockfrag::pulse {

// With w = omega_p and T the pulse's end, w T + phi = (2n + 1) pi - phi, so
//   velocity     integral_0^T cos(w s + phi) ds = [sin(w T + phi) - sin(phi)] / w = 0 for every
//   phi, displacement integral_0^T [sin(w s + phi) - sin(phi)] / w ds
//              = [cos(phi) - cos(w T + phi)] / w^2 - T sin(phi) / w
//              = [2 cos(phi) - ((2n + 1) pi - 2 phi) sin(phi)] / w^2.
// The bracket is 2 at phi = 0, -2 n pi at pi/2, and its derivative -((2n + 1) pi - 2 phi) cos(phi)
// is negative in between: one root.
double makris_c_phase(int n) {
  if (n < 1) throw ContractViolation("Makris type C_n needs n >= 1");
  const double odd_pi = (2.0 * n + 1.0) * std::numbers::pi;
  const auto residual = [&](double phi) {
    return 2.0 * std::cos(phi) - (odd_pi - 2.0 * phi) * std::sin(phi);
  };
  double low = 0.0, high = std::numbers::pi / 2;  // residual(low) > 0 > residual(high)
  while (true) {
    const double mid = 0.5 * (low + high);
    if (mid <= low || mid >= high) break;  // adjacent doubles
    (residual(mid) > 0.0 ? low : high) = mid;
  }
  return std::abs(residual(low)) < std::abs(residual(high)) ? low : high;
}

namespace {

struct ZeroSearch {
  const std::function<double(double)>& f;
  double slope_bound;
  double
      slack;  // the round-off in |f(a)| + |f(b)|: a bound that is attained must not prove too much
  double min_width;
  std::vector<double>& zeros;

  // A zero z in [a, b] needs |f(a)| <= bound (z - a) and |f(b)| <= bound (b - z).
  void cell(double a, double fa, double b, double fb) const {
    if (std::abs(fa) + std::abs(fb) > kSlopeBoundFactor * slope_bound * (b - a) + slack) return;
    const bool crosses = (fa > 0.0) != (fb > 0.0);
    if (b - a <= min_width) {
      if (crosses) zeros.push_back(bisect(a, fa, b));
      return;
    }
    const double mid = 0.5 * (a + b);
    const double fm = f(mid);
    cell(a, fa, mid, fm);
    cell(mid, fm, b, fb);
  }

  double bisect(double a, double fa, double b) const {
    while (true) {
      const double mid = 0.5 * (a + b);
      if (mid <= a || mid >= b) return mid;
      const double fm = f(mid);
      if ((fm > 0.0) == (fa > 0.0)) {
        a = mid;
        fa = fm;
      } else {
        b = mid;
      }
    }
  }
};

}  // namespace

std::vector<double> zeros_between(const std::function<double(double)>& f, double slope_bound,
                                  double t0, double t1, double cell, double min_width) {
  std::vector<double> zeros;
  if (!(t1 > t0)) return zeros;
  const double cells = std::max(1.0, std::ceil((t1 - t0) / cell));
  const ZeroSearch search{f, slope_bound, kSlopeZeroTolerance * slope_bound * cell, min_width,
                          zeros};
  double a = t0, fa = f(t0);
  for (double k = 1.0; k <= cells; k += 1.0) {
    const double b = k == cells ? t1 : t0 + (t1 - t0) * (k / cells);
    const double fb = f(b);
    search.cell(a, fa, b, fb);
    a = b;
    fa = fb;
  }
  // The ends are not interior: a zero within min_width of one is the caller's end (which it
  // checks).
  std::erase_if(zeros, [&](double t) { return t <= t0 + min_width || t >= t1 - min_width; });
  return zeros;
}

}  // namespace blockfrag::pulse
