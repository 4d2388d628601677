#include "engine/motion/ground_motion.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <type_traits>

#include "engine/tolerances.hpp"

namespace blockfrag {

namespace {

// Ricker: the wavelet's slope 2 u (2 u^2 - 3) exp(-u^2) vanishes at u = 0, +-sqrt(3/2).
std::vector<double> ricker_extrema(const MotionPiece::Formula& f, double t0, double t1) {
  std::vector<double> times;
  for (const double u : {-std::sqrt(1.5), 0.0, std::sqrt(1.5)}) {
    const double t = f.origin + u / f.angular_frequency;
    if (t > t0 && t < t1) times.push_back(t);
  }
  return times;
}

// Mavroeidis-Papageorgiou: no closed form for the zeros of a sum of three cosines, so search for
// them with the bound on the slope's own derivative, which proves the cells it skips empty. A
// maximum and minimum closer than min_width differ by less than kNegligibleExtremumPair of the
// pulse's scale (far below the rest mode's onset margin): such a pair can be skipped.
std::vector<double> mavroeidis_papageorgiou_extrema(const MotionPiece::Formula& f, double t0,
                                                    double t1) {
  const double omega = f.angular_frequency, k = f.modulation;
  // In units of A: slope omega s(x) with x = omega (t - origin), |d/dt| of that <= omega^2 bound.
  const double bound = omega * omega * pulse::mavroeidis_papageorgiou_curvature_bound(k);
  const auto slope = [&](double t) {
    return omega * pulse::mavroeidis_papageorgiou_slope(omega * (t - f.origin), k, f.phase);
  };
  const double fastest_period = 2.0 * std::numbers::pi / (omega * (1.0 + k));
  const double min_width = 2.0 * std::sqrt(kNegligibleExtremumPair / bound);
  return pulse::zeros_between(slope, bound, t0, t1, fastest_period / kExtremumCellsPerPeriod,
                              min_width);
}

}  // namespace

double MotionPiece::max_abs_lambda() const {
  if (is_zero()) return 0.0;
  if (f_.shape == Shape::linear)
    return std::max(std::abs(formula_value(start_)), std::abs(formula_value(end_)));
  // Mavroeidis-Papageorgiou: three sines of amplitudes 1, (1 + k)/2, (1 - k)/2 add to at most 2.
  if (f_.shape == Shape::mavroeidis_papageorgiou) return 2.0 * std::abs(f_.amplitude);
  return std::abs(f_.amplitude);  // the Ricker wavelet's peak is at its centre
}

std::vector<double> MotionPiece::extrema_between(double t0, double t1) const {
  if (is_zero()) return {};
  if (f_.shape == Shape::ricker) return ricker_extrema(f_, t0, t1);
  if (f_.shape == Shape::mavroeidis_papageorgiou)
    return mavroeidis_papageorgiou_extrema(f_, t0, t1);
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

GroundMotionPieces::GroundMotionPieces(const GroundMotion& motion, double g) {
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
        } else if constexpr (std::is_same_v<M, MakrisPulseA> || std::is_same_v<M, MakrisPulseB>) {
          add({.shape = std::is_same_v<M, MakrisPulseB> ? Shape::cosine : Shape::sine,
               .amplitude = m.amplitude_g,
               .angular_frequency = 2.0 * std::numbers::pi / m.period},
              m.period);
        } else if constexpr (std::is_same_v<M, MakrisPulseC>) {
          const double phi = pulse::makris_c_phase(m.n);
          add({.shape = Shape::cosine,
               .amplitude = m.amplitude_g,
               .angular_frequency = 2.0 * std::numbers::pi / m.period,
               .phase = phi},
              (m.n + 0.5 - phi / std::numbers::pi) * m.period);
        } else if constexpr (std::is_same_v<M, RickerWavelet>) {
          add({.shape = Shape::ricker,
               .amplitude = m.amplitude_g,
               .angular_frequency = std::numbers::pi / m.period,
               .origin = m.center()},
              2.0 * m.center());
        } else if constexpr (std::is_same_v<M, MavroeidisPapageorgiouPulse>) {
          const double omega = 2.0 * std::numbers::pi / m.period;
          const double start = m.center() - m.half_width();
          if (start > 0.0) add({}, start);
          add({.shape = Shape::mavroeidis_papageorgiou,
               .amplitude = m.velocity_amplitude * omega / (2.0 * g),
               .angular_frequency = omega,
               .phase = m.phase,
               .origin = m.center(),
               .modulation = 1.0 / m.gamma},
              m.center() + m.half_width());
        } else if constexpr (std::is_same_v<M, RecordedMotion>) {
          std::vector<double> lambdas;  // the record is the ground's acceleration, -lambda g
          lambdas.reserve(m.record->acceleration_g.size());
          for (const double a : m.record->acceleration_g) lambdas.push_back(-m.scale * a);
          add_tabulated(m.record->times, lambdas);
        }
      },
      motion);
  close();
}

GroundMotionPieces::GroundMotionPieces(const std::vector<double>& times,
                                       const std::vector<double>& lambdas) {
  add_tabulated(times, lambdas);
  close();
}

void GroundMotionPieces::add_tabulated(const std::vector<double>& times,
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
}

void GroundMotionPieces::add(const MotionPiece::Formula& formula, double end) {
  const double start = pieces_.empty() ? 0.0 : pieces_.back().end();
  pieces_.emplace_back(formula, start, end);
}

void GroundMotionPieces::close() { add({}, std::numeric_limits<double>::infinity()); }

double GroundMotionPieces::peak_abs_lambda() const {
  double peak = 0.0;
  for (const MotionPiece& piece : pieces_) {
    if (piece.is_zero()) continue;
    std::vector<double> times = piece.extrema_between(piece.start(), piece.end());
    times.push_back(piece.start());
    times.push_back(piece.end());
    for (const double t : times) peak = std::max(peak, std::abs(piece.formula_value(t)));
  }
  return peak;
}

MotionPiece& GroundMotionPieces::search(double t) {
  // Next after the last piece, the one a simulation moves on to; then a search (a record has tens
  // of thousands of pieces).
  const auto holds = [&](std::size_t k) {
    return t < pieces_[k].end() && (k == 0 || !(t < pieces_[k - 1].end()));
  };
  if (last_ + 1 < pieces_.size() && holds(last_ + 1)) return pieces_[++last_];
  const auto it =
      std::upper_bound(pieces_.begin(), pieces_.end(), t,
                       [](double x, const MotionPiece& piece) { return x < piece.end(); });
  last_ = it == pieces_.end() ? pieces_.size() - 1 : static_cast<std::size_t>(it - pieces_.begin());
  return pieces_[last_];
}

}  // namespace blockfrag
