#include "engine/ground_motion.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <type_traits>

namespace blockfrag {

double MotionPiece::max_abs_lambda() const {
  if (is_zero()) return 0.0;
  if (f_.shape == Shape::linear) return std::max(std::abs(lambda(start_)), std::abs(lambda(end_)));
  return std::abs(f_.amplitude);
}

std::vector<double> MotionPiece::extrema_between(double t0, double t1) const {
  std::vector<double> times;
  if (f_.shape != Shape::cosine && f_.shape != Shape::sine) return times;
  // cos(omega t + phase) has extrema at omega t + phase = k pi, sin at (k + 1/2) pi.
  const double offset = (f_.shape == Shape::sine ? 0.5 : 0.0) - f_.phase / std::numbers::pi;
  const double half_period = std::numbers::pi / f_.angular_frequency;
  for (double k = std::ceil(t0 / half_period - offset);; k += 1.0) {
    const double t = (k + offset) * half_period;
    if (t >= t1) break;
    if (t > t0) times.push_back(t);
  }
  return times;
}

GroundMotionPieces::GroundMotionPieces(const GroundMotion& motion) {
  using Shape = MotionPiece::Shape;
  std::visit(
      [&](const auto& m) {
        using M = std::decay_t<decltype(m)>;
        if constexpr (std::is_same_v<M, RectangularPulse>) {
          add({.shape = Shape::constant, .amplitude = m.amplitude_g}, m.duration);
        } else if constexpr (std::is_same_v<M, CosinePulse> || std::is_same_v<M, SinePulse>) {
          add({.shape = std::is_same_v<M, CosinePulse> ? Shape::cosine : Shape::sine,
               .amplitude = m.amplitude_g,
               .angular_frequency = 2.0 * std::numbers::pi / m.period},
              m.cycles * m.period);
        }
      },
      motion);
  close();
}

GroundMotionPieces::GroundMotionPieces(const std::vector<double>& times,
                                       const std::vector<double>& lambdas) {
  if (!times.empty() && times.front() > 0) add({}, times.front());
  for (std::size_t i = 0; i + 1 < times.size(); ++i) {
    if (times[i + 1] == times[i]) continue;  // a repeated time: lambda jumps there
    const double slope = (lambdas[i + 1] - lambdas[i]) / (times[i + 1] - times[i]);
    add({.shape = MotionPiece::Shape::linear,
         .amplitude = lambdas[i],
         .origin = times[i],
         .slope = slope},
        times[i + 1]);
  }
  close();
}

void GroundMotionPieces::add(const MotionPiece::Formula& formula, double end) {
  const double start = pieces_.empty() ? 0.0 : pieces_.back().end();
  pieces_.emplace_back(formula, start, end);
}

void GroundMotionPieces::close() { add({}, std::numeric_limits<double>::infinity()); }

const MotionPiece& GroundMotionPieces::piece_at(double t) const {
  const auto it = std::upper_bound(pieces_.begin(), pieces_.end(), t,
                                   [](double x, const MotionPiece& piece) { return x < piece.end(); });
  return it == pieces_.end() ? pieces_.back() : *it;
}

}  // namespace blockfrag
