#include "engine/motion/ground_drift.hpp"

#include <array>
#include <cmath>

#include "engine/sine_cosine.hpp"

namespace blockfrag {

namespace {

// For the advance e of a sinusoid's angle: sin e, 1 - cos e and e - sin e, each to its own
// relative precision (differences of nearly equal numbers would lose it for a short flight).
struct Advance {
  double sin, one_minus_cos, minus_sin;
};

Advance advance_of(double e) {
  const SineCosine turn = sine_cosine(e);
  const double s = turn.sin, c = turn.cos;
  Advance a{s, c > 0 ? s * s / (1.0 + c) : 1.0 - c, e - s};
  if (std::abs(e) < 1.0) {
    // e - sin e = e^3/3! - e^5/5! + ...: nine terms leave under 1e-19 of it for |e| < 1.
    // 1 / ((2n) (2n + 1)) for n = 2 to 10: a product per term instead of a division.
    constexpr std::array<double, 9> kInverse = {1.0 / 20,  1.0 / 42,  1.0 / 72,
                                                1.0 / 110, 1.0 / 156, 1.0 / 210,
                                                1.0 / 272, 1.0 / 342, 1.0 / 420};
    const double e2 = e * e;
    double series = 1.0;
    for (int n = 8; n >= 0; --n) series = 1.0 - e2 * kInverse[static_cast<std::size_t>(n)] * series;
    a.minus_sin = e * e2 / 6.0 * series;
  }
  return a;
}

}  // namespace

GroundDrift::GroundDrift(const MotionPiece& piece, double t0)
    : shape_(piece.is_zero() ? MotionPiece::Shape::zero : piece.formula().shape), t0_(t0) {
  using Shape = MotionPiece::Shape;
  const MotionPiece::Formula& f = piece.formula();
  omega_ = f.angular_frequency;
  const auto add = [&](double weight, double multiple, double angle, bool is_cosine) {
    if (weight == 0.0) return;
    const SineCosine start = sine_cosine(angle);
    sinusoids_[static_cast<std::size_t>(sinusoid_count_++)] = {weight, multiple, start.sin,
                                                               start.cos, is_cosine};
  };
  switch (shape_) {
    case Shape::zero: break;
    case Shape::constant: lambda0_ = f.amplitude; break;
    case Shape::linear:
      lambda0_ = f.amplitude + f.slope * (t0 - f.origin);
      slope_ = f.slope;
      break;
    case Shape::cosine:
    case Shape::sine: add(f.amplitude, 1.0, omega_ * t0 + f.phase, shape_ == Shape::cosine); break;
    case Shape::ricker:
      amplitude_ = f.amplitude;
      origin_ = f.origin;
      v0_ = omega_ * (t0 - f.origin);
      exp0_ = std::exp(-v0_ * v0_);
      break;
    case Shape::mavroeidis_papageorgiou: {
      // A [sin(x + nu) + (1 + k)/2 sin((1 + k) x + nu) + (1 - k)/2 sin((1 - k) x + nu)].
      const double k = f.modulation, x0 = omega_ * (t0 - f.origin);
      const std::array<std::array<double, 2>, 3> terms = {
          {{1.0, 1.0}, {0.5 * (1.0 + k), 1.0 + k}, {0.5 * (1.0 - k), 1.0 - k}}};
      for (const auto& [weight, m] : terms) add(f.amplitude * weight, m, m * x0 + f.phase, false);
      break;
    }
  }
}

GroundDrift::Integrals GroundDrift::at(double t) const {
  using Shape = MotionPiece::Shape;
  const double u = t - t0_;
  switch (shape_) {
    case Shape::zero: return {0.0, 0.0};
    case Shape::constant:
    case Shape::linear:
      return {u * (lambda0_ + 0.5 * slope_ * u), u * u * (0.5 * lambda0_ + slope_ * u / 6.0)};
    case Shape::ricker: {
      // v e - v0 e0 and e0 - e written with e - e0 = e0 expm1(-(v^2 - v0^2)), v^2 - v0^2 =
      // delta (v + v0): no difference of nearly equal numbers for a short flight.
      const double v = omega_ * (t - origin_), e = std::exp(-v * v), delta = omega_ * u;
      // A flight that starts far before the wavelet's centre (v0 < -26) has e0 below the smallest
      // double and e far above it: there e - e0 is e, and expm1 of the exponent would overflow.
      constexpr double kLargestExpm1Argument = 700.0;  // exp(700) is about 1e304
      const double exponent = -delta * (v + v0_);
      const double change =
          exponent < kLargestExpm1Argument ? exp0_ * std::expm1(exponent) : e - exp0_;  // e - e0
      const double scale = amplitude_ / omega_;
      return {scale * (delta * e + v0_ * change),
              scale / omega_ * (-0.5 * change - delta * v0_ * exp0_)};
    }
    case Shape::cosine:
    case Shape::sine:
    case Shape::mavroeidis_papageorgiou: break;
  }
  // A sinusoid of angle b = b0 + e, e = m omega u:
  //   sin b: first (cos b0 (1 - cos e) + sin b0 sin e) / (m omega),
  //          second (cos b0 (e - sin e) + sin b0 (1 - cos e)) / (m omega)^2;
  //   cos b: first (cos b0 sin e - sin b0 (1 - cos e)) / (m omega),
  //          second (cos b0 (1 - cos e) - sin b0 (e - sin e)) / (m omega)^2.
  Integrals sum{0.0, 0.0};
  for (int i = 0; i < sinusoid_count_; ++i) {
    const Sinusoid& s = sinusoids_[static_cast<std::size_t>(i)];
    const double rate = s.multiple * omega_;
    const Advance a = advance_of(rate * u);
    const double first = s.is_cosine ? s.cos_start * a.sin - s.sin_start * a.one_minus_cos
                                     : s.cos_start * a.one_minus_cos + s.sin_start * a.sin;
    const double second = s.is_cosine ? s.cos_start * a.one_minus_cos - s.sin_start * a.minus_sin
                                      : s.cos_start * a.minus_sin + s.sin_start * a.one_minus_cos;
    sum.first += s.weight / rate * first;
    sum.second += s.weight / (rate * rate) * second;
  }
  return sum;
}

}  // namespace blockfrag
