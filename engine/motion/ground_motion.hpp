// The ground motion as smooth pieces: lambda(t) is smooth inside each piece and may jump (or kink)
// between pieces, so the integrator never steps across a piece boundary and each stage evaluates
// the formula of the piece it lies in (the left limit at the piece's end, not the next piece's).
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <vector>

#include "engine/motion/pulse_shapes.hpp"
#include "engine/scene/scene.hpp"
#include "engine/sine_cosine.hpp"

namespace blockfrag {

class MotionPiece {
 public:
  enum class Shape { zero, constant, linear, cosine, sine, ricker, mavroeidis_papageorgiou };

  // lambda(t) for one shape; unused parameters stay zero.
  struct Formula {
    Shape shape = Shape::zero;
    double amplitude = 0.0;          // the value (constant, linear at origin) or the peak
    double angular_frequency = 0.0;  // cosine, sine: A cos(omega t + phase)
    double phase = 0.0;
    double origin = 0.0;  // linear: lambda = A + slope (t - origin)
    double slope = 0.0;
    // ricker: A pulse::ricker(omega (t - origin)), omega = pi / Tp.
    // mavroeidis_papageorgiou: A pulse::mavroeidis_papageorgiou(omega (t - origin), modulation,
    // phase), omega = 2 pi / Tp, modulation = 1 / gamma.
    double modulation = 0.0;
  };

  // Valid from start (the previous piece's end, or 0) to end.
  MotionPiece(const Formula& formula, double start, double end)
      : f_(formula), start_(start), end_(end) {}

  const Formula& formula() const { return f_; }
  double start() const { return start_; }
  double end() const { return end_; }
  bool is_zero() const {
    return f_.shape == Shape::zero || (f_.amplitude == 0.0 && f_.slope == 0.0);
  }

  // The piece's formula, also at its end point (the left limit there), remembering the last time's
  // value: a Runge-Kutta step's last two stages, the guards at its end and the contact forces
  // there all ask for lambda at the same t, and remembering it saves 7% of the instructions of
  // the type A pulse on the flat ground, 3% on a flat seat. The time is compared bit for bit.
  // Whoever asks holds the piece non-const (a system's context holds MotionPiece*); the
  // simulation that owns the motion is its only user, so a piece is not to be shared between
  // threads.
  double lambda(double t) {
    const auto bits = std::bit_cast<std::uint64_t>(t);
    if (bits != remembered_bits_) {
      remembered_lambda_ = formula_value(t);
      remembered_bits_ = bits;
    }
    return remembered_lambda_;
  }
  // lambda(t) from the formula, for a const piece: the same value, without remembering it.
  double formula_value(double t) const {
    switch (f_.shape) {
      case Shape::zero: return 0.0;
      case Shape::constant: return f_.amplitude;
      case Shape::linear: return f_.amplitude + f_.slope * (t - f_.origin);
      case Shape::cosine: return f_.amplitude * cosine(f_.angular_frequency * t + f_.phase);
      case Shape::sine: return f_.amplitude * sine(f_.angular_frequency * t + f_.phase);
      case Shape::ricker:
        return f_.amplitude * pulse::ricker(f_.angular_frequency * (t - f_.origin));
      case Shape::mavroeidis_papageorgiou:
        return f_.amplitude * pulse::mavroeidis_papageorgiou(f_.angular_frequency * (t - f_.origin),
                                                             f_.modulation, f_.phase);
    }
    return 0.0;
  }

  // An upper bound of |lambda| over the piece.
  double max_abs_lambda() const;

  // How fast lambda changes: its period for oscillating pieces (the Ricker wavelet's Tp, the
  // fastest of the Mavroeidis-Papageorgiou pulse's three sines), unbounded for polynomial ones.
  double time_scale() const {
    const double omega = f_.angular_frequency;
    if (!(omega > 0)) return std::numeric_limits<double>::infinity();
    if (f_.shape == Shape::ricker) return std::numbers::pi / omega;
    if (f_.shape == Shape::mavroeidis_papageorgiou)
      return 2.0 * std::numbers::pi / (omega * (1.0 + f_.modulation));
    return 2.0 * std::numbers::pi / omega;
  }

  // Times in (t0, t1) where lambda has an extremum: checking a function of lambda alone there and
  // at the ends finds every excursion past a threshold.
  std::vector<double> extrema_between(double t0, double t1) const;

 private:
  Formula f_;
  double start_, end_;
  // lambda's last time and value; the bits of a NaN no time has, so the first call computes.
  std::uint64_t remembered_bits_ = 0x7ff8dead'beefcafeULL;
  double remembered_lambda_ = 0.0;
};

class GroundMotionPieces {
 public:
  // g converts the pulses given by a ground velocity in m/s (Mavroeidis-Papageorgiou) into lambda;
  // every other motion is given in g already.
  explicit GroundMotionPieces(const GroundMotion& motion, double g = 9.81);
  // lambda given at increasing times, linear in between, zero outside [times.front(),
  // times.back()]. A time given twice in a row is a jump: the first value ends one piece, the
  // second starts the next.
  GroundMotionPieces(const std::vector<double>& times, const std::vector<double>& lambdas);

  // The first piece with t < end. A simulation asks in time order, mostly for the piece it asked
  // for last: that one is looked at here, inline (every event asks), the others by search().
  // Remembering the piece found (last_) saves 4% of a type B block's run under a record (tens of
  // thousands of pieces to search) and makes asking non-const; the simulation that owns the
  // motion is its only user, so a motion is not to be shared between threads.
  MotionPiece& piece_at(double t) {
    if (t < pieces_[last_].end() && (last_ == 0 || !(t < pieces_[last_ - 1].end()))) {
      return pieces_[last_];
    }
    return search(t);
  }
  double lambda(double t) { return piece_at(t).lambda(t); }
  const std::vector<MotionPiece>& pieces() const { return pieces_; }
  // The largest |lambda| (the peak ground acceleration in g): at the pieces' ends and extrema.
  double peak_abs_lambda() const;
  // Where the motion ends: lambda is zero from here on (0 for no motion).
  double end_of_motion() const { return pieces_.back().start(); }

 private:
  void add(const MotionPiece::Formula& formula, double end);
  void add_tabulated(const std::vector<double>& times, const std::vector<double>& lambdas);
  void close();  // appends the zero piece that lasts forever
  // piece_at for a t past the piece it found last.
  MotionPiece& search(double t);

  std::vector<MotionPiece> pieces_;
  std::size_t last_ = 0;  // the piece piece_at found last: where it looks first
};

}  // namespace blockfrag
