// The ground motion as smooth pieces: lambda(t) is smooth inside each piece and may jump between
// pieces, so the integrator never steps across a piece boundary and each stage evaluates the
// formula of the piece it lies in (the left limit at the piece's end, not the next piece's value).
#pragma once

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "engine/scene.hpp"

namespace blockfrag {

class MotionPiece {
 public:
  enum class Shape { zero, constant, cosine, sine };

  // Valid from the previous piece's end (or t = 0) to end.
  MotionPiece(Shape shape, double amplitude, double angular_frequency, double end)
      : shape_(shape), amplitude_(amplitude), omega_(angular_frequency), end_(end) {}

  double end() const { return end_; }
  bool is_zero() const { return shape_ == Shape::zero || amplitude_ == 0.0; }

  // The piece's formula, also at its end point (the left limit there).
  double lambda(double t) const {
    switch (shape_) {
      case Shape::zero: return 0.0;
      case Shape::constant: return amplitude_;
      case Shape::cosine: return amplitude_ * std::cos(omega_ * t);
      case Shape::sine: return amplitude_ * std::sin(omega_ * t);
    }
    return 0.0;
  }

  double max_abs_lambda() const { return is_zero() ? 0.0 : std::abs(amplitude_); }

  // How fast lambda changes: its period for oscillating pieces, unbounded for constant ones.
  double time_scale() const {
    return omega_ > 0 ? 2.0 * std::numbers::pi / omega_ : std::numeric_limits<double>::infinity();
  }

  // Times in (t0, t1) where lambda has an extremum: checking a function of lambda alone there and
  // at the ends finds every excursion past a threshold.
  std::vector<double> extrema_between(double t0, double t1) const;

 private:
  Shape shape_;
  double amplitude_, omega_, end_;
};

class GroundMotionPieces {
 public:
  explicit GroundMotionPieces(const GroundMotion& motion);

  const MotionPiece& piece_at(double t) const;  // the first piece with t < end
  double lambda(double t) const { return piece_at(t).lambda(t); }

 private:
  std::vector<MotionPiece> pieces_;  // the last one is zero and lasts forever
};

}  // namespace blockfrag
