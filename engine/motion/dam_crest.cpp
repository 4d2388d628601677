#include "engine/motion/dam_crest.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <string>
#include <type_traits>

#include "engine/errors.hpp"
#include "engine/tolerances.hpp"

namespace blockfrag {

namespace {

constexpr double kMetresPerFoot = 0.3048;
constexpr double kPascalsPerPsi = 6894.757293168361;  // 1 lbf / in^2

}  // namespace

PieceGrid piece_grid(const MotionPiece& piece, double duration, double period) {
  const double end = std::min(piece.end(), duration);
  const double max_step = std::min(period, piece.time_scale()) / kCrestNodesPerPeriod;
  const long steps = std::max(1L, static_cast<long>(std::ceil((end - piece.start()) / max_step)));
  return {&piece, piece.start(), end, steps};
}

double fenves_chopra_period(double height_m, double elastic_modulus_pa) {
  const double height_ft = height_m / kMetresPerFoot;
  const double modulus_psi = elastic_modulus_pa / kPascalsPerPsi;
  return 1.4 * height_ft / std::sqrt(modulus_psi);
}

double dam_period(const DamCrest& dam) {
  return std::visit(
      [](const auto& s) {
        if constexpr (std::is_same_v<std::decay_t<decltype(s)>, DamPeriod>) {
          return s.period;
        } else {
          return fenves_chopra_period(s.height, s.elastic_modulus);
        }
      },
      dam.stiffness);
}

DamMode fenves_chopra_mode(DamMode rigid_empty, double reservoir_period_ratio,
                           double reservoir_damping, double foundation_period_ratio,
                           double foundation_damping) {
  const double r_r = reservoir_period_ratio, r_f = foundation_period_ratio;
  return {r_r * r_f * rigid_empty.period,
          rigid_empty.damping / (r_r * r_f * r_f * r_f) + reservoir_damping + foundation_damping};
}

DamMode dam_mode(const DamCrest& dam) {
  return fenves_chopra_mode({dam_period(dam), dam.damping}, dam.reservoir_period_ratio,
                            dam.reservoir_damping, dam.foundation_period_ratio,
                            dam.foundation_damping);
}

NigamJenningsStep::NigamJenningsStep(double omega, double zeta, double h)
    : omega_(omega), zeta_(zeta), h_(h), taylor_(omega * h < kTaylorBelow) {
  if (taylor_) return;
  const double w = omega, z = zeta;
  const double root = std::sqrt(1.0 - z * z);
  const double wd = w * root;
  const double E = std::exp(-z * w * h), S = std::sin(wd * h), C = std::cos(wd * h);
  // Homogeneous part: free vibration from (q, v).
  a11_ = E * (z / root * S + C);
  a12_ = E * S / wd;
  a21_ = -w / root * E * S;
  a22_ = E * (C - z / root * S);
  // Forced part: the response to a(t) = a0 (1 - t/h) + a1 t/h from rest (Nigam & Jennings 1969).
  const double k1 = (2 * z * z - 1) / (w * w * h);
  const double k2 = 2 * z / (w * w * w * h);
  const double decaying_v = C - z / root * S;  // e^{zwt} times d/dt of the decaying sine part
  const double rate = wd * S + z * w * C;
  b11_ = E * ((k1 + z / w) * S / wd + (k2 + 1 / (w * w)) * C) - k2;
  b12_ = -E * (k1 * S / wd + k2 * C) - 1 / (w * w) + k2;
  b21_ = E * ((k1 + z / w) * decaying_v - (k2 + 1 / (w * w)) * rate) + 1 / (w * w * h);
  b22_ = -E * (k1 * decaying_v - k2 * rate) - 1 / (w * w * h);
}

OscillatorState NigamJenningsStep::operator()(const OscillatorState& s, double a0,
                                              double a1) const {
  if (taylor_) {
    // q''' = -2 zeta omega q'' - omega^2 q' - a'; truncation O((omega h)^3) relative.
    const double w = omega_, h = h_;
    const double acc = -2 * zeta_ * w * s.v - w * w * s.q - a0;
    const double jerk = -2 * zeta_ * w * acc - w * w * s.v - (a1 - a0) / h;
    return {s.q + h * (s.v + h * (acc / 2 + h * jerk / 6)), s.v + h * (acc + h * jerk / 2)};
  }
  return {a11_ * s.q + a12_ * s.v + b11_ * a0 + b12_ * a1,
          a21_ * s.q + a22_ * s.v + b21_ * a0 + b22_ * a1};
}

std::size_t dam_crest_nodes(const GroundMotionPieces& foundation, double period, double duration) {
  std::size_t nodes = 1;
  for (const MotionPiece& piece : foundation.pieces()) {
    if (piece.start() >= duration) break;
    if (piece.end() <= piece.start()) continue;
    // + 1: a possible repeated node where the foundation jumps.
    nodes += static_cast<std::size_t>(piece_grid(piece, duration, period).steps) + 1;
  }
  return nodes;
}

namespace {

void check_crest_node_count(std::size_t nodes, double period, double duration) {
  if (nodes > kMaxCrestNodes) {
    std::ostringstream why;
    why << "invalid scene: the dam's period (" << period << " s) is too short for the duration ("
        << duration << " s): the crest motion would need " << nodes
        << " nodes (one per period / 100), more than " << kMaxCrestNodes;
    throw InvalidInput(why.str());
  }
}

// The grids of the foundation's pieces that start before `duration` and last.
std::vector<PieceGrid> crest_piece_grids(const GroundMotionPieces& foundation, double period,
                                         double duration) {
  std::vector<PieceGrid> grids;
  for (const MotionPiece& piece : foundation.pieces()) {
    if (piece.start() >= duration) break;
    if (piece.end() <= piece.start()) continue;
    grids.push_back(piece_grid(piece, duration, period));
  }
  return grids;
}

}  // namespace

CrestHistory dam_crest_history(const GroundMotionPieces& foundation, const DamCrest& dam,
                               double duration, double g, bool until_quiet) {
  const DamMode mode = dam_mode(dam);
  const double period = mode.period;
  const double omega = 2 * std::numbers::pi / period;
  const double zeta = mode.damping, gamma_phi = dam.participation;

  const std::size_t nodes = dam_crest_nodes(foundation, period, duration);
  check_crest_node_count(nodes, period, duration);
  const std::vector<PieceGrid> grids = crest_piece_grids(foundation, period, duration);

  CrestHistory h;
  h.times.reserve(nodes);
  h.foundation_acceleration.reserve(nodes);
  h.modal.reserve(nodes);
  h.crest_lambda.reserve(nodes);
  auto record = [&](double t, double a_g, const OscillatorState& s) {
    const double a_rel = -2 * zeta * omega * s.v - omega * omega * s.q - a_g;
    h.times.push_back(t);
    h.foundation_acceleration.push_back(a_g);
    h.modal.push_back(s);
    h.crest_lambda.push_back(-(a_g + gamma_phi * a_rel) / g);
  };

  // After the foundation stops, the crest rings freely: q = A e^{-zeta omega t} cos(omega_d t -
  // phi), whose every derivative has amplitude omega times the one before, so |lambda_crest| is at
  // most Gamma phi omega^2 A / g.
  const double omega_d = omega * std::sqrt(1.0 - zeta * zeta);
  const auto quiet = [&](const OscillatorState& s) {
    const double amplitude = std::hypot(s.q, (s.v + zeta * omega * s.q) / omega_d);
    return gamma_phi * omega * omega * amplitude / g < kRingingEndAccelerationG;
  };
  const double foundation_end = foundation.end_of_motion();

  OscillatorState state;
  for (const PieceGrid& grid : grids) {
    const MotionPiece& piece = *grid.piece;
    const bool ringing = until_quiet && grid.start >= foundation_end;
    const double a_start = -piece.formula_value(grid.start) * g;
    if (h.times.empty() || a_start != h.foundation_acceleration.back()) {
      record(grid.start, a_start, state);
    }
    const double step = (grid.end - grid.start) / static_cast<double>(grid.steps);
    const NigamJenningsStep advance(omega, zeta, step);
    double a0 = a_start;
    for (long j = 1; j <= grid.steps; ++j) {
      const double t = j == grid.steps ? grid.end : grid.start + static_cast<double>(j) * step;
      const double a1 = -piece.formula_value(t) * g;  // at the piece's end: its left limit
      state = advance(state, a0, a1);
      record(t, a1, state);
      a0 = a1;
      if (ringing && quiet(state)) return h;
    }
  }
  return h;
}

GroundMotionPieces dam_crest_motion(const GroundMotionPieces& foundation, const DamCrest& dam,
                                    double duration, double g, bool until_quiet) {
  CrestHistory history = dam_crest_history(foundation, dam, duration, g, until_quiet);
  // A repeated node whose crest value did not jump (participation 1 makes the crest continuous
  // where the foundation jumps) would only be an empty piece.
  std::vector<double> times, lambdas;
  times.reserve(history.times.size());
  lambdas.reserve(history.times.size());
  for (std::size_t i = 0; i < history.times.size(); ++i) {
    if (!times.empty() && history.times[i] == times.back() &&
        history.crest_lambda[i] == lambdas.back()) {
      continue;
    }
    times.push_back(history.times[i]);
    lambdas.push_back(history.crest_lambda[i]);
  }
  return GroundMotionPieces(times, lambdas);
}

}  // namespace blockfrag
