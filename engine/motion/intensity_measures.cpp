#include "engine/motion/intensity_measures.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <numbers>
#include <string>

#include "engine/errors.hpp"
#include "engine/motion/dam_crest.hpp"
#include "engine/motion/pulse_shapes.hpp"
#include "engine/number_text.hpp"
#include "engine/tolerances.hpp"

namespace blockfrag {

namespace {

using Shape = MotionPiece::Shape;
constexpr double pi = std::numbers::pi;

// sin(d x) / d, which tends to x as d does (a Mavroeidis-Papageorgiou pulse's products of sines
// of nearly equal frequencies).
double sin_over(double d, double x) { return d == 0.0 ? x : std::sin(d * x) / d; }

// An antiderivative in x of a Mavroeidis-Papageorgiou pulse's lambda^2 over its amplitude^2.
// lambda over its amplitude is sum_i c_i sin(w_i x + nu) with (w_i) = (1, 1 + k, 1 - k) and
// (c_i) = (1, (1 + k)/2, (1 - k)/2), all w_i > 0 as gamma > 1 (k = 1 / gamma < 1); sin^2 =
// (1 - cos 2y) / 2 integrates the squares, 2 sin p sin q = cos(p - q) - cos(p + q) the products.
double mavroeidis_papageorgiou_square_integral(double x, double k, double nu) {
  const std::array<double, 3> w{1.0, 1.0 + k, 1.0 - k}, c{1.0, 0.5 * (1.0 + k), 0.5 * (1.0 - k)};
  double sum = 0.0;
  for (std::size_t i = 0; i < 3; ++i) {
    sum += c[i] * c[i] * (0.5 * x - std::sin(2.0 * (w[i] * x + nu)) / (4.0 * w[i]));
    for (std::size_t j = i + 1; j < 3; ++j) {
      sum += c[i] * c[j] *
             (sin_over(w[i] - w[j], x) - std::sin((w[i] + w[j]) * x + 2.0 * nu) / (w[i] + w[j]));
    }
  }
  return sum;
}

// An antiderivative in u of the Ricker wavelet squared, (1 - 2u^2)^2 exp(-2u^2). By parts, with
// J_n the integral of u^n exp(-2u^2): J0 = sqrt(pi/8) erf(sqrt(2) u), J2 = -u exp(-2u^2)/4 +
// J0/4, J4 = -u^3 exp(-2u^2)/4 + 3/4 J2; so J0 - 4 J2 + 4 J4 = 3/4 J0 + (u/4 - u^3) exp(-2u^2).
double ricker_square_integral(double u) {
  return 0.75 * std::sqrt(pi / 8.0) * std::erf(std::numbers::sqrt2 * u) +
         (0.25 * u - u * u * u) * std::exp(-2.0 * u * u);
}

// The integral of lambda from the piece's start to t (t in the piece).
double lambda_integral(const MotionPiece& piece, double t) {
  const MotionPiece::Formula& f = piece.formula();
  const double start = piece.start(), w = f.angular_frequency;
  switch (f.shape) {
    case Shape::zero: return 0.0;
    case Shape::constant: return f.amplitude * (t - start);
    case Shape::linear: {
      const double tau = t - start;
      return tau * (piece.formula_value(start) + 0.5 * f.slope * tau);
    }
    case Shape::cosine:
      return f.amplitude / w * (std::sin(w * t + f.phase) - std::sin(w * start + f.phase));
    case Shape::sine:
      return f.amplitude / w * (std::cos(w * start + f.phase) - std::cos(w * t + f.phase));
    case Shape::ricker: {
      // d/du of u exp(-u^2) is (1 - 2u^2) exp(-u^2).
      const auto antiderivative = [&](double x) {
        const double u = w * (x - f.origin);
        return u * std::exp(-u * u);
      };
      return f.amplitude / w * (antiderivative(t) - antiderivative(start));
    }
    case Shape::mavroeidis_papageorgiou: {
      // pulse_shapes.hpp: the shape is the x-derivative of -[1 + cos(k x)] cos(x + nu).
      const auto antiderivative = [&](double x) {
        const double y = w * (x - f.origin);
        return -(1.0 + std::cos(f.modulation * y)) * std::cos(y + f.phase);
      };
      return f.amplitude / w * (antiderivative(t) - antiderivative(start));
    }
  }
  return 0.0;
}

// The integral of lambda^2 from the piece's start to t (t in the piece).
double lambda_square_integral(const MotionPiece& piece, double t) {
  const MotionPiece::Formula& f = piece.formula();
  const double start = piece.start(), w = f.angular_frequency, a2 = f.amplitude * f.amplitude;
  switch (f.shape) {
    case Shape::zero: return 0.0;
    case Shape::constant: return a2 * (t - start);
    case Shape::linear: {
      // (l0 + s tau)^2 integrates to l0^2 tau + l0 s tau^2 + s^2 tau^3 / 3.
      const double tau = t - start, l0 = piece.formula_value(start), s = f.slope;
      return tau * (l0 * l0 + tau * s * (l0 + s * tau / 3.0));
    }
    case Shape::cosine:
    case Shape::sine: {
      // cos^2 = (1 + cos 2y) / 2, sin^2 = (1 - cos 2y) / 2.
      const double sign = f.shape == Shape::cosine ? 1.0 : -1.0;
      const double oscillation =
          std::sin(2.0 * (w * t + f.phase)) - std::sin(2.0 * (w * start + f.phase));
      return a2 * (0.5 * (t - start) + sign * oscillation / (4.0 * w));
    }
    case Shape::ricker:
      return a2 / w *
             (ricker_square_integral(w * (t - f.origin)) -
              ricker_square_integral(w * (start - f.origin)));
    case Shape::mavroeidis_papageorgiou:
      return a2 / w *
             (mavroeidis_papageorgiou_square_integral(w * (t - f.origin), f.modulation, f.phase) -
              mavroeidis_papageorgiou_square_integral(w * (start - f.origin), f.modulation,
                                                      f.phase));
  }
  return 0.0;
}

// Where lambda changes sign inside the piece: the ground velocity's extremes.
std::vector<double> lambda_sign_changes(const MotionPiece& piece) {
  const MotionPiece::Formula& f = piece.formula();
  const double t0 = piece.start(), t1 = piece.end(), w = f.angular_frequency;
  std::vector<double> times;
  const auto keep = [&](double t) {
    if (t > t0 && t < t1) times.push_back(t);
  };
  switch (f.shape) {
    case Shape::zero:
    case Shape::constant: break;
    case Shape::linear:
      if (f.slope != 0.0) keep(t0 - piece.formula_value(t0) / f.slope);
      break;
    case Shape::cosine:
    case Shape::sine: {
      // sin y = 0 at y = n pi, cos y = 0 at y = n pi + pi/2, y = w t + phase.
      const double shift = (f.shape == Shape::cosine ? 0.5 * pi : 0.0) - f.phase;
      for (double n = std::ceil((w * t0 - shift) / pi);; n += 1.0) {
        const double t = (n * pi + shift) / w;
        if (t >= t1) break;
        keep(t);
      }
      break;
    }
    case Shape::ricker:  // 1 - 2u^2 = 0
      keep(f.origin - std::numbers::sqrt2 / 2.0 / w);
      keep(f.origin + std::numbers::sqrt2 / 2.0 / w);
      break;
    case Shape::mavroeidis_papageorgiou: {
      const double k = f.modulation;
      const auto shape = [&](double t) {
        return pulse::mavroeidis_papageorgiou(w * (t - f.origin), k, f.phase);
      };
      // The shape's slope in t is at most w (2 + k^2), the three sines' weights times their
      // frequencies. Between two sign changes closer than min_width the shape integrates to at
      // most slope_bound min_width^2 / 4 (s): kNegligibleVelocityPair of its scale, 1 / w.
      const double slope_bound = w * (2.0 + k * k);
      const double min_width = 2.0 * std::sqrt(kNegligibleVelocityPair / (w * slope_bound));
      times = pulse::zeros_between(shape, slope_bound, t0, t1,
                                   piece.time_scale() / kExtremumCellsPerPeriod, min_width);
      break;
    }
  }
  return times;
}

// The pieces that carry the motion: every one but the zero ones (the last lasts forever).
template <class Visit>
void for_each_moving_piece(const GroundMotionPieces& motion, Visit&& visit) {
  for (const MotionPiece& piece : motion.pieces()) {
    if (!piece.is_zero() && piece.end() > piece.start()) visit(piece);
  }
}

// The first t in the piece where the Arias integral from its start reaches `needed`, which is at
// most the piece's whole integral: it grows with t, so bisection keeps the first crossing.
double arias_crossing(const MotionPiece& piece, double needed) {
  double low = piece.start(), high = piece.end();
  const double width = kDurationCrossingTolerance * (high - low);
  while (high - low > width) {
    const double mid = 0.5 * (low + high);
    if (mid <= low || mid >= high) break;  // adjacent doubles
    (lambda_square_integral(piece, mid) >= needed ? high : low) = mid;
  }
  return high;
}

// |u| at the free oscillator's first extremum after its state s (a = 0): u' is e^(-zeta omega t)
// [v cos(wd t) - omega (zeta v + omega u) / wd sin(wd t)], zero where tan(wd t) = v wd / (omega
// (zeta v + omega u)); the first such wd t in (0, pi].
double first_free_extremum(double omega, double zeta, const OscillatorState& s) {
  const double wd = omega * std::sqrt(1.0 - zeta * zeta);
  double phase = std::atan2(s.v * wd, omega * (zeta * s.v + omega * s.q));
  if (phase <= 0.0) phase += pi;
  return std::abs(NigamJenningsStep(omega, zeta, phase / wd)(s, 0.0, 0.0).q);
}

void require_measure_in(const Domain& domain, double value, const char* name) {
  if (!domain.contains(value)) {
    throw InvalidInput(std::string("invalid intensity measure: ") + name + " " + domain.rule() +
                       " (got " + format_number(value) + ")");
  }
}

}  // namespace

double peak_ground_acceleration_g(const GroundMotionPieces& motion) {
  return motion.peak_abs_lambda();
}

double peak_ground_velocity(const GroundMotionPieces& motion, double g) {
  require_measure_in(domain::g, g, "g");
  double area = 0.0, peak = 0.0;  // area: the integral of lambda from 0 to the piece's start
  for_each_moving_piece(motion, [&](const MotionPiece& piece) {
    for (const double t : lambda_sign_changes(piece)) {
      peak = std::max(peak, std::abs(area + lambda_integral(piece, t)));
    }
    area += lambda_integral(piece, piece.end());
    peak = std::max(peak, std::abs(area));
  });
  return g * peak;
}

double significant_duration(const GroundMotionPieces& motion) {
  double total = 0.0;
  for_each_moving_piece(motion, [&](const MotionPiece& piece) {
    total += lambda_square_integral(piece, piece.end());
  });
  if (!(total > 0.0)) return 0.0;
  const auto crossing = [&](double fraction) {
    const double target = fraction * total;
    double before = 0.0, time = motion.end_of_motion();
    bool found = false;
    for_each_moving_piece(motion, [&](const MotionPiece& piece) {
      if (found) return;
      const double whole = lambda_square_integral(piece, piece.end());
      if (before + whole >= target) {
        time = arias_crossing(piece, target - before);
        found = true;
      }
      before += whole;
    });
    return time;
  };
  return crossing(0.95) - crossing(0.05);
}

std::vector<double> step_extrema(double omega, double zeta, double h, double a0, double a1,
                                 const OscillatorState& start, const OscillatorState& end) {
  const auto a = [&](double tau) { return a0 + (a1 - a0) * (tau / h); };
  // The exact state inside the step: a Nigam-Jennings step of the part up to tau.
  const auto at = [&](double tau) {
    return NigamJenningsStep(omega, zeta, tau)(start, a0, a(tau));
  };
  const auto acceleration = [&](double tau, const OscillatorState& s) {
    return -a(tau) - 2.0 * zeta * omega * s.v - omega * omega * s.q;
  };
  // The zero of f in (low, high), where f changes sign, by bisection. The sign at low is given:
  // at tau = 0 the step would have length 0, which Nigam-Jennings cannot take.
  const auto zero_of = [&](auto&& f, double low, double high, bool low_positive) {
    while (high - low > kSpectrumExtremumTimeTolerance * h) {
      const double mid = 0.5 * (low + high);
      if (mid <= low || mid >= high) break;
      ((f(mid) > 0.0) == low_positive ? low : high) = mid;
    }
    return 0.5 * (low + high);
  };
  const auto opposite = [](double x, double y) {
    return (x > 0.0 && y < 0.0) || (x < 0.0 && y > 0.0);
  };
  const auto rate = [&](double tau) { return at(tau).v; };
  std::vector<double> times;
  // u' monotone from low to high: one zero where its sign changes, none otherwise.
  const auto monotone = [&](double low, double v_low, double high, double v_high) {
    if (opposite(v_low, v_high)) times.push_back(zero_of(rate, low, high, v_low > 0.0));
  };
  const double c0 = acceleration(0.0, start), c1 = acceleration(h, end);
  if (!opposite(c0, c1)) {
    monotone(0.0, start.v, h, end.v);
    return times;
  }
  // u' turns once inside, where u'' = 0. Leaving a strict sign away from zero, it turns farther
  // from zero and keeps its sign up to an end of the same sign: no zero.
  if (opposite(start.v, -c0) && !opposite(start.v, end.v) && end.v != 0.0) return times;
  const double turn =
      zero_of([&](double tau) { return acceleration(tau, at(tau)); }, 0.0, h, c0 > 0.0);
  const double v_turn = at(turn).v;
  monotone(0.0, start.v, turn, v_turn);
  if (v_turn == 0.0) times.push_back(turn);
  monotone(turn, v_turn, h, end.v);
  return times;
}

double spectral_acceleration_g(const GroundMotionPieces& motion, double period, double damping) {
  require_measure_in(kSpectralPeriodDomain, period, "period");
  require_measure_in(kSpectralDampingDomain, damping, "damping");
  const double omega = 2.0 * pi / period, end = motion.end_of_motion();

  const auto refuse = [&] {
    throw InvalidInput("invalid intensity measure: Sa at period " + format_number(period) +
                       " s would take more than " + format_number(kMaxSpectrumSteps) +
                       " steps of period / 100 over a motion of " + format_number(end) + " s");
  };
  // Every step is at most period / 100 long, so this many periods already break the budget; it is
  // checked first because a piece's step count would overflow for a period near 0.
  if (end / period > static_cast<double>(kMaxSpectrumSteps)) refuse();
  std::vector<PieceGrid> grids;
  long steps = 0;
  for (const MotionPiece& piece : motion.pieces()) {
    if (piece.start() >= end) break;
    if (piece.end() <= piece.start()) continue;
    grids.push_back(piece_grid(piece, end, period));
    steps += grids.back().steps;
    if (steps > kMaxSpectrumSteps) refuse();
  }

  // The excitation in g: a / g = -lambda, so u and omega^2 u come out in g s^2 and g.
  OscillatorState state;
  double peak = 0.0;
  for (const PieceGrid& grid : grids) {
    const MotionPiece& piece = *grid.piece;
    const double h = (grid.end - grid.start) / static_cast<double>(grid.steps);
    const NigamJenningsStep advance(omega, damping, h);
    double a0 = -piece.formula_value(grid.start);
    for (long j = 1; j <= grid.steps; ++j) {
      const double t = j == grid.steps ? grid.end : grid.start + static_cast<double>(j) * h;
      const double a1 = -piece.formula_value(t);  // at the piece's end: its left limit
      const OscillatorState next = advance(state, a0, a1);
      peak = std::max(peak, std::abs(next.q));
      for (const double tau : step_extrema(omega, damping, h, a0, a1, state, next)) {
        const double a_tau = a0 + (a1 - a0) * (tau / h);
        peak = std::max(peak, std::abs(NigamJenningsStep(omega, damping, tau)(state, a0, a_tau).q));
      }
      state = next;
      a0 = a1;
    }
  }
  peak = std::max(peak, first_free_extremum(omega, damping, state));
  return omega * omega * peak;
}

IntensityMeasures intensity_measures(const GroundMotionPieces& motion,
                                     const std::vector<double>& periods, double damping, double g) {
  IntensityMeasures m;
  m.pga_g = peak_ground_acceleration_g(motion);
  m.pgv = peak_ground_velocity(motion, g);
  m.significant_duration = significant_duration(motion);
  m.sa_g.reserve(periods.size());
  for (const double period : periods) {
    m.sa_g.push_back(spectral_acceleration_g(motion, period, damping));
  }
  return m;
}

GroundMotionPieces accelerogram_pieces(const Accelerogram& record) {
  check_accelerogram(record);
  RecordedMotion motion;
  motion.scale = 1.0;
  motion.record = std::make_shared<const Accelerogram>(record);
  return GroundMotionPieces(GroundMotion{motion});
}

IntensityMeasures intensity_measures(const Accelerogram& record, const std::vector<double>& periods,
                                     double damping, double g) {
  return intensity_measures(accelerogram_pieces(record), periods, damping, g);
}

}  // namespace blockfrag
