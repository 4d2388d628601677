// Ground-motion intensity measures of a motion given as pieces (engine/motion/ground_motion.hpp),
// taken on the ground's acceleration a(t) = -lambda(t) g: the peak ground acceleration and
// velocity, the significant duration D5-95 and the pseudo-spectral acceleration of a damped linear
// oscillator. The ground is at rest at t = 0 and no baseline is corrected: the velocity is the
// integral of a from 0 as the motion gives it. Negating a negates v and u too, so PGA, PGV and Sa
// (largest magnitudes) and D5-95 (of a^2) are the same for either sign: neither the sign
// convention (a record's samples are a, a pulse's lambda is -a / g) nor the sign of a scale factor
// changes them.
//
// Where each is exact:
// - PGV. Every piece's lambda has an antiderivative in closed form (a linear piece's is a
//   quadratic, a cosine's a sine, a Ricker wavelet's u exp(-u^2) / omega, a Mavroeidis-
//   Papageorgiou pulse's its own defining velocity), and v has its extremes at the pieces' ends
//   and where lambda changes sign inside one: in closed form for every shape but the Mavroeidis-
//   Papageorgiou pulse, whose sign changes are searched with the bound on lambda's slope
//   (pulse::zeros_between). That search can only miss two sign changes closer than its
//   min_width, a maximum and a minimum of v that differ by less than kNegligibleVelocityPair of
//   the pulse's velocity scale; the larger of the pair is then within that of a value looked at.
// - D5-95 (Trifunac & Brady 1975): the Arias integral of a^2 is in closed form per piece too (a
//   linear piece's is a cubic, a cosine's t/2 + sin(2 theta)/(4 omega), a Ricker wavelet's an erf
//   and a Gaussian, a Mavroeidis-Papageorgiou pulse's three squares and three products of sines);
//   the 5 % and 95 % crossings are bisected inside their piece to kDurationCrossingTolerance of its
//   length.
// - Sa. The oscillator u'' + 2 zeta omega u' + omega^2 u = -a(t), from rest, is stepped with
//   NigamJenningsStep (engine/motion/dam_crest.hpp, exact when a is linear over the step) on the
//   dam filter's grid (piece_grid): steps of at most min(T, the piece's time scale) / 100, so a
//   record's pieces are stepped exactly and a smooth pulse's are drawn linearly between nodes,
//   which errs by at most (2 pi / 100)^2 / 8 = 4.9e-4 of the pulse's peak in the excitation and by
//   about that fraction in Sa. The maximum of |u| is not taken at the nodes alone (a node can miss
//   a peak by up to (omega h)^2 / 8 of it, 4.9e-4 at h = T / 100): it is at the nodes or where u' =
//   0 inside a step, and those zeros are found exactly. Inside a step a is linear, so u is a line
//   plus a damped sinusoid of period T_d = T / sqrt(1 - zeta^2) and u'' is that sinusoid's second
//   derivative alone, whose zeros are T_d / 2 > h apart: u'' changes sign at most once in a step,
//   and u' has at most one extremum there. So u' has one zero where it changes sign over the step,
//   two where it keeps its sign but its extremum (u'' = 0, located first) has the other sign, and
//   none otherwise; each zero is located by bisection with the exact solution over part of the
//   step, to kSpectrumExtremumTimeTolerance of the step, where u is flat to round-off. After the
//   motion ends the oscillator rings freely: its largest |u| from then on is at the end or at its
//   first extremum after it (closed form, one Nigam-Jennings step of a = 0; each later extremum is
//   the one before times exp(-zeta omega T_d / 2) <= 1), however long the ringing takes.
#pragma once

#include <vector>

#include "engine/motion/accelerogram.hpp"
#include "engine/motion/dam_crest.hpp"
#include "engine/motion/ground_motion.hpp"
#include "engine/scene/parameter_domains.hpp"
#include "engine/tolerances.hpp"

namespace blockfrag {

// The oscillator's period: up to 10 s, the long end of design spectra.
inline constexpr Domain kSpectralPeriodDomain{0.0, 10.0, false, true, "s"};
// Its damping, of critical: the Nigam-Jennings step is for underdamped oscillators only.
inline constexpr Domain kSpectralDampingDomain{0.0, 1.0, true, false, ""};

// max |lambda|, in g: the peak ground acceleration.
double peak_ground_acceleration_g(const GroundMotionPieces& motion);

// max |v(t)|, in m/s, v = -g times the integral of lambda from 0 (g in m/s^2).
double peak_ground_velocity(const GroundMotionPieces& motion, double g);

// D5-95 in s: the time from 5 % to 95 % of the Arias intensity (the integral of a^2 from 0), each
// the first time the intensity reaches that fraction. 0 for a motion that is zero everywhere.
double significant_duration(const GroundMotionPieces& motion);

// Sa(T, zeta) in g: omega^2 max |u| over all t >= 0 (the ringing after the motion included), with
// omega = 2 pi / T. Refuses (InvalidInput) a period or damping outside its domain above, or a
// motion that would take more than kMaxSpectrumSteps steps.
double spectral_acceleration_g(const GroundMotionPieces& motion, double period, double damping);

// The times in (0, h) where u' = 0 over one step of the oscillator (omega = 2 pi / T, damping
// zeta) with a linear from a0 to a1, from the state `start` to `end` (the step's Nigam-Jennings
// result): the extremes of u between the nodes, in order, each to kSpectrumExtremumTimeTolerance of
// h. The step must be shorter than T_d / 2 (above: u'' then changes sign at most once in it).
std::vector<double> step_extrema(double omega, double zeta, double h, double a0, double a1,
                                 const OscillatorState& start, const OscillatorState& end);

struct IntensityMeasures {
  double pga_g = 0.0;
  double pgv = 0.0;                   // m/s
  double significant_duration = 0.0;  // D5-95, s
  std::vector<double> sa_g;           // Sa at the periods asked for, in their order, g
};

// All of the above; g (m/s^2) converts lambda into a for PGV, in domain::g.
IntensityMeasures intensity_measures(const GroundMotionPieces& motion,
                                     const std::vector<double>& periods, double damping, double g);

// A record of a(t) in g as the pieces a scene gives it (a RecordedMotion of scale 1: lambda = -a,
// zero before the first sample and after the last). Refuses what check_accelerogram refuses.
GroundMotionPieces accelerogram_pieces(const Accelerogram& record);

// The measures of a record of a(t) in g, through accelerogram_pieces.
IntensityMeasures intensity_measures(const Accelerogram& record, const std::vector<double>& periods,
                                     double damping, double g);

}  // namespace blockfrag
