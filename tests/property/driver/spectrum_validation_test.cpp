// Overturning spectra against what is known of them (docs/references.md, "Overturning
// thresholds" and "Similarity"):
// - Housner's rocking block under a rectangular pulse overturns from A / tan(alpha) = 2.564527,
//   1.583046, 1.151926 at p t1 = 0.5, 1, 2 (the nonlinear model, alpha = 26.565 deg): the bisected
//   boundary, one onset per frequency, matches to 1e-6;
// - similarity (Dimitrakopoulos & DeJong 2012): a block ten times larger with the same alpha has
//   the same dimensionless map and boundary, to 1e-6;
// - a large block's boundary falls to the static limit a_p = g tan(alpha) as the pulse gets long;
// - the paper's block (cosine pulse of 2 s, e = 0.6, mu = 0.6, full model) overturns at 0.60 to
//   0.62 g and stands at 0.63 g: a safe island above the minimum overturning amplitude.
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "mpi_driver/config/spectrum_config.hpp"
#include "tests/support/paper_block.hpp"
#include "tests/support/spectrum_serial.hpp"

namespace blockfrag {
namespace {

using nlohmann::json;
using testing::serial_spectrum;
using testing::SerialSpectrum;

using testing::pi;

SpectrumConfig spectrum_of(const json& document) {
  return parse_spectrum_config(document, "validation.json");
}

TEST(SpectrumValidation, RectangularPulseThresholdsOfHousnersBlock) {
  // omega_p / p = pi / (p t1): p t1 = 2, 1, 0.5.
  const SpectrumConfig config = spectrum_of(json::parse(R"({
    "block": {"half_width": 0.5, "half_height": 1.0},
    "contact": {"friction": 0.6, "restitution": 0.6},
    "effects": ["rocking", "impact"],
    "pulse": {"type": "rectangular_pulse"},
    "frequency_ratio": {"values": [1.5707963267948966, 3.141592653589793, 6.283185307179586]},
    "amplitude_ratio": {"values": [1.05, 2.0, 3.0]},
    "bisection": {"tolerance": 1e-9},
    "solver": {"tolerance": 1e-10}})"));
  const SerialSpectrum spectrum = serial_spectrum(config);
  const double expected[] = {1.151926, 1.583046, 2.564527};
  ASSERT_EQ(spectrum.brackets.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    const SpectrumBracket& b = spectrum.brackets[i];
    EXPECT_EQ(b.frequency_index, static_cast<std::int64_t>(i));
    EXPECT_EQ(b.direction(), +1);
    EXPECT_EQ(b.state, static_cast<std::int64_t>(BracketState::converged));
    // No impact: it overturns on its first swing.
    EXPECT_EQ(b.verdict_high, static_cast<std::int64_t>(SpectrumVerdict::overturns_no_impact));
    EXPECT_NEAR(b.midpoint(), expected[i], 1e-6) << "p t1 = " << pi / config.frequency_ratio[i];
  }
}

// The crossings of two spectra pair up: same frequency, same direction, amplitude within 1e-6.
void expect_same_boundary(const SerialSpectrum& a, const SerialSpectrum& b) {
  ASSERT_EQ(a.brackets.size(), b.brackets.size());
  for (std::size_t k = 0; k < a.brackets.size(); ++k) {
    EXPECT_EQ(a.brackets[k].frequency_index, b.brackets[k].frequency_index) << k;
    EXPECT_EQ(a.brackets[k].direction(), b.brackets[k].direction()) << k;
    EXPECT_NEAR(a.brackets[k].midpoint(), b.brackets[k].midpoint(), 1e-6) << k;
  }
}

TEST(SpectrumValidation, SimilarBlocksHaveTheSameDimensionlessSpectrum) {
  json document = json::parse(R"({
    "block": {"half_width": 0.5, "half_height": 1.0},
    "contact": {"friction": 0.6, "restitution": 0.6},
    "pulse": {"type": "cosine_pulse"},
    "frequency_ratio": {"values": [0.8, 1.6, 2.4]},
    "amplitude_ratio": {"from": 1.0, "to": 4.0, "count": 16},
    "bisection": {"tolerance": 1e-8}})");
  const SerialSpectrum small = serial_spectrum(spectrum_of(document));
  document["block"] = {{"half_width", 5.0}, {"half_height", 10.0}};
  const SerialSpectrum large = serial_spectrum(spectrum_of(document));
  EXPECT_EQ(small.map, large.map);
  expect_same_boundary(small, large);
  EXPECT_GE(small.brackets.size(), 3u);  // one onset per frequency at least
}

TEST(SpectrumValidation, LargeBlockTendsToTheStaticLimitUnderLongPulses) {
  // A 10 m x 20 m block (p = 0.81 rad/s): omega_p / p = 0.125 is a rectangular pulse of 31 s.
  const SpectrumConfig config = spectrum_of(json::parse(R"({
    "block": {"half_width": 5.0, "half_height": 10.0},
    "contact": {"friction": 0.6, "restitution": 0.6},
    "effects": ["rocking", "impact"],
    "pulse": {"type": "rectangular_pulse"},
    "frequency_ratio": {"values": [0.125, 0.25, 0.5, 1.0, 2.0]},
    "amplitude_ratio": {"values": [0.99, 1.5]},
    "bisection": {"tolerance": 1e-9}})"));
  const SerialSpectrum spectrum = serial_spectrum(config);
  ASSERT_EQ(spectrum.brackets.size(), 5u);
  for (std::size_t i = 0; i < 5; ++i) {
    const double onset = spectrum.brackets[i].midpoint();
    EXPECT_EQ(spectrum.brackets[i].direction(), +1);
    EXPECT_GE(onset, 1.0 - 1e-9);  // never below the static limit
    // The excess over the static limit falls as Housner's linearised one, 1 / (1 - exp(-p t1)) - 1
    // with p t1 = pi / (omega_p / p), does (about exp(-p t1)): within a factor, where it is larger
    // than the bisection's resolution. The nonlinear block's excess is the smaller one for long
    // pulses.
    const double linear = 1.0 / (1.0 - std::exp(-pi / config.frequency_ratio[i]));
    if (linear - 1.0 > 1e-7) {
      EXPECT_LE(onset - 1.0, 1.05 * (linear - 1.0)) << config.frequency_ratio[i];
      EXPECT_GE(onset - 1.0, 0.3 * (linear - 1.0)) << config.frequency_ratio[i];
    }
    if (i > 0) {
      EXPECT_LT(spectrum.brackets[i - 1].midpoint(), onset);  // longer pulses, lower
    }
  }
  // A pulse of 31 s overturns the block from the static limit on.
  EXPECT_NEAR(spectrum.brackets[0].midpoint(), 1.0, 1e-6);
}

TEST(SpectrumValidation, PaperBlockHasASafeIslandAtPointSixThreeG) {
  // The paper's block under a one-cycle cosine pulse of T = 2 s: omega_p / p = pi / p.
  json document = json::parse(R"({
    "block": {"half_width": 0.5, "half_height": 1.0},
    "contact": {"friction": 0.6, "restitution": 0.6},
    "pulse": {"type": "cosine_pulse"},
    "amplitude_ratio": {"from": 1.1, "to": 1.32, "count": 12},
    "bisection": {"tolerance": 1e-7}})");
  const double p = std::sqrt(3 * 9.81 / (4 * std::hypot(0.5, 1.0)));
  document["frequency_ratio"] = {{"values", {pi / p}}};
  const SpectrumConfig config = spectrum_of(document);
  EXPECT_NEAR(spectrum_pulse_time(config, config.frequency_ratio[0]), 2.0, 1e-14);
  const SerialSpectrum spectrum = serial_spectrum(config);
  // The grid is 1.1 + 0.02 k (0.55 g + 0.01 g k): it stands at 0.59 g, overturns at 0.60, 0.61
  // and 0.62 g (after many impacts and flights), stands at 0.63 g and overturns at 0.64 g.
  const auto verdict = [&](std::size_t j) { return spectrum.at(config, 0, j); };
  EXPECT_EQ(verdict(4), SpectrumVerdict::stands);
  for (const std::size_t j : {5, 6, 7})
    EXPECT_EQ(verdict(j), SpectrumVerdict::overturns_more_impacts);
  EXPECT_EQ(verdict(8), SpectrumVerdict::stands);
  EXPECT_TRUE(overturned(verdict(9)));
  ASSERT_EQ(spectrum.brackets.size(), 3u);
  const SpectrumBracket &onset = spectrum.brackets[0], &island_low = spectrum.brackets[1],
                        &island_high = spectrum.brackets[2];
  // The minimum overturning amplitude lies between 0.59 and 0.60 g.
  EXPECT_EQ(onset.direction(), +1);
  EXPECT_GT(onset.midpoint(), 1.18);
  EXPECT_LT(onset.midpoint(), 1.20);
  // Above it, a band where the block stands again contains 0.63 g (1.26) but not 0.62 or 0.64 g.
  EXPECT_EQ(island_low.direction(), -1);
  EXPECT_EQ(island_high.direction(), +1);
  EXPECT_GT(island_low.midpoint(), 1.24);
  EXPECT_LT(island_low.midpoint(), 1.26);
  EXPECT_GT(island_high.midpoint(), 1.26);
  EXPECT_LT(island_high.midpoint(), 1.28);
}

}  // namespace
}  // namespace blockfrag
