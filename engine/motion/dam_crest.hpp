// The motion of a gravity dam's crest, from the motion of its foundation. The dam is its
// fundamental mode (Fenves & Chopra's simplified analysis): a damped oscillator whose modal
// coordinate q obeys q'' + 2 zeta omega q' + omega^2 q = -a_g(t), and whose crest moves, relative
// to the foundation, by Gamma phi q. The crest's absolute acceleration is
//   a_crest = a_g + Gamma phi a_rel,   a_rel = q'' = -2 zeta omega q' - omega^2 q - a_g,
// and with a_g = -lambda g the block on the crest feels lambda_crest = -a_crest / g.
#pragma once

#include <cstddef>
#include <vector>

#include "engine/motion/ground_motion.hpp"
#include "engine/scene/scene.hpp"

namespace blockfrag {

// Fenves & Chopra (1987), eq. (2): T1 = 1.4 H / sqrt(E), with H in feet and E in psi; the
// period of the dam on rigid foundation rock with an empty reservoir.
double fenves_chopra_period(double height_m, double elastic_modulus_pa);

// The dam's fundamental period on rigid rock with an empty reservoir: as given, or estimated from
// its height and modulus.
double dam_period(const DamCrest& dam);

// The fundamental mode the crest filter runs: period (s) and damping (of critical).
struct DamMode {
  double period;
  double damping;
};

// Fenves & Chopra's simplified analysis (Fenves & Chopra 1987; USACE EP 1110-2-12, 1995,
// appendix C): the impounded water lengthens the period by R_r and the flexible foundation rock by
// R_f, and each adds damping,
//   T1' = R_r R_f T1,   zeta1' = zeta1 / (R_r R_f^3) + zeta_r + zeta_f.
// With R_r = R_f = 1 and zeta_r = zeta_f = 0 the mode is the dam's own, to the bit.
DamMode fenves_chopra_mode(DamMode rigid_empty, double reservoir_period_ratio,
                           double reservoir_damping, double foundation_period_ratio,
                           double foundation_damping);

// The dam's mode with its reservoir and foundation: what the crest filter runs.
DamMode dam_mode(const DamCrest& dam);

// The modal coordinate and its rate.
struct OscillatorState {
  double q = 0.0;  // m
  double v = 0.0;  // m/s
};

// One step of Nigam & Jennings (1969): the exact map of the oscillator's state over a step of
// length h when the excitation a(t) is linear from a0 to a1 over the step. Underdamped only
// (0 <= zeta < 1).
class NigamJenningsStep {
 public:
  NigamJenningsStep(double omega, double zeta, double h);
  OscillatorState operator()(const OscillatorState& s, double a0, double a1) const;

 private:
  double omega_, zeta_, h_;
  bool taylor_;  // a step too short for the closed form's coefficients (see the .cpp)
  double a11_ = 0, a12_ = 0, a21_ = 0, a22_ = 0;
  double b11_ = 0, b12_ = 0, b21_ = 0, b22_ = 0;
};

// The filter's grid over one piece: from its start to min(its end, duration) in `steps` equal
// steps, none longer than min(period, the piece's time scale) / 100. The dam filter and the
// response spectrum (engine/motion/intensity_measures.hpp) both step on it.
struct PieceGrid {
  const MotionPiece* piece;
  double start, end;
  long steps;
};
PieceGrid piece_grid(const MotionPiece& piece, double duration, double period);

// The crest's response at the nodes of the filter's grid: every boundary of the foundation's
// pieces, and steps of at most min(T1, the piece's time scale) / 100 between them. Where the
// foundation's acceleration jumps, the node is repeated: first with the value before the jump,
// then after (the oscillator's state is continuous there).
struct CrestHistory {
  std::vector<double> times;                    // s, non-decreasing, from 0 to the duration
  std::vector<double> foundation_acceleration;  // a_g, m/s^2
  std::vector<OscillatorState> modal;           // q, q'
  std::vector<double> crest_lambda;             // -a_crest / g
};

// The nodes of the crest history up to `duration` under a dam of this period, counted without
// building it (a ringing crest followed until_quiet may stop earlier, but is refused on this count
// all the same): a config reader decides with it, before any work, what dam_crest_history would
// refuse (more nodes than kMaxCrestNodes, engine/tolerances.hpp).
std::size_t dam_crest_nodes(const GroundMotionPieces& foundation, double period, double duration);

// Up to `duration`; with until_quiet, the history ends earlier once the foundation has stopped
// and the crest's free ringing can no longer exceed kRingingEndAccelerationG
// (engine/tolerances.hpp).
CrestHistory dam_crest_history(const GroundMotionPieces& foundation, const DamCrest& dam,
                               double duration, double g, bool until_quiet = false);

// The crest motion as the block feels it: the history's lambdas, linear between nodes, zero after
// the history ends. The dam keeps ringing after the foundation stops, up to the duration, or with
// until_quiet until its ringing has died out.
GroundMotionPieces dam_crest_motion(const GroundMotionPieces& foundation, const DamCrest& dam,
                                    double duration, double g, bool until_quiet = false);

}  // namespace blockfrag
