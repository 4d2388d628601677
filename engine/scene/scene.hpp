// One simulation's inputs: block, contact, excitation, solver. Plain values, SI units.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "engine/motion/accelerogram.hpp"
#include "engine/motion/near_fault_pulses.hpp"
#include "engine/scene/reservoir.hpp"

namespace blockfrag {

// A rectangle of half-width a and half-height b resting on its base.
struct RectangularBlock {
  double half_width = 0.5;   // a, m
  double half_height = 1.0;  // b, m
  double mass = 1.0;         // kg; no result depends on it, impulses and forces scale with it
};

// Any simple polygon resting on its one lowest edge: vertices (x, y) in metres, counter-clockwise,
// from any vertex and in any frame (the centre of mass is computed; uniform density). Rocks about
// the two ends of the base edge; the ground touches only its convex hull; it lies on another face
// of the hull (overturns) when that face reaches the ground.
struct PolygonBlock {
  std::vector<std::array<double, 2>> vertices;
  double mass = 1.0;  // kg, of the whole block (e.g. per metre of a dam's length)
};

// The rocking restitution r = omega+ / omega- of a rocking impact (engine/contact/
// rocking_restitution.hpp): a value in (0, 1], or Housner's, the block's own angular-momentum
// value.
struct RockingRestitution {
  bool housner = false;
  double ratio = 1.0;  // r, when not housner
};

struct Contact {
  // Contact{mu, e}: the rocking restitution unset.
  Contact() = default;
  Contact(double mu, double e, std::optional<RockingRestitution> rocking = std::nullopt)
      : friction(mu), restitution(e), rocking_restitution(rocking) {}

  double friction = 0.6;  // mu, Coulomb, static = kinetic
  double restitution =
      0.6;  // e, Newton's coefficient on the normal velocity of the impacting corner
  // None: Newton's e at every impact, rocking impacts included.
  std::optional<RockingRestitution> rocking_restitution;
};

// The ground the block rests on when it is not one flat unbounded line (engine/scene/seat.hpp): a
// polyline of points [x, y] from left to right, in the frame of the block's vertices (a
// rectangle's: its centre); beyond its ends there is no ground.
struct Seat {
  std::vector<std::array<double, 2>> points;
};

// The ground's horizontal acceleration is -lambda(t) g; each pulse is zero outside its window.
struct NoMotion {};
struct CosinePulse {  // lambda = A cos(2 pi t / T) for 0 <= t < cycles T
  double amplitude_g = 1.0;
  double period = 2.0;
  double cycles = 1.0;
};
struct SinePulse {  // lambda = A sin(2 pi t / T) for 0 <= t < cycles T
  double amplitude_g = 1.0;
  double period = 2.0;
  double cycles = 1.0;
};
struct RectangularPulse {  // lambda = A for 0 <= t < duration
  double amplitude_g = 1.0;
  double duration = 1.0;
};
// A recorded accelerogram a(t) (in g) is the ground's acceleration: lambda = -scale a(t), linear
// between samples, zero before the first and after the last. The samples are shared, not copied,
// when scenes are copied.
struct RecordedMotion {
  std::string file;  // as the scene gave it (for output)
  double scale = 1.0;
  std::shared_ptr<const Accelerogram> record;
};
// The near-fault pulses (Makris A, B, C_n, Ricker, Mavroeidis-Papageorgiou) are in
// engine/motion/near_fault_pulses.hpp with their formulas.
using GroundMotion =
    std::variant<NoMotion, CosinePulse, SinePulse, RectangularPulse, RecordedMotion, MakrisPulseA,
                 MakrisPulseB, MakrisPulseC, RickerWavelet, MavroeidisPapageorgiouPulse>;

// The block sits on the crest of a gravity dam: the foundation motion reaches it through the dam's
// fundamental mode, a damped oscillator (engine/motion/dam_crest.hpp). The period is given, or
// estimated from the dam's height and concrete modulus (Fenves & Chopra 1987).
struct DamPeriod {
  double period = 0.25;  // T1, s
};
struct DamSize {
  double height = 100.0;          // H, m
  double elastic_modulus = 25e9;  // E, Pa
};
// The period and damping are the dam's on rigid rock with an empty reservoir; the ratios and added
// dampings of Fenves & Chopra's simplified analysis bring in the impounded water and the flexible
// foundation (engine/motion/dam_crest.hpp, dam_mode). Their defaults leave the dam as given.
struct DamCrest {
  std::variant<DamPeriod, DamSize> stiffness = DamPeriod{};
  double damping = 0.05;  // zeta, of critical
  double participation =
      1.0;  // Gamma_1 phi_1(crest): the mode's participation times its crest ordinate
  double reservoir_period_ratio = 1.0;   // R_r >= 1
  double reservoir_damping = 0.0;        // zeta_r, of critical
  double foundation_period_ratio = 1.0;  // R_f >= 1
  double foundation_damping = 0.0;       // zeta_f, of critical
};

// rk4: the paper's fixed step. adaptive: Dormand-Prince 5(4) with dense output (the production
// method). gsl_rkf45, gsl_rk8pd: GSL's odeiv2 steppers with its standard step control, as a
// well-known library's answer (cubic Hermite dense output for event location).
enum class Method { rk4, adaptive, gsl_rkf45, gsl_rk8pd };

struct SolverSettings {
  Method method = Method::adaptive;
  double dt = 2.5e-4;       // rk4 step, s (the paper's)
  double tolerance = 1e-8;  // adaptive: relative and scaled absolute error per step
  // Safety net: a scene that exceeds any of these stops with status "failed".
  long max_steps = 50'000'000;
  long max_events = 1'000'000;
};

// A block released tilted by theta (rad, counter-clockwise positive) onto the corner that is then
// lowest (theta = 0: flat on its base), turning at omega (rad/s, counter-clockwise positive) about
// that corner; flat and turning, about the corner its turning keeps on the ground (the right one
// for omega < 0).
struct InitialState {
  double theta = 0.0;
  double omega = 0.0;
};

// The physics a scene simulates ("effects" in a scene file). automatic ("auto"): everything the
// inputs make possible, pruning what they make impossible (never changing a result). Otherwise the
// flags name one model: rocking (+ impact): Housner's rocking block, which never slides or lifts
// off (impacts with Housner's ratio; without impact the pivot changes without loss); sliding alone:
// Newmark's sliding block, which never rocks; all four: the full model, which alone also takes
// vertical ground motion (the fifth flag, set exactly when the scene has one).
struct Effects {
  bool automatic = true;
  bool rocking = true, sliding = true, impact = true, flight = true, vertical = false;
};

struct Scene {
  Effects effects;
  RectangularBlock block;
  // When set, the block is this polygon and `block` above is not used.
  std::optional<PolygonBlock> polygon;
  std::optional<Seat> seat;  // none: the flat ground, without ends
  Contact contact;
  GroundMotion ground_motion = NoMotion{};
  // The ground's upward acceleration is lambda_v(t) g: gravity in the ground's frame is
  // g (1 + lambda_v), and the block leaves the ground when the ground falls faster than g.
  GroundMotion vertical_motion = NoMotion{};
  std::optional<DamCrest> dam;         // none: the block stands on the foundation
  std::optional<Reservoir> reservoir;  // none: no water (engine/scene/reservoir.hpp)
  // The simulated time, s. None: the run goes on until the block has settled (every excitation,
  // the dam crest's ringing included, has ended and the block is at rest on its base, or it has
  // overturned), and stops unsettled at max_duration.
  std::optional<double> duration = 4.0;
  // Without a duration, where a run that has not settled stops (s); none: kSettleAllowance after
  // the last excitation ends.
  std::optional<double> max_duration;
  double g = 9.81;  // m/s^2
  SolverSettings solver;
  InitialState initial;
};

}  // namespace blockfrag
