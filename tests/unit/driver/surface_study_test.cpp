// Studies over a grid of two measures (a fragility surface): the second axis as read, its place in
// the canonical config (only a surface has it), the map from a sample to its cell and the cell's
// period and amplitude, the counts per cell against hand-counted records, and every refused
// combination at its JSON path.
#include <cmath>
#include <string>
#include <variant>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "mpi_driver/config/config_reader.hpp"
#include "mpi_driver/config/study_config.hpp"
#include "mpi_driver/study/fragility_tally.hpp"
#include "mpi_driver/study/study_sample.hpp"

namespace blockfrag {
namespace {

using nlohmann::json;
using ::testing::HasSubstr;

json surface_study() {
  return json::parse(R"({
    "scene": {
      "block": {"half_width": 0.5, "half_height": 1.0},
      "contact": {"friction": 0.7, "restitution": 0.7},
      "ground_motion": {"type": "cosine_pulse", "amplitude_g": 1.0, "period": 1.0},
      "duration": 2.0},
    "inputs": {
      "friction": {"distribution": "uniform", "min": 0.55, "max": 0.9},
      "direction": {"distribution": "random_sign"}},
    "intensity_measure": {"levels": [0.3, 0.6, 0.9, 1.2],
                          "second": {"type": "pulse_period", "levels": [0.5, 1.0, 2.0]}},
    "samples_per_level": 5,
    "design": "latin_hypercube",
    "limit_states": [{"name": "overturn", "type": "overturning"}],
    "seed": 42})");
}

std::string all_errors(const json& document) {
  try {
    parse_study_config(document, "study.json");
  } catch (const ConfigError& error) {
    std::string all;
    for (const auto& message : error.messages()) all += message + "\n";
    return all;
  }
  return {};
}

TEST(SurfaceStudy, ReadsTheGridAndPutsItInTheCanonicalConfig) {
  const StudyConfig config = parse_study_config(surface_study(), "study.json");
  EXPECT_EQ(config.intensity.levels, (std::vector<double>{0.3, 0.6, 0.9, 1.2}));
  EXPECT_EQ(config.intensity.periods, (std::vector<double>{0.5, 1.0, 2.0}));
  EXPECT_TRUE(config.intensity.surface());
  EXPECT_EQ(config.intensity.level_count(), 12u);
  EXPECT_EQ(config.total_samples(), 60);
  EXPECT_EQ(config.canonical["intensity_measure"]["second"],
            json::parse(R"({"type": "pulse_period", "levels": [0.5, 1.0, 2.0]})"));
  // from/to/count as for the first axis; a different grid is a different study.
  json counted = surface_study();
  counted["intensity_measure"]["second"] = {
      {"type", "pulse_period"}, {"from", 0.5}, {"to", 2.0}, {"count", 4}};
  const StudyConfig other = parse_study_config(counted, "study.json");
  EXPECT_EQ(other.intensity.periods, (std::vector<double>{0.5, 1.0, 1.5, 2.0}));
  EXPECT_NE(other.hash, config.hash);
  // A study of one measure has no "second" key: its canonical config and hash are as before.
  json one = surface_study();
  one["intensity_measure"].erase("second");
  const StudyConfig single = parse_study_config(one, "study.json");
  EXPECT_FALSE(single.intensity.surface());
  EXPECT_FALSE(single.canonical["intensity_measure"].contains("second"));
  EXPECT_EQ(single.intensity.level_count(), 4u);
}

TEST(SurfaceStudy, EachSampleRunsItsCellsAmplitudeAndPeriod) {
  const StudyConfig config = parse_study_config(surface_study(), "study.json");
  StudySampler sampler(config);
  StudySampler backwards(config);
  for (std::int64_t i = 0; i < config.total_samples(); ++i) {
    const StudySample sample = sampler.draw(i, true);
    const auto cell = static_cast<std::size_t>(i / 5);
    EXPECT_EQ(sample.level, cell);
    EXPECT_EQ(sample.im, config.intensity.levels[cell / 3]) << i;
    EXPECT_EQ(sample.im2, config.intensity.periods[cell % 3]) << i;
    const auto& pulse = std::get<CosinePulse>(sample.scene.ground_motion);
    EXPECT_EQ(pulse.period, sample.im2) << i;
    EXPECT_EQ(std::abs(pulse.amplitude_g), sample.im) << i;
    // PGV/PGA of a cosine pulse is proportional to its period: g T / (2 pi) for one cycle from
    // rest (its velocity peaks at a quarter period).
    EXPECT_NEAR(sample.pgv_m_s / (sample.pga_g * sample.scene.g), sample.im2 / (2 * M_PI), 1e-9);
    // Any order of draws gives the same sample.
    const StudySample again = backwards.draw(config.total_samples() - 1 - i);
    const StudySample mirror = sampler.draw(config.total_samples() - 1 - i);
    EXPECT_EQ(again.values, mirror.values);
    EXPECT_EQ(again.im2, mirror.im2);
  }
}

TEST(SurfaceStudy, CountsEachCellAndSumsThemOverThePeriodsForTheCurve) {
  const StudyConfig config = parse_study_config(surface_study(), "study.json");
  FragilityTally tally(config);
  std::vector<std::int64_t> cell_hits(12, 0), cell_trials(12, 0);
  for (std::int64_t i = 0; i < config.total_samples(); ++i) {
    SampleRecord record;
    record.index = i;
    // A pattern that rises with both amplitude and period, with a failed sample in cell 7.
    const auto cell = static_cast<std::size_t>(i / 5);
    record.status = i == 37 ? static_cast<std::int64_t>(SampleStatus::failed)
                            : static_cast<std::int64_t>(SampleStatus::ok);
    record.overturned =
        static_cast<std::int64_t>((i % 5) < static_cast<std::int64_t>(cell / 3 + cell % 3));
    if (record.status == 0) {
      ++cell_trials[cell];
      cell_hits[cell] += record.overturned;
    }
    tally.add(record, 0.46, config.intensity.levels[cell / 3]);
  }
  const StudyFragility fragility = tally.finish();
  ASSERT_EQ(fragility.surfaces.size(), 1u);
  const SurfaceGrid& grid = fragility.surfaces[0];
  EXPECT_EQ(grid.trials, cell_trials);
  EXPECT_EQ(grid.exceedances, cell_hits);
  EXPECT_EQ(grid.im2, config.intensity.periods);
  const FragilityCurve& curve = fragility.curves[0];
  ASSERT_EQ(curve.trials.size(), 4u);
  for (std::size_t k1 = 0; k1 < 4; ++k1) {
    EXPECT_EQ(curve.trials[k1],
              cell_trials[3 * k1] + cell_trials[3 * k1 + 1] + cell_trials[3 * k1 + 2]);
    EXPECT_EQ(curve.exceedances[k1],
              cell_hits[3 * k1] + cell_hits[3 * k1 + 1] + cell_hits[3 * k1 + 2]);
  }
  EXPECT_EQ(grid.fit.status, SurfaceFitStatus::ok);
}

TEST(SurfaceStudy, RefusesEveryBadCombinationAtItsPath) {
  json with_period = surface_study();
  with_period["inputs"]["period"] = {{"distribution", "uniform"}, {"min", 0.5}, {"max", 2.0}};
  EXPECT_THAT(all_errors(with_period),
              HasSubstr("study.json: /inputs/period: draws the pulse's period, which "
                        "/intensity_measure/second sets"));

  json cloud = surface_study();
  cloud["intensity_measure"] = json::parse(
      R"({"type": "pga", "scaling": "none", "second": {"type": "pulse_period", "levels": [1]}})");
  EXPECT_THAT(all_errors(cloud), HasSubstr("study.json: /intensity_measure/second/type: makes a "
                                           "grid of stripes: a cloud"));

  json ricker = surface_study();
  ricker["scene"]["ground_motion"] = {{"type", "ricker"}, {"amplitude_g", 1.0}, {"period", 1.0}};
  EXPECT_THAT(all_errors(ricker), HasSubstr("study.json: /intensity_measure/second: sets the "
                                            "pulse's period: it needs a cosine_pulse"));

  json adaptive = surface_study();
  adaptive["design"] = {{"adaptive", json::object()}};
  EXPECT_THAT(all_errors(adaptive), HasSubstr("study.json: /design/adaptive: places stripes of one "
                                              "measure: a surface's grid"));

  json too_many = surface_study();
  too_many["intensity_measure"]["from"] = 0.1;
  too_many["intensity_measure"]["to"] = 2.0;
  too_many["intensity_measure"]["count"] = 50;
  too_many["intensity_measure"].erase("levels");
  too_many["intensity_measure"]["second"] = {
      {"type", "pulse_period"}, {"from", 0.2}, {"to", 4.0}, {"count", 21}};
  EXPECT_THAT(all_errors(too_many),
              HasSubstr("study.json: /intensity_measure/second/count: makes a grid of 50 x 21 = "
                        "1050 cells, more than 1000"));

  json bad_levels = surface_study();
  bad_levels["intensity_measure"]["second"] = {{"type", "period"}, {"levels", {2.0, -1.0}}};
  const std::string errors = all_errors(bad_levels);
  EXPECT_THAT(errors, HasSubstr("study.json: /intensity_measure/second/type: must be one of"));
  EXPECT_THAT(errors, HasSubstr("study.json: /intensity_measure/second/levels/1: must be in"));

  json stray = surface_study();
  stray["intensity_measure"]["second"]["scale"] = 2;
  EXPECT_THAT(all_errors(stray),
              HasSubstr("study.json: /intensity_measure/second/scale: unknown key"));
}

TEST(SurfaceStudy, RefusesRecords) {
  json document = surface_study();
  document["scene"]["ground_motion"] = {{"type", "record"}, {"file", "decaying_sine.AT2"}};
  document["intensity_measure"]["type"] = "pga";
  const std::string source = std::string(BLOCKFRAG_SOURCE_DIR) + "/tests/data/records/study.json";
  try {
    parse_study_config(document, source);
    FAIL() << "a record study with a period axis was accepted";
  } catch (const ConfigError& error) {
    std::string all;
    for (const auto& message : error.messages()) all += message + "\n";
    EXPECT_THAT(all, HasSubstr("/intensity_measure/second: sets the pulse's period, but "
                               "/scene/ground_motion is a record"));
  }
}

}  // namespace
}  // namespace blockfrag
