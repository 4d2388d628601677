// An overturning spectrum (`blockfrag spectrum SPEC.json`): one rectangular block under one pulse
// family, mapped over a grid of frequency ratio omega_p / p and amplitude ratio a_p / (g tan alpha)
// (p^2 = M g R / I_O = 3 g / (4 R) for a rectangle), and the boundaries of the overturning region
// found by bisection along each frequency. The form (docs/spectra.md has every key):
//   {"block": {"half_width": 0.5, "half_height": 1.0}  or  {"alpha": 0.4636, "R": 1.118},
//    "contact": {"friction": 0.6, "restitution": 0.6},
//    "effects": "auto"  or  ["rocking", "impact"] (a scene's effects),
//    "pulse": {"type": "cosine_pulse", "cycles": 1},
//    "frequency_ratio": {"from": 0.5, "to": 20, "count": 400, "spacing": "log"} or {"values":
//    [...]}, "amplitude_ratio": {"from": 0.5, "to": 10, "count": 400}, "bisection": {"tolerance":
//    1e-7, "max_iterations": 60}, "minimum_overturning": {"tolerance": 1e-3, ...},
//    "settle_allowance_tau": 200, "solver": {...}, "g": 9.81, "output": "spectrum.h5",
//    "checkpoint_interval_s": 60}
// Every error names its JSON path, all are reported at once, and every rule (the pulse periods and
// amplitudes the grid asks for inside the scene domains, the grid's size) is checked before any
// work starts.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/scene/scene.hpp"
#include "mpi_driver/config/minimum_overturning_json.hpp"

namespace blockfrag {

// The pulse families a spectrum maps; each is zero outside its window and peaks at its amplitude.
enum class SpectrumPulse { cosine, sine, rectangular, makris_a, makris_b, makris_c, ricker };

// The scene's "type" name of the family ("cosine_pulse", "ricker", ...).
const char* spectrum_pulse_name(SpectrumPulse pulse);

// Verdict codes of the map and the bisection, as stored in the output's /map/verdict.
enum class SpectrumVerdict : std::int64_t {
  stands = 0,                  // at rest on its base at the end, never overturned
  overturns_no_impact = 1,     // overturned before any impact
  overturns_one_impact = 2,    // overturned after exactly one impact
  overturns_more_impacts = 3,  // overturned after two impacts or more
  still_moving = 4,            // not overturned, but still moving when the run stopped at its cap
  failed = 5,                  // the engine gave up (a step or event budget spent)
  rejected = 6,                // the engine refused the scene (cannot happen for a valid config)
};

// Overturned: codes 1 to 3. The boundaries separate these from the others.
inline bool overturned(SpectrumVerdict verdict) {
  return verdict == SpectrumVerdict::overturns_no_impact ||
         verdict == SpectrumVerdict::overturns_one_impact ||
         verdict == SpectrumVerdict::overturns_more_impacts;
}
// A verdict the boundaries can use (not failed, not rejected).
inline bool decided(SpectrumVerdict verdict) {
  return verdict != SpectrumVerdict::failed && verdict != SpectrumVerdict::rejected;
}

// "0 stands, 1 overturns with no impact, ...": the meaning attribute.
std::string spectrum_verdict_meaning();

struct SpectrumConfig {
  // The block, contact, effects, g and solver of every point's scene: no ground motion, no
  // duration (the scenes settle).
  Scene base_scene;
  SpectrumPulse pulse = SpectrumPulse::cosine;
  double cycles = 1.0;                  // cosine_pulse, sine_pulse
  int makris_n = 1;                     // makris_c
  std::vector<double> frequency_ratio;  // omega_p / p, increasing
  std::vector<double> amplitude_ratio;  // a_p / (g tan alpha), increasing
  double bisection_tolerance = 1e-7;    // relative, in amplitude ratio
  int max_iterations = 60;              // bisection steps per crossing at most
  // The refinement of each frequency's minimum overturning amplitude.
  MinimumOverturningSettings minimum_overturning;
  // A run goes on at most this long after the pulse ends, in units of 1/p (tau = p t), so the cap
  // is the same for every block size.
  double settle_allowance_tau = 200.0;
  std::filesystem::path output;
  double checkpoint_interval_s = 60.0;

  nlohmann::json canonical;  // defaults filled, keys sorted
  // Of canonical without "output" and "checkpoint_interval_s", and without "minimum_overturning"
  // when it holds the defaults.
  std::uint64_t hash = 0;

  double alpha() const;      // atan(a / b), rad
  double tan_alpha() const;  // a / b
  double R() const;          // sqrt(a^2 + b^2), m
  double p() const;          // sqrt(3 g / (4 R)), rad/s
  std::int64_t map_points() const {
    return static_cast<std::int64_t>(frequency_ratio.size() * amplitude_ratio.size());
  }
};

// Caps, so that no config exhausts memory (rank 0 holds the map's verdicts and brackets); the
// bisection's own cap is domain::bisection_iterations (engine/scene/parameter_domains.hpp).
inline constexpr std::int64_t kMaxSpectrumAxis = 100'000;
inline constexpr std::int64_t kMaxSpectrumPoints = 4'000'000;

// The pulse of the family at a point: omega_p = frequency_ratio p; a period T = 2 pi / omega_p
// (a rectangular pulse lasts half of it, t1 = pi / omega_p); amplitude_g = amplitude_ratio tan
// alpha.
GroundMotion spectrum_pulse(const SpectrumConfig& config, double frequency_ratio,
                            double amplitude_ratio);
// The family's time parameter at a frequency ratio: the period T, or a rectangular pulse's length
// t1 (s).
double spectrum_pulse_time(const SpectrumConfig& config, double frequency_ratio);
// The point's scene: the base scene with the pulse, settling, capped at the pulse's end plus
// settle_allowance_tau / p.
Scene spectrum_scene(const SpectrumConfig& config, double frequency_ratio, double amplitude_ratio);

// Throws ConfigError listing every problem, each as "source: /json/pointer: rule".
SpectrumConfig parse_spectrum_config(const nlohmann::json& document, const std::string& source,
                                     const std::optional<std::filesystem::path>& output = {});
SpectrumConfig read_spectrum_config(const std::filesystem::path& path,
                                    const std::optional<std::filesystem::path>& output = {});

}  // namespace blockfrag
