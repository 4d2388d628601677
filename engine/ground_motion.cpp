#include "engine/ground_motion.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <type_traits>

namespace blockfrag {

std::vector<double> MotionPiece::extrema_between(double t0, double t1) const {
  std::vector<double> times;
  if (shape_ != Shape::cosine && shape_ != Shape::sine) return times;
  // cos extrema at omega t = k pi, sin extrema at omega t = (k + 1/2) pi.
  const double offset = shape_ == Shape::sine ? 0.5 : 0.0;
  const double half_period = std::numbers::pi / omega_;
  for (double k = std::ceil(t0 / half_period - offset); ; k += 1.0) {
    const double t = (k + offset) * half_period;
    if (t >= t1) break;
    if (t > t0) times.push_back(t);
  }
  return times;
}

GroundMotionPieces::GroundMotionPieces(const GroundMotion& motion) {
  constexpr double kForever = std::numeric_limits<double>::infinity();
  std::visit(
      [&](const auto& m) {
        using M = std::decay_t<decltype(m)>;
        if constexpr (std::is_same_v<M, RectangularPulse>) {
          pieces_.emplace_back(MotionPiece::Shape::constant, m.amplitude_g, 0.0, m.duration);
        } else if constexpr (!std::is_same_v<M, NoMotion>) {
          const auto shape = std::is_same_v<M, CosinePulse> ? MotionPiece::Shape::cosine
                                                            : MotionPiece::Shape::sine;
          const double end = m.cycles * m.period;
          pieces_.emplace_back(shape, m.amplitude_g, 2.0 * std::numbers::pi / m.period, end);
        }
      },
      motion);
  pieces_.emplace_back(MotionPiece::Shape::zero, 0.0, 0.0, kForever);
}

const MotionPiece& GroundMotionPieces::piece_at(double t) const {
  for (const MotionPiece& piece : pieces_) {
    if (t < piece.end()) return piece;
  }
  return pieces_.back();
}

}  // namespace blockfrag
