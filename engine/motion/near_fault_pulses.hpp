// Analytic near-fault pulses: the ground motions a scene names by "type" besides the plain
// sine/cosine/rectangular pulses. Plain values; engine/motion/pulse_shapes.hpp has their formulas
// and engine/motion/ground_motion.cpp turns each into pieces. As everywhere, the ground's
// acceleration is -lambda(t) g, so a positive amplitude_g pushes the block to +x first; each is
// zero outside its window, which starts at t = 0.
#pragma once

#include <optional>

namespace blockfrag {

// Makris's cycloidal pulses in acceleration form, omega_p = 2 pi / Tp (Makris 1997, "Rigidity-
// plasticity-viscosity: can electrorheological dampers protect base-isolated structures from
// near-source ground motions?"; Makris & Roussos 2000, Geotechnique 50(3); Zhang & Makris 2001,
// J. Eng. Mech. 127(5)).
// Type A, one sine of acceleration (a forward velocity pulse):
//   lambda = A sin(omega_p t) for 0 <= t < Tp.
struct MakrisPulseA {
  double amplitude_g = 1.0;  // A
  double period = 1.0;       // Tp, s
};
// Type B, one cosine of acceleration (a forward-and-back velocity pulse):
//   lambda = A cos(omega_p t) for 0 <= t < Tp.
struct MakrisPulseB {
  double amplitude_g = 1.0;
  double period = 1.0;
};
// Type C_n, n main velocity cycles:
//   lambda = A cos(omega_p t + phi) for 0 <= t < (n + 1/2 - phi/pi) Tp.
// The ground velocity returns to zero at the end for any phi; the displacement does for the phi in
// (0, pi/2) that solves 2 cos(phi) = ((2n + 1) pi - 2 phi) sin(phi) (integrate lambda twice from 0
// to the end: engine/motion/pulse_shapes.cpp). makris_c_phase(n) solves it.
struct MakrisPulseC {
  double amplitude_g = 1.0;
  double period = 1.0;
  int n = 1;
};

// Ricker wavelet (the "Mexican hat"; Ricker 1943) with peak frequency f_p = 1/Tp (the maximum of
// its Fourier amplitude spectrum):
//   lambda = A (1 - 2 u^2) exp(-u^2), u = pi f_p (t - t0) = pi (t - t0) / Tp, for 0 <= t < 2 t0.
// Its extrema are at t0 (A) and t0 +- sqrt(3/2) Tp / pi (-2 exp(-3/2) A = -0.446 A).
struct RickerWavelet {
  double amplitude_g = 1.0;
  double period = 1.0;       // Tp = 1 / f_p, s
  std::optional<double> t0;  // the centre, s; default 1.5 Tp
  // At the default centre, u = 1.5 pi at t = 0 and the cut tails are below 1e-8 A.
  double center() const { return t0.value_or(1.5 * period); }
};

// Mavroeidis & Papageorgiou (2003, BSSA 93(3)) pulse, given by its ground velocity:
//   v(t) = (Vp / 2) [1 + cos(2 pi fp (t - t0) / gamma)] cos(2 pi fp (t - t0) + nu)
// for |t - t0| <= gamma / (2 fp), zero outside; fp = 1/Tp. lambda = -a / g with a = dv/dt; with
// Omega = 2 pi fp and tau = t - t0, the product of cosines expands into three sines:
//   lambda = (Vp Omega / (2 g)) [sin(Omega tau + nu) + (1 + 1/gamma)/2 sin((1 + 1/gamma) Omega tau
//   + nu)
//                                + (1 - 1/gamma)/2 sin((1 - 1/gamma) Omega tau + nu)].
// With nu = 0 the ground velocity peaks at Vp at t0.
struct MavroeidisPapageorgiouPulse {
  double velocity_amplitude = 1.0;  // Vp, m/s
  double period = 1.0;              // Tp = 1 / fp, s
  double gamma = 2.0;               // the envelope's length in periods; > 1
  double phase = 0.0;               // nu, rad
  std::optional<double> t0;         // the envelope's centre, s; default gamma Tp / 2 (starts at 0)
  double center() const { return t0.value_or(0.5 * gamma * period); }
  double half_width() const { return 0.5 * gamma * period; }
};

}  // namespace blockfrag
