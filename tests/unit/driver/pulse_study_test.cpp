// A study scales a Mavroeidis-Papageorgiou pulse, which is given by its ground velocity, so that
// its peak |lambda| (its PGA in g) is the intensity level, with the sign of the direction input.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <variant>

#include <gtest/gtest.h>

#include "engine/motion/ground_motion.hpp"
#include "mpi_driver/config/study_config.hpp"
#include "mpi_driver/study/study_sample.hpp"

namespace blockfrag {
namespace {

// max |lambda| on a grid of 1e5 points: an estimate independent of the engine's extrema.
double scanned_peak(GroundMotionPieces& motion, double end) {
  double peak = 0.0;
  for (int i = 0; i <= 100000; ++i)
    peak = std::max(peak, std::abs(motion.lambda(end * i / 100000.0)));
  return peak;
}

// A study of a Mavroeidis-Papageorgiou pulse (g = 9.7) at PGA levels, in either direction.
StudyConfig mavroeidis_study(double direction) {
  const nlohmann::json document = {
      {"scene",
       {{"block", {{"half_width", 0.5}, {"half_height", 1.0}}},
        {"contact", {{"friction", 0.6}, {"restitution", 0.6}}},
        {"ground_motion",
         {{"type", "mavroeidis_papageorgiou"},
          {"velocity_amplitude", -0.5},
          {"period", 0.8},
          {"gamma", 2.5},
          {"phase", 0.4}}},
        {"g", 9.7},
        {"duration", 2.0}}},
      {"inputs", {{"direction", {{"distribution", "fixed"}, {"value", direction}}}}},
      {"intensity_measure", {{"type", "pga"}, {"levels", {0.3, 0.45}}}},
      {"samples_per_level", 1},
      {"limit_states", {{{"name", "overturn"}, {"type", "overturning"}}}},
      {"seed", 1}};
  return parse_study_config(document, "study.json");
}

TEST(PulseStudy, MavroeidisPapageorgiouIsScaledToItsPeakAcceleration) {
  for (const double direction : {1.0, -1.0}) {
    const StudyConfig config = mavroeidis_study(direction);
    StudySampler sampler(config);
    for (const std::int64_t index : {0, 1}) {
      const StudySample sample = sampler.draw(index);
      const double level = config.intensity.levels[static_cast<std::size_t>(index)];
      EXPECT_EQ(sample.im, level);
      const auto& pulse = std::get<MavroeidisPapageorgiouPulse>(sample.scene.ground_motion);
      EXPECT_EQ(pulse.velocity_amplitude > 0,
                direction > 0);  // the direction's sign, not the base's
      EXPECT_EQ(pulse.gamma, 2.5);
      GroundMotionPieces motion(sample.scene.ground_motion, sample.scene.g);
      EXPECT_NEAR(scanned_peak(motion, 2.0), level, 1e-7 * level);
      EXPECT_NEAR(motion.peak_abs_lambda(), level, 1e-14);
    }
  }
}

// Given by its velocity, the Mavroeidis-Papageorgiou pulse has no amplitude in g: its levels are
// of its PGA unless the study names another measure, and "pulse_amplitude" is refused.
TEST(PulseStudy, MavroeidisPapageorgiouLevelsAreOfItsPgaByDefault) {
  nlohmann::json document = {{"scene",
                              {{"block", {{"half_width", 0.5}, {"half_height", 1.0}}},
                               {"contact", {{"friction", 0.6}, {"restitution", 0.6}}},
                               {"ground_motion",
                                {{"type", "mavroeidis_papageorgiou"},
                                 {"velocity_amplitude", 0.5},
                                 {"period", 0.8},
                                 {"gamma", 2.5}}},
                               {"duration", 2.0}}},
                             {"intensity_measure", {{"levels", {0.3}}}},
                             {"samples_per_level", 1},
                             {"limit_states", {{{"name", "overturn"}, {"type", "overturning"}}}},
                             {"seed", 1}};
  EXPECT_EQ(parse_study_config(document, "study.json").intensity.type, ImType::pga);
  document["intensity_measure"]["type"] = "pulse_amplitude";
  try {
    parse_study_config(document, "study.json");
    ADD_FAILURE() << "accepted";
  } catch (const ConfigError& error) {
    ASSERT_EQ(error.messages().size(), 1u);
    EXPECT_EQ(error.messages()[0].rfind(
                  "study.json: /intensity_measure/type: a Mavroeidis-Papageorgiou", 0),
              0u)
        << error.messages()[0];
  }
}

// One cycle of lambda = A cos(2 pi t / T) moves the ground at most A g T / (2 pi)
// (docs/references.md: the velocity is A g T / (2 pi) sin(2 pi t / T)): at PGV stripes the
// amplitude is the level times 2 pi / (g T), for each sample's own period.
TEST(PulseStudy, PgvStripesScaleEachPulseByItsOwnPeriod) {
  const nlohmann::json document = {
      {"scene",
       {{"block", {{"half_width", 0.5}, {"half_height", 1.0}}},
        {"contact", {{"friction", 0.6}, {"restitution", 0.6}}},
        {"ground_motion", {{"type", "cosine_pulse"}, {"amplitude_g", 1.0}, {"period", 1.0}}}}},
      {"inputs",
       {{"period", {{"distribution", "uniform"}, {"min", 0.5}, {"max", 2.0}}},
        {"direction", {{"distribution", "random_sign"}}}}},
      {"intensity_measure", {{"type", "pgv"}, {"levels", {0.1, 0.4}}}},
      {"samples_per_level", 5},
      {"limit_states", {{{"name", "overturn"}, {"type", "overturning"}}}},
      {"seed", 3}};
  const StudyConfig config = parse_study_config(document, "study.json");
  StudySampler sampler(config);
  for (std::int64_t i = 0; i < config.total_samples(); ++i) {
    const StudySample sample = sampler.draw(i, true);
    const auto& pulse = std::get<CosinePulse>(sample.scene.ground_motion);
    const double expected = sample.im * 2 * std::numbers::pi / (9.81 * pulse.period);
    EXPECT_NEAR(std::abs(pulse.amplitude_g), expected, 1e-12 * expected) << i;
    EXPECT_EQ(pulse.amplitude_g > 0, sample.values[1] > 0);  // direction
    EXPECT_NEAR(sample.pgv_m_s, sample.im, 1e-12 * sample.im);
    EXPECT_NEAR(sample.pga_g, std::abs(pulse.amplitude_g), 1e-14);
  }
}

}  // namespace
}  // namespace blockfrag
