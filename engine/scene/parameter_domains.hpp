// The values each scene parameter may take: one table, used by the engine's scene validation, the
// scene and study readers (their messages and every sampled input's support). Each domain is wide
// enough for any real block and ground motion, and narrow enough that no value in it can overflow
// the arithmetic, stall an integrator or ask for more work than a scene's budgets allow.
#pragma once

#include <cstddef>
#include <limits>
#include <numbers>
#include <string>

#include "engine/number_text.hpp"

namespace blockfrag {

struct Domain {
  double low, high;
  bool low_inclusive, high_inclusive;
  const char* unit;  // "m", "s", "g", ... or "" for a pure number
  // Names a bound in messages where the digits would not speak ("pi/2"); nullptr: the digits.
  const char* low_label = nullptr;
  const char* high_label = nullptr;

  constexpr bool contains(double x) const {
    return (low_inclusive ? x >= low : x > low) && (high_inclusive ? x <= high : x < high);
  }
  // "must be in (0, 10000]", or "must be > 0" without an upper bound.
  std::string rule() const {
    const auto text = [](double value, const char* label) {
      return label ? std::string(label) : format_number(value);
    };
    if (high == std::numeric_limits<double>::infinity()) {
      return std::string("must be ") + (low_inclusive ? ">= " : "> ") + text(low, low_label);
    }
    return "must be in " + std::string(low_inclusive ? "[" : "(") + text(low, low_label) + ", " +
           text(high, high_label) + (high_inclusive ? "]" : ")");
  }
};

namespace domain {

// --- The block ---------------------------------------------------------------------------------
// A rectangle's half-width and half-height, a sampled R, and a polygon's size (its largest corner
// distance from the centre of mass): from a 0.1 mm pebble to a 10 km slab.
inline constexpr Domain block_length{1e-4, 1e4, true, true, "m"};
// A polygon's vertex coordinates, in any frame: the block may sit far from the origin.
inline constexpr Domain polygon_coordinate{-1e5, 1e5, true, true, "m"};
// No result depends on the mass (the engine works per unit mass): any positive finite value.
inline constexpr Domain mass{0.0, std::numeric_limits<double>::infinity(), false, false, "kg"};
// Up to 10,000 vertices (a digitised outline).
inline constexpr double kMaxPolygonVertices = 10'000;
// A seat's points (engine/scene/seat.hpp), in the same frame and domain as a polygon's: up to
// 1,000, so checking the fit (every block edge against every seat segment) stays in milliseconds.
inline constexpr double kMaxSeatPoints = 1'000;
// A rectangle's slenderness as a study samples it.
inline constexpr Domain alpha{0.0, std::numbers::pi / 2, false, false, "rad", nullptr, "pi/2"};

// --- The contact ---------------------------------------------------------------------------------
// Coulomb's mu: 0 (frictionless) to 10,000 (no slip in practice: Housner's block).
inline constexpr Domain friction{0.0, 1e4, true, true, ""};
inline constexpr Domain restitution{0.0, 1.0, true, true, ""};
// The rocking restitution r = omega+ / omega- (engine/contact/rocking_restitution.hpp): 0 would
// stop the block dead at every rocking impact, above 1 every impact would add energy.
inline constexpr Domain rocking_restitution{0.0, 1.0, false, true, ""};

// --- Ground motion -------------------------------------------------------------------------------
// A pulse's peak acceleration in g, either sign: 1000 g is far past any earthquake.
inline constexpr Domain amplitude_g{-1e3, 1e3, true, true, "g"};
// A record's peak acceleration to scale to, and a study's intensity levels in g.
inline constexpr Domain target_pga_g{0.0, 1e3, false, true, "g"};
inline constexpr Domain intensity_g = target_pga_g;
// A factor on a record, either sign.
inline constexpr Domain record_scale{-1e3, 1e3, true, true, ""};
// A pulse's period (and a Ricker wavelet's 1 / peak frequency): from 1 ms (1 kHz) to 1000 s.
inline constexpr Domain pulse_period{1e-3, 1e3, true, true, "s"};
// Whole or fractional periods of a cosine or sine pulse.
inline constexpr Domain pulse_cycles{0.0, 1e4, false, true, ""};
// A rectangular pulse's length.
inline constexpr Domain pulse_duration{1e-4, 1e4, true, true, "s"};
// Makris's type C_n pulse: its number of main velocity cycles n.
inline constexpr Domain makris_c_n{1.0, 1e3, true, true, ""};
// A time inside a motion (a Ricker wavelet's centre, a Mavroeidis-Papageorgiou pulse's t0).
inline constexpr Domain motion_time{0.0, 1e5, false, true, "s"};
// A Mavroeidis-Papageorgiou pulse: its velocity amplitude, gamma (oscillations under the
// envelope) and phase.
inline constexpr Domain velocity_amplitude{-100.0, 100.0, true, true, "m/s"};
inline constexpr Domain mp_gamma{1.0, 100.0, false, true, ""};
inline constexpr Domain mp_phase{-1e3, 1e3, true, true, "rad"};
// A recorded motion's sample times.
inline constexpr Domain record_time{0.0, 1e5, true, true, "s"};
// A record has at most this many samples: 5.5 hours at 200 Hz, 50 times the longest real
// strong-motion record. A scene holds about 120 bytes a sample (the samples and a motion piece
// between each two), so one record costs at most about 500 MB, where the file size cap alone
// would let a file of short lines ask for 20 GB.
inline constexpr std::size_t kMaxRecordSamples = 4'000'000;

// --- The dam crest ------------------------------------------------------------------------------
inline constexpr Domain dam_period{1e-3, 10.0, true, true, "s"};
inline constexpr Domain dam_height{1.0, 1e3, true, true, "m"};
inline constexpr Domain elastic_modulus{1e6, 1e13, true, true, "Pa"};
inline constexpr Domain dam_damping{0.0, 1.0, true, false, ""};
inline constexpr Domain participation{0.0, 100.0, false, true, ""};
// Fenves & Chopra's period ratios (R_r for the reservoir, R_f for the foundation: about 1 to 1.5 in
// their charts) and added dampings (zeta_r, zeta_f: up to about 0.15). Past 10 no simplified
// analysis holds.
inline constexpr Domain dam_period_ratio{1.0, 10.0, true, true, ""};
inline constexpr Domain dam_added_damping{0.0, 1.0, true, false, ""};

// --- The reservoir -------------------------------------------------------------------------------
// The water surface's y, in the frame of the block's vertices: as a polygon's coordinates.
inline constexpr Domain reservoir_level = polygon_coordinate;
// The reservoir's depth at the dam (Westergaard's H): a pond to ten times the highest dam.
inline constexpr Domain reservoir_depth{0.0, 1e4, false, true, "m"};
// Fresh water is 1000 kg/m^3, a silt-laden reservoir a few percent more: anything up to a heavy
// slurry's ten times.
inline constexpr Domain water_density{0.0, 1e4, false, true, "kg/m^3"};
// CADAM3D's uplift effective area: the fraction of the crack the pressure acts on.
inline constexpr Domain uplift_area_factor{0.0, 1.0, true, true, ""};

// --- The run -------------------------------------------------------------------------------------
// A scene's duration: up to about 28 hours of motion.
inline constexpr Domain duration{0.0, 1e5, false, true, "s"};
// Gravity: the Moon's 1.6 to a centrifuge's 100 g.
inline constexpr Domain g{1e-2, 1e3, true, true, "m/s^2"};
// A release tilt (a polygon's own overturning angles narrow it further).
inline constexpr Domain initial_theta{
    -std::numbers::pi / 2, std::numbers::pi / 2, false, false, "rad", "-pi/2", "pi/2"};
// A release's angular velocity: a free-rocking or impulse test's, far past any block's overturning.
inline constexpr Domain initial_omega{-1e3, 1e3, true, true, "rad/s"};
// RK4's fixed step (and at most the scene's duration).
inline constexpr Domain rk4_step{1e-7, 10.0, true, true, "s"};
// The adaptive methods' relative tolerance: round-off below 1e-14, no accuracy above 0.1.
inline constexpr Domain tolerance{1e-14, 0.1, true, true, ""};
// The step and event budgets.
inline constexpr Domain max_steps{1.0, 1e10, true, true, ""};
inline constexpr Domain max_events{1.0, 1e9, true, true, ""};

// --- Studies and spectra (mpi_driver/config/study_fields.hpp) ----------------------------------
// Seconds between checkpoints: a millisecond to about eleven days.
inline constexpr Domain checkpoint_interval_s{1e-3, 1e6, true, true, "s"};
// The fraction of a study's samples that may fail or be rejected before its exit code says so.
inline constexpr Domain allowed_failed_fraction{0.0, 1.0, true, true, ""};
// Resamples of a fit's bootstrap (0: none).
inline constexpr Domain bootstrap_resamples{0.0, 1e5, true, true, ""};
// A spectrum's minimum overturning amplitude: its bracket and the narrowest interval probed below
// it, both relative; the max |theta| / alpha at which a standing amplitude counts as near
// overturning; the midpoints per frequency, which rank 0 keeps with the grid's 100,000 frequencies.
inline constexpr Domain minimum_tolerance{1e-9, 0.1, true, true, ""};
inline constexpr Domain minimum_resolution{1e-9, 0.1, true, true, ""};
inline constexpr Domain near_overturning{0.0, 1.0, true, true, ""};
inline constexpr Domain minimum_midpoints{1.0, 1e5, true, true, "", "1", "100000"};
// A spectrum's bisection: its relative bracket, and at most 200 iterations, so that no config asks
// for an endless one.
inline constexpr Domain bisection_tolerance{1e-14, 0.1, true, true, ""};
inline constexpr Domain bisection_iterations{1.0, 200.0, true, true, ""};
// A spectrum point's run after the pulse, in 1 / p.
inline constexpr Domain settle_allowance_tau{1.0, 1e6, true, true, ""};
// A spectrum's frequency and amplitude ratios, positive; an axis given by from/to/count has 2 to
// 100,000 values.
inline constexpr Domain spectrum_ratio{0.0, std::numeric_limits<double>::infinity(), false, false,
                                       ""};
inline constexpr Domain spectrum_axis_count{2.0, 1e5, true, true, ""};
// An Sa measure's oscillator period: design spectra end near 10 s.
inline constexpr Domain sa_period{0.0, 10.0, false, true, "s"};
// A cloud's factor on every record, and a suite record's weight.
inline constexpr Domain cloud_scale{0.0, 1e3, false, true, ""};
inline constexpr Domain record_weight{0.0, 1e6, false, true, ""};
// Adaptive stripes: the median's 95 % interval width aimed at, relative; where a batch's pair of
// levels lies on the fit (at least 0.01: the pair lies at most 2.33 beta from the median in
// logarithm, where the fit still speaks of its data, not at the ends of the measure's range, as
// p = 1e-300 would ask for 1e-72 g and 1000 g; at most 0.49, just short of both levels at the
// median); the budget of samples in all batches (records stream to disk, so no memory limit, but
// a budget is a promise about time and disk).
inline constexpr Domain target_relative_width{0.0, 2.0, false, true, ""};
inline constexpr Domain pair_probability{0.01, 0.49, true, true, ""};
inline constexpr Domain adaptive_samples{1.0, 1e9, true, true, ""};
// A study's PGV levels, m/s (its other measures' are intensity_g's), and the count of levels
// from/to/count makes (at most kMaxIntensityLevels in all).
inline constexpr Domain pgv_level{0.0, 100.0, false, true, "m/s"};
inline constexpr double kMaxIntensityLevels = 1'000'000;
inline constexpr Domain intensity_level_count{2.0, kMaxIntensityLevels, true, true, ""};
// A limit state's threshold: a rotation over alpha, a slide in m or a safety factor, positive.
inline constexpr Domain limit_state_threshold{0.0, std::numeric_limits<double>::infinity(), false,
                                              false, ""};
// A sampled input's distribution parameters: any number here; the distribution's support is
// checked against the input's own domain after.
inline constexpr Domain distribution_parameter{-std::numeric_limits<double>::infinity(),
                                               std::numeric_limits<double>::infinity(), true, false,
                                               ""};
// A study's samples per level and its seed (any non-negative integer).
inline constexpr Domain samples_per_level{1.0, 2147483648.0, true, true, ""};
inline constexpr Domain seed{0.0, std::numeric_limits<double>::infinity(), true, false, ""};

}  // namespace domain
}  // namespace blockfrag
