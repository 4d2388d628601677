// sin and cos of one angle together, inline and without touching the rounding mode: the block's
// rotation and a sinusoidal pulse are evaluated at every stage, guard sample and located event,
// and the C library's sincos and cos (which save and restore the floating-point environment
// around every call) took 29 % of the paper grid's time. Within 1.5 ulp of the true values (or
// 1e-21 absolute near a zero of sin or cos away from 0); not bit for bit the C library's.
#pragma once

#include <cmath>

namespace blockfrag {

struct SineCosine {
  double sin, cos;
};

namespace sine_cosine_detail {

// sin and cos on [-pi/4, pi/4]: the minimax polynomials of FreeBSD's k_sin.c and k_cos.c (Sun's
// fdlibm), within 2^-58 of the functions there.
inline double kernel_sin(double x) {
  constexpr double kS1 = -1.66666666666666324348e-01, kS2 = 8.33333333332248946124e-03,
                   kS3 = -1.98412698298579493134e-04, kS4 = 2.75573137070700676789e-06,
                   kS5 = -2.50507602534068634195e-08, kS6 = 1.58969099521155010221e-10;
  const double z = x * x, w = z * z;
  const double r = kS2 + z * (kS3 + z * kS4) + z * w * (kS5 + z * kS6);
  return x + z * x * (kS1 + z * r);
}

inline double kernel_cos(double x) {
  constexpr double kC1 = 4.16666666666666019037e-02, kC2 = -1.38888888888741095749e-03,
                   kC3 = 2.48015872894767294178e-05, kC4 = -2.75573143513906633035e-07,
                   kC5 = 2.08757232129817482790e-09, kC6 = -1.13596475577881948265e-11;
  const double z = x * x, w = z * z;
  const double r = z * (kC1 + z * (kC2 + z * kC3)) + w * w * (kC4 + z * (kC5 + z * kC6));
  // 1 - z/2 rounded, and what that rounding lost, added back with the rest.
  const double half_z = 0.5 * z, v = 1.0 - half_z;
  return v + (((1.0 - v) - half_z) + z * r);
}

// x = n pi/2 + y with |y| <= pi/4, for pi/4 < |x| < 1e5. Adding and subtracting 1.5 * 2^52
// rounds to the nearest integer (std::nearbyint is a library call without SSE4.1). pi/2's head has
// 33 bits, so n times it is exact for |n| < 2^20; its tail leaves y within 1e-21 of the exact
// reduction. quadrant is n mod 4.
struct Reduced {
  int quadrant;
  double y;
};

inline Reduced reduce(double x) {
  constexpr double kTwoOverPi = 6.36619772367581382433e-01;
  constexpr double kRound = 6755399441055744.0;
  constexpr double kHalfPiHead = 1.57079632673412561417e+00;
  constexpr double kHalfPiTail = 6.07710050650619224932e-11;
  const double n = (x * kTwoOverPi + kRound) - kRound;
  return {static_cast<int>(n) & 3, (x - n * kHalfPiHead) - n * kHalfPiTail};
}

constexpr double kQuarterPi = 0.785398163397448279;
// Below 2^-27, sin x rounds to x and cos x to 1 (and -0 keeps its sign, which the polynomial's
// x + 0 would not).
constexpr double kTiny = 0x1p-27;
// Beyond this the two-part reduction loses precision; the C library reduces exactly.
constexpr double kLargest = 1e5;

}  // namespace sine_cosine_detail

inline SineCosine sine_cosine(double x) {
  using namespace sine_cosine_detail;
  if (std::abs(x) < kTiny) return {x, 1.0};
  if (std::abs(x) <= kQuarterPi) return {kernel_sin(x), kernel_cos(x)};  // a block's tilt
  if (!(std::abs(x) < kLargest)) return {std::sin(x), std::cos(x)};      // also NaN and infinities
  const Reduced r = reduce(x);
  const double s = kernel_sin(r.y), c = kernel_cos(r.y);
  switch (r.quadrant) {
    case 0: return {s, c};
    case 1: return {c, -s};
    case 2: return {-s, -c};
    default: return {-c, s};
  }
}

// sine_cosine(x).cos and .sin to the bit, each alone: a sinusoidal pulse's lambda needs only one,
// and each quadrant only one of the two kernels.
inline double cosine(double x) {
  using namespace sine_cosine_detail;
  if (std::abs(x) < kTiny) return 1.0;
  if (std::abs(x) <= kQuarterPi) return kernel_cos(x);
  if (!(std::abs(x) < kLargest)) return std::cos(x);
  const Reduced r = reduce(x);
  switch (r.quadrant) {
    case 0: return kernel_cos(r.y);
    case 1: return -kernel_sin(r.y);
    case 2: return -kernel_cos(r.y);
    default: return kernel_sin(r.y);
  }
}

inline double sine(double x) {
  using namespace sine_cosine_detail;
  if (std::abs(x) < kTiny) return x;
  if (std::abs(x) <= kQuarterPi) return kernel_sin(x);
  if (!(std::abs(x) < kLargest)) return std::sin(x);
  const Reduced r = reduce(x);
  switch (r.quadrant) {
    case 0: return kernel_sin(r.y);
    case 1: return kernel_cos(r.y);
    case 2: return -kernel_sin(r.y);
    default: return -kernel_cos(r.y);
  }
}

}  // namespace blockfrag
