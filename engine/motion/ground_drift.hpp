// The first and second integrals of a motion piece's lambda from a start time, in closed form for
// every shape: a block in free flight feels x'' = lambda g, so its horizontal drift needs no
// integrator (theta and y are closed form already, engine/modes/flight.hpp).
#pragma once

#include <array>

#include "engine/motion/ground_motion.hpp"

namespace blockfrag {

class GroundDrift {
 public:
  // Integrals from t0 inside the piece; t0 and the times asked for lie in [piece.start(),
  // piece.end()] (the piece's formula holds up to its end, as MotionPiece::lambda).
  GroundDrift(const MotionPiece& piece, double t0);

  struct Integrals {
    double first;   // integral of lambda from t0 to t (s)
    double second;  // integral of the first from t0 to t (s^2)
  };
  // One sine and cosine per sinusoid of the piece (three for the Mavroeidis-Papageorgiou pulse),
  // one exponential for the Ricker wavelet, none for polynomial pieces.
  Integrals at(double t) const;

 private:
  // c sin(m x + b0 - m x0) or its cosine, with x = omega t: one sinusoid of lambda, written from
  // the start angle b0 so that short intervals keep their relative precision.
  struct Sinusoid {
    double weight = 0.0;     // c
    double multiple = 1.0;   // m
    double sin_start = 0.0;  // sin(b0)
    double cos_start = 1.0;  // cos(b0)
    bool is_cosine = false;
  };

  MotionPiece::Shape shape_;
  double t0_;
  double omega_ = 0.0;
  double lambda0_ = 0.0;  // polynomial pieces: lambda(t0)
  double slope_ = 0.0;    // linear pieces: d lambda / dt
  // Ricker: lambda = A (1 - 2 v^2) exp(-v^2) with v = omega (t - origin).
  double amplitude_ = 0.0, origin_ = 0.0, v0_ = 0.0, exp0_ = 0.0;
  std::array<Sinusoid, 3> sinusoids_{};
  int sinusoid_count_ = 0;
};

}  // namespace blockfrag
