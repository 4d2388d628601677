// The minimum overturning amplitude's refinement with the engine, against a brute-force scan made
// in the test itself. A slender block (alpha = 0.25 rad, R = 1 m, Housner's rocking block) under a
// one-sine pulse at omega_p / p = 1 overturns in a band [1.1066, 1.1130] of amplitude ratio, well
// below the onset the map finds from 1.131 on; a map whose step is wider than the band steps over
// it. Every amplitude ratio from 1.0 (below it the pulse cannot tip the block) to the map's
// standing point above the band, 1e-4 apart, gives the first overturning amplitude the refined
// minimum must match, to its tolerance and the scan's step.
//
// Zhang & Makris (2001) tell two ways a block overturns under a cycloidal pulse: after impacts, and
// without any impact, the latter from a threshold a linearised (slender) block gives in closed form
// (docs/references.md, "Overturning thresholds under pulses"). A block of alpha = 0.02 rad, where
// the linearisation is good to its order alpha^2, overturns with no impact from the closed form's
// amplitude on, to 1e-3, under one-sine and one-cosine pulses at omega_p / p = 1, 2 and 3.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "engine/simulate.hpp"
#include "mpi_driver/config/spectrum_config.hpp"
#include "tests/support/spectrum_serial.hpp"

namespace blockfrag {
namespace {

using nlohmann::json;

TEST(MinimumOverturningValidation, FindsTheOneSineBandTheMapStepsOver) {
  // The map's amplitudes: 1.104 stands 0.0026 below the band (max |theta| / alpha 0.74 there),
  // 1.12 stands above it, 1.16 overturns.
  const SpectrumConfig config = parse_spectrum_config(json::parse(R"({
    "block": {"alpha": 0.25, "R": 1.0},
    "contact": {"friction": 10, "restitution": 0},
    "effects": ["rocking", "impact"],
    "pulse": {"type": "sine_pulse"},
    "frequency_ratio": {"values": [1.0]},
    "amplitude_ratio": {"values": [1.0, 1.04, 1.08, 1.104, 1.12, 1.16, 1.2]}})"),
                                                      "sine.json");
  const testing::SerialSpectrum spectrum = testing::serial_spectrum(config);
  const std::vector<FrequencyMinimum> minima = testing::serial_minima(config, spectrum);
  ASSERT_EQ(minima.size(), 1u);
  const FrequencyMinimum& refined = minima[0];
  ASSERT_FALSE(spectrum.brackets.empty());
  const double map_minimum = spectrum.brackets.front().midpoint();
  EXPECT_EQ(spectrum.brackets.front().direction(), +1);

  // The scan: the first amplitude that overturns, and the last that stands below it.
  const double step = 1e-4;
  double last_standing = 0.0, first_overturning = 0.0;
  for (int k = 0; 1.0 + k * step <= 1.12; ++k) {
    const double a = 1.0 + k * step;
    const Summary summary = simulate(spectrum_scene(config, 1.0, a));
    if (summary.overturned) {
      first_overturning = a;
      break;
    }
    last_standing = a;
  }
  ASSERT_GT(first_overturning, 1.1) << "the scan found no band below the map's onset";
  // The map misses it by more than 2 per cent; the refinement finds it.
  EXPECT_GT(map_minimum, 1.02 * first_overturning);
  EXPECT_EQ(refined.state, static_cast<std::int64_t>(MinimumState::found));
  EXPECT_TRUE(overturned(static_cast<SpectrumVerdict>(refined.verdict_high)));
  EXPECT_LE(refined.high - refined.low, config.minimum_overturning.tolerance * refined.high);
  // Both brackets hold the edge: [last_standing, first_overturning] and [low, high].
  EXPECT_LT(refined.low, first_overturning);
  EXPECT_GT(refined.high, last_standing);
  EXPECT_NEAR(refined.amplitude_ratio, 0.5 * (last_standing + first_overturning),
              0.5 * config.minimum_overturning.tolerance * refined.high + step);
}

// Overturns on its first swing, before any impact.
bool overturns_without_impact(const SpectrumConfig& config, double amplitude_ratio) {
  const Summary summary =
      simulate(spectrum_scene(config, config.frequency_ratio[0], amplitude_ratio));
  return summary.overturned && summary.impacts == 0;
}

TEST(MinimumOverturningValidation, NoImpactOverturningOfASlenderBlockIsTheLinearisedClosedForm) {
  struct Case {
    const char* pulse;
    double frequency_ratio, closed_form;
  };
  // psi = (1 + W^2) / (1 - exp(-2 pi / W)) for the cosine; sqrt(psi^2 - 1) - psi exp(-(2 pi -
  // asin(1 / psi)) / W) = W for the sine.
  for (const Case c : {Case{"cosine_pulse", 1, 2.00374}, Case{"cosine_pulse", 2, 5.22583},
                       Case{"cosine_pulse", 3, 11.40439}, Case{"sine_pulse", 1, 1.41832},
                       Case{"sine_pulse", 2, 2.34990}, Case{"sine_pulse", 3, 3.63115}}) {
    json document = json::parse(R"({
      "block": {"alpha": 0.02, "R": 1.0},
      "contact": {"friction": 10, "restitution": 0},
      "effects": ["rocking", "impact"],
      "amplitude_ratio": {"values": [1.0, 2.0]}})");
    document["pulse"] = {{"type", c.pulse}};
    document["frequency_ratio"] = {{"values", {c.frequency_ratio}}};
    const SpectrumConfig config = parse_spectrum_config(document, "modes.json");
    double low = 0.97 * c.closed_form, high = 1.03 * c.closed_form;
    ASSERT_FALSE(overturns_without_impact(config, low)) << c.pulse << " " << c.frequency_ratio;
    ASSERT_TRUE(overturns_without_impact(config, high)) << c.pulse << " " << c.frequency_ratio;
    while (high - low > 1e-5 * high) {
      const double middle = 0.5 * (low + high);
      (overturns_without_impact(config, middle) ? high : low) = middle;
    }
    EXPECT_NEAR(high / c.closed_form, 1.0, 1e-3) << c.pulse << " " << c.frequency_ratio;
  }
}

}  // namespace
}  // namespace blockfrag
