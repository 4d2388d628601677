// Spectrum configs: values and defaults as documented, the block as half_width/half_height or as
// alpha/R, the grid's axes (values, linear and log from/to/count), the canonical hash (what changes
// it and what does not), every refusal at its JSON path (all at once), the grid's rules checked
// against the scene domains before any work; and a point's scene: the pulse at omega_p =
// frequency_ratio p with amplitude amplitude_ratio tan alpha, settling, capped at the pulse's end
// plus settle_allowance_tau / p.
#include "mpi_driver/config/spectrum_config.hpp"

#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "mpi_driver/config/config_reader.hpp"

namespace blockfrag {
namespace {

using nlohmann::json;
using ::testing::HasSubstr;
using ::testing::Not;

json paper_spectrum() {
  return json::parse(R"({
    "block": {"half_width": 0.5, "half_height": 1.0},
    "contact": {"friction": 0.6, "restitution": 0.6},
    "pulse": {"type": "cosine_pulse"},
    "frequency_ratio": {"from": 0.5, "to": 4, "count": 4, "spacing": "log"},
    "amplitude_ratio": {"from": 1, "to": 3, "count": 5},
    "output": "paper.h5",
    "checkpoint_interval_s": 5})");
}

std::string spectrum_errors(const json& document) {
  try {
    parse_spectrum_config(document, "spec.json");
  } catch (const ConfigError& error) {
    return error.what();
  }
  return "(accepted)";
}

TEST(SpectrumConfig, ReadsEveryValueWithItsDefaults) {
  const SpectrumConfig config = parse_spectrum_config(paper_spectrum(), "spec.json");
  EXPECT_EQ(config.pulse, SpectrumPulse::cosine);
  EXPECT_EQ(config.cycles, 1.0);
  EXPECT_EQ(config.base_scene.contact.friction, 0.6);
  EXPECT_EQ(config.base_scene.contact.restitution, 0.6);
  EXPECT_TRUE(config.base_scene.effects.automatic);
  EXPECT_EQ(config.base_scene.solver.tolerance, 1e-8);
  EXPECT_EQ(config.bisection_tolerance, 1e-7);
  EXPECT_EQ(config.max_iterations, 60);
  EXPECT_EQ(config.minimum_overturning.tolerance, 1e-3);
  EXPECT_EQ(config.minimum_overturning.resolution, 1e-3);
  EXPECT_EQ(config.minimum_overturning.near_overturning, 0.5);
  EXPECT_EQ(config.minimum_overturning.max_midpoints, 1000);
  EXPECT_EQ(config.settle_allowance_tau, 200.0);
  EXPECT_EQ(config.output, "paper.h5");
  EXPECT_EQ(config.checkpoint_interval_s, 5.0);
  EXPECT_EQ(config.map_points(), 20);
  // The paper's block: alpha = atan(1/2), R = sqrt(1.25), p = sqrt(3 g / (4 R)).
  EXPECT_DOUBLE_EQ(config.tan_alpha(), 0.5);
  EXPECT_DOUBLE_EQ(config.alpha(), std::atan(0.5));
  EXPECT_DOUBLE_EQ(config.R(), std::sqrt(1.25));
  EXPECT_DOUBLE_EQ(config.p(), std::sqrt(3 * 9.81 / (4 * std::sqrt(1.25))));
  // Linear amplitudes, log frequencies, both ends exact.
  EXPECT_EQ(config.amplitude_ratio, (std::vector<double>{1.0, 1.5, 2.0, 2.5, 3.0}));
  ASSERT_EQ(config.frequency_ratio.size(), 4u);
  EXPECT_EQ(config.frequency_ratio.front(), 0.5);
  EXPECT_EQ(config.frequency_ratio.back(), 4.0);
  EXPECT_NEAR(config.frequency_ratio[1], 1.0, 1e-15);
  EXPECT_NEAR(config.frequency_ratio[2], 2.0, 1e-15);
}

TEST(SpectrumConfig, TakesTheBlockAsAlphaAndR) {
  json document = paper_spectrum();
  document["block"] = {{"alpha", std::atan(0.5)}, {"R", std::sqrt(1.25)}};
  const SpectrumConfig config = parse_spectrum_config(document, "spec.json");
  EXPECT_NEAR(config.base_scene.block.half_width, 0.5, 1e-15);
  EXPECT_NEAR(config.base_scene.block.half_height, 1.0, 1e-15);
  EXPECT_NEAR(config.alpha(), std::atan(0.5), 1e-15);
}

TEST(SpectrumConfig, ReadsAxisValuesAndEveryPulseFamily) {
  json document = paper_spectrum();
  document["frequency_ratio"] = {{"values", {0.7}}};
  document["amplitude_ratio"] = {{"values", {1.1, 1.2, 5}}};
  for (const char* type :
       {"cosine_pulse", "sine_pulse", "rectangular_pulse", "makris_a", "makris_b", "ricker"}) {
    document["pulse"] = {{"type", type}};
    const SpectrumConfig config = parse_spectrum_config(document, "spec.json");
    EXPECT_STREQ(spectrum_pulse_name(config.pulse), type);
    EXPECT_EQ(config.frequency_ratio, (std::vector<double>{0.7}));
    EXPECT_EQ(config.amplitude_ratio, (std::vector<double>{1.1, 1.2, 5.0}));
  }
  document["pulse"] = {{"type", "makris_c"}, {"n", 2}};
  EXPECT_EQ(parse_spectrum_config(document, "spec.json").makris_n, 2);
  document["pulse"] = {{"type", "sine_pulse"}, {"cycles", 2.5}};
  EXPECT_EQ(parse_spectrum_config(document, "spec.json").cycles, 2.5);
}

TEST(SpectrumConfig, HashCoversWhatChangesAResultOnly) {
  const SpectrumConfig base = parse_spectrum_config(paper_spectrum(), "spec.json");
  json moved = paper_spectrum();
  moved["output"] = "elsewhere.h5";
  moved["checkpoint_interval_s"] = 99;
  EXPECT_EQ(parse_spectrum_config(moved, "spec.json").hash, base.hash);
  EXPECT_EQ(parse_spectrum_config(paper_spectrum(), "spec.json", "other.h5").hash, base.hash);
  for (const auto& [pointer, value] : std::vector<std::pair<std::string, json>>{
           {"/contact/restitution", 0.5},
           {"/amplitude_ratio/count", 6},
           {"/frequency_ratio/spacing", "linear"},
           {"/bisection", {{"tolerance", 1e-6}}},
           {"/minimum_overturning", {{"tolerance", 1e-4}}},
           {"/minimum_overturning", {{"near_overturning", 0.7}}},
           {"/settle_allowance_tau", 100},
           {"/effects", {"rocking", "impact"}},
           {"/pulse/cycles", 2}}) {
    json changed = paper_spectrum();
    changed[JsonPointer(pointer)] = value;
    EXPECT_NE(parse_spectrum_config(changed, "spec.json").hash, base.hash) << pointer;
  }
  // The refinement's defaults written out hash as a spec without the key does (a spec of before
  // the key existed), so its checkpoints resume.
  json defaults = paper_spectrum();
  defaults["minimum_overturning"] = {{"tolerance", 1e-3}, {"max_midpoints", 1000}};
  EXPECT_EQ(parse_spectrum_config(defaults, "spec.json").hash, base.hash);
  // The canonical config has every default written out.
  EXPECT_EQ(base.canonical["bisection"]["max_iterations"], 60);
  EXPECT_EQ(base.canonical["minimum_overturning"]["near_overturning"], 0.5);
  EXPECT_EQ(base.canonical["block"]["mass"], 1.0);
  EXPECT_EQ(base.canonical["pulse"]["cycles"], 1.0);
  EXPECT_EQ(base.canonical["solver"]["method"], "adaptive");
}

TEST(SpectrumConfig, ReportsEveryErrorAtItsPath) {
  json document = paper_spectrum();
  document["contact"]["friction"] = -1;
  document["pulse"]["amplitude_g"] = 2;
  document["amplitude_ratio"]["to"] = 0.5;
  document["bisection"] = {{"tolerance", 0}, {"max_iterations", 1000}};
  document["settle_alowance_tau"] = 10;
  document["minimum_overturning"] = {{"tolerance", 0.5},
                                     {"resolution", 0},
                                     {"near_overturning", -0.1},
                                     {"max_midpoints", 0},
                                     {"tolerence", 1e-3}};
  const std::string errors = spectrum_errors(document);
  EXPECT_THAT(errors, HasSubstr("spec.json: /contact/friction: must be in [0, 10000] (got -1)"));
  EXPECT_THAT(errors, HasSubstr("spec.json: /pulse/amplitude_g: is set at each point of the grid"));
  EXPECT_THAT(errors, HasSubstr("spec.json: /amplitude_ratio/to: must be greater than from (1)"));
  EXPECT_THAT(errors, HasSubstr("spec.json: /bisection/tolerance: must be in [1e-14, 0.1]"));
  EXPECT_THAT(errors, HasSubstr("spec.json: /bisection/max_iterations: must be in [1, 200]"));
  EXPECT_THAT(errors, HasSubstr("spec.json: /settle_alowance_tau: unknown key"));
  EXPECT_THAT(errors,
              HasSubstr("spec.json: /minimum_overturning/tolerance: must be in [1e-09, 0.1]"));
  EXPECT_THAT(errors,
              HasSubstr("spec.json: /minimum_overturning/resolution: must be in [1e-09, 0.1]"));
  EXPECT_THAT(errors,
              HasSubstr("spec.json: /minimum_overturning/near_overturning: must be in [0, 1]"));
  EXPECT_THAT(errors,
              HasSubstr("spec.json: /minimum_overturning/max_midpoints: must be in [1, 100000]"));
  EXPECT_THAT(errors, HasSubstr("spec.json: /minimum_overturning/tolerence: unknown key; did you "
                                "mean \"tolerance\"?"));
}

TEST(SpectrumConfig, RefusesBlocksItCannotMap) {
  json document = paper_spectrum();
  document["block"] = {{"polygon", {{0, 0}, {1, 0}, {1, 2}, {0, 2}}}};
  EXPECT_THAT(spectrum_errors(document),
              HasSubstr("spec.json: /block: a spectrum is of a rectangular"));
  document["block"] = {{"alpha", 0.4}, {"R", 1}, {"half_width", 0.5}};
  EXPECT_THAT(spectrum_errors(document),
              HasSubstr("/block/half_width: give the block as alpha and R, or as half_width"));
  document["block"] = {{"alpha", 2}, {"R", 1}};
  EXPECT_THAT(spectrum_errors(document), HasSubstr("/block/alpha: must be in (0, pi/2)"));
  // Sizes out of their domain are reported once, at the keys the file has: not again at
  // /block/half_width, which the file does not have.
  document["block"] = {{"alpha", 1e-300}, {"R", 1}};
  EXPECT_EQ(spectrum_errors(document),
            "spec.json: /block/R: with this alpha gives the half_width 1e-300 m, which must be in "
            "[1e-04, 10000] m");
  document["block"] = {{"alpha", 1e-9}, {"R", 1}};
  EXPECT_THAT(spectrum_errors(document),
              HasSubstr("/block/R: with this alpha gives the half_width 1e-09 m"));
  EXPECT_THAT(spectrum_errors(document), Not(HasSubstr("/block/half_width")));
  document.erase("block");
  EXPECT_THAT(spectrum_errors(document), HasSubstr("spec.json: /block: "));
}

TEST(SpectrumConfig, RefusesAxesItCannotRun) {
  json document = paper_spectrum();
  document["frequency_ratio"] = {{"values", {1, 0.5}}};
  EXPECT_THAT(spectrum_errors(document),
              HasSubstr("/frequency_ratio/values/1: must be greater than the value before it"));
  document["frequency_ratio"] = {{"values", json::array()}};
  EXPECT_THAT(spectrum_errors(document),
              HasSubstr("/frequency_ratio/values: must have 1 to 100000"));
  document["frequency_ratio"] = {{"values", {1}}, {"from", 1}};
  EXPECT_THAT(spectrum_errors(document), HasSubstr("/frequency_ratio/from: give either values or"));
  document["frequency_ratio"] = paper_spectrum()["frequency_ratio"];
  document["amplitude_ratio"] = {{"values", {1}}};
  EXPECT_THAT(spectrum_errors(document),
              HasSubstr("/amplitude_ratio/values: must have 2 to 100000"));
  document["amplitude_ratio"] = {{"from", 1}, {"to", 1 + 1e-15}, {"count", 100}};
  EXPECT_THAT(spectrum_errors(document),
              HasSubstr("/amplitude_ratio/count: is too large for the range"));
  document["amplitude_ratio"] = {{"from", 1}, {"to", 2}, {"count", 3000}};
  document["frequency_ratio"] = {{"from", 1}, {"to", 2}, {"count", 3000}};
  EXPECT_THAT(spectrum_errors(document),
              HasSubstr("/amplitude_ratio: the grid has 9000000 points (3000 x 3000), more than "
                        "4000000"));
}

TEST(SpectrumConfig, RefusesAGridOutsideTheSceneDomains) {
  json document = paper_spectrum();
  // p = 2.5653 rad/s: omega_p / p = 5000 is a period of 0.49 ms, 1e-4 one of 24,500 s.
  document["frequency_ratio"] = {{"from", 1e-4}, {"to", 5000}, {"count", 3}};
  document["amplitude_ratio"]["to"] = 4000;  // 2000 g at tan alpha = 0.5
  const std::string errors = spectrum_errors(document);
  EXPECT_THAT(errors, HasSubstr("/frequency_ratio/to: gives a pulse period of 0.00048"));
  EXPECT_THAT(errors, HasSubstr("/frequency_ratio/from: gives a pulse period of 2449"));
  EXPECT_THAT(errors, HasSubstr("must be in [0.001, 1000] s"));
  EXPECT_THAT(errors, HasSubstr("/amplitude_ratio/to: gives an amplitude of 2000 g"));
  // The settling cap: a long pulse and a long allowance past 1e5 s.
  document = paper_spectrum();
  document["frequency_ratio"] = {{"values", {0.01}}};
  document["settle_allowance_tau"] = 1e6;
  EXPECT_THAT(spectrum_errors(document),
              HasSubstr("/frequency_ratio/values/0: with "
                        "settle_allowance_tau, the longest run would last"));
}

TEST(SpectrumConfig, PointSceneIsThePulseAtItsRatios) {
  const SpectrumConfig config = parse_spectrum_config(paper_spectrum(), "spec.json");
  const double p = config.p();
  const Scene scene = spectrum_scene(config, 2.0, 3.0);
  const auto& pulse = std::get<CosinePulse>(scene.ground_motion);
  EXPECT_DOUBLE_EQ(pulse.amplitude_g, 1.5);
  EXPECT_DOUBLE_EQ(pulse.period, 2 * std::numbers::pi / (2.0 * p));
  EXPECT_EQ(pulse.cycles, 1.0);
  EXPECT_FALSE(scene.duration.has_value());
  EXPECT_DOUBLE_EQ(*scene.max_duration, pulse.period + 200.0 / p);

  json document = paper_spectrum();
  document["pulse"] = {{"type", "rectangular_pulse"}};
  const SpectrumConfig rectangular = parse_spectrum_config(document, "spec.json");
  // omega_p / p = pi is p t1 = 1.
  const Scene rectangular_scene = spectrum_scene(rectangular, std::numbers::pi, 1.0);
  const auto& step = std::get<RectangularPulse>(rectangular_scene.ground_motion);
  EXPECT_DOUBLE_EQ(step.duration * p, 1.0);
  EXPECT_DOUBLE_EQ(step.amplitude_g, 0.5);
  document["pulse"] = {{"type", "ricker"}};
  const Scene ricker = spectrum_scene(parse_spectrum_config(document, "spec.json"), 1.0, 1.0);
  const double tp = std::get<RickerWavelet>(ricker.ground_motion).period;
  EXPECT_DOUBLE_EQ(*ricker.max_duration, 3 * tp + 200.0 / p);  // the window is 2 t0 = 3 Tp
}

// The specs of tests/data/spectrum_specs (the spectrum spec fuzzer's seeds beside configs/) read,
// and read back from their canonical configs to the same hash: each family, axis form and block
// form a seed stands for.
TEST(SpectrumConfig, TheSeedSpecsReadAndRoundTrip) {
  const std::filesystem::path folder =
      std::filesystem::path(BLOCKFRAG_SOURCE_DIR) / "tests/data/spectrum_specs";
  int specs = 0;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    const SpectrumConfig config = read_spectrum_config(entry.path());
    const SpectrumConfig again = parse_spectrum_config(config.canonical, entry.path().string());
    EXPECT_EQ(again.hash, config.hash) << entry.path();
    EXPECT_EQ(again.canonical, config.canonical) << entry.path();
    ++specs;
  }
  EXPECT_EQ(specs, 4);
  const SpectrumConfig values = read_spectrum_config(folder / "alpha_r_sine_values.json");
  EXPECT_EQ(values.pulse, SpectrumPulse::sine);
  EXPECT_EQ(values.frequency_ratio, (std::vector<double>{1.5, 2.0, 3.5}));
  EXPECT_NEAR(values.alpha(), 0.25, 1e-15);
  EXPECT_EQ(read_spectrum_config(folder / "makris_c_gsl.json").makris_n, 2);
}

}  // namespace
}  // namespace blockfrag
