// A study of a scene with a reservoir: the pool level sampled as any input ("reservoir_level", set
// on each sample's scene), the limit state "post_earthquake_unstable" (read with its default
// threshold 1, written to the canonical form, refused without a reservoir), and its count: a block
// standing at the end whose post-earthquake safety factor (the smaller of its two) is below the
// threshold, and, unless overturned_exceeds is false, one that overturned or fell.
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "mpi_driver/config/config_reader.hpp"
#include "mpi_driver/config/study_config.hpp"
#include "mpi_driver/study/limit_states.hpp"
#include "mpi_driver/study/study_record.hpp"
#include "mpi_driver/study/study_sample.hpp"

namespace blockfrag {
namespace {

using nlohmann::json;
using ::testing::HasSubstr;

json reservoir_study() {
  return json::parse(R"({
    "scene": {
      "block": {"half_width": 0.5, "half_height": 1.0, "mass": 4800},
      "contact": {"friction": 0.7, "restitution": 0.7},
      "ground_motion": {"type": "cosine_pulse", "amplitude_g": 1.0, "period": 1.0},
      "reservoir": {"level": 1.0, "depth": 50.0},
      "duration": 2.0},
    "inputs": {
      "reservoir_level": {"distribution": "uniform", "min": -0.5, "max": 1.0},
      "friction": {"distribution": "uniform", "min": 0.55, "max": 0.9}},
    "intensity_measure": {"levels": [0.3, 0.6]},
    "samples_per_level": 5,
    "limit_states": [{"name": "after", "type": "post_earthquake_unstable"},
                     {"name": "after_strict", "type": "post_earthquake_unstable", "threshold": 1.5,
                      "overturned_exceeds": false}],
    "seed": 7})");
}

std::string study_errors(const json& document) {
  try {
    parse_study_config(document, "study.json");
  } catch (const ConfigError& error) {
    return error.what();
  }
  return "(accepted)";
}

TEST(ReservoirStudy, SamplesThePoolLevelOnEachScene) {
  const StudyConfig config = parse_study_config(reservoir_study(), "study.json");
  ASSERT_EQ(config.inputs.size(), 2u);
  EXPECT_EQ(config.inputs[0].input, StudyInput::friction);  // the documented column order
  EXPECT_EQ(config.inputs[1].input, StudyInput::reservoir_level);
  EXPECT_EQ(std::string(input_key(StudyInput::reservoir_level)), "reservoir_level");
  EXPECT_EQ(config.canonical["inputs"]["reservoir_level"],
            (json{{"distribution", "uniform"}, {"min", -0.5}, {"max", 1.0}}));
  StudySampler sampler(config);
  double lowest = 10.0, highest = -10.0;
  for (std::int64_t i = 0; i < config.total_samples(); ++i) {
    const StudySample sample = sampler.draw(i, false);
    ASSERT_TRUE(sample.scene.reservoir.has_value());
    EXPECT_EQ(sample.scene.reservoir->level, sample.values[1]);
    lowest = std::min(lowest, sample.values[1]);
    highest = std::max(highest, sample.values[1]);
  }
  EXPECT_GE(lowest, -0.5);
  EXPECT_LE(highest, 1.0);
  EXPECT_LT(lowest, highest);
}

TEST(ReservoirStudy, ReadsThePostEarthquakeLimitState) {
  const StudyConfig config = parse_study_config(reservoir_study(), "study.json");
  ASSERT_EQ(config.limit_states.size(), 2u);
  EXPECT_EQ(config.limit_states[0].kind, LimitStateKind::post_earthquake_unstable);
  EXPECT_EQ(config.limit_states[0].threshold, 1.0);
  EXPECT_TRUE(config.limit_states[0].overturned_exceeds);
  EXPECT_EQ(config.limit_states[1].threshold, 1.5);
  EXPECT_FALSE(config.limit_states[1].overturned_exceeds);
  EXPECT_EQ(config.canonical["limit_states"][0], (json{{"name", "after"},
                                                       {"type", "post_earthquake_unstable"},
                                                       {"threshold", 1.0},
                                                       {"overturned_exceeds", true}}));
}

TEST(ReservoirStudy, RefusesALevelOrALimitStateWithoutAReservoir) {
  json dry = reservoir_study();
  dry["scene"].erase("reservoir");
  const std::string errors = study_errors(dry);
  EXPECT_THAT(errors, HasSubstr("study.json: /inputs/reservoir_level: sets the reservoir's level, "
                                "but /scene has no reservoir"));
  EXPECT_THAT(errors, HasSubstr("study.json: /limit_states/0/type: \"post_earthquake_unstable\" "
                                "needs a reservoir in /scene"));
  json deep = reservoir_study();
  deep["scene"]["reservoir"] = {{"level", 0.0}, {"depth", 1.5}};  // the level 1 puts 2 m on it
  EXPECT_THAT(study_errors(deep),
              HasSubstr("/inputs/reservoir_level: reaches 1, which puts 2 m of water against the "
                        "block, more than /scene/reservoir/depth (1.5 m)"));
  json negative = reservoir_study();
  negative["limit_states"][0]["threshold"] = -1.0;
  EXPECT_THAT(study_errors(negative), HasSubstr("/limit_states/0/threshold: must be > 0"));
}

// The record keeps the smaller factor; the state counts it below the threshold, never a block
// without one (NaN: not standing at rest at the end), and an overturned one unless told not to.
TEST(ReservoirStudy, CountsABlockStandingBelowTheThreshold) {
  Summary summary;
  summary.post_earthquake = PostEarthquakeCheck{1.4, 0.9};
  const SampleRecord weak = make_record(0, summary);
  EXPECT_EQ(weak.post_earthquake_safety_factor, 0.9);
  summary.post_earthquake = PostEarthquakeCheck{std::numeric_limits<double>::infinity(), 2.0};
  const SampleRecord strong = make_record(1, summary);
  EXPECT_EQ(strong.post_earthquake_safety_factor, 2.0);
  summary.post_earthquake = PostEarthquakeCheck{};
  const SampleRecord moving = make_record(2, summary);
  EXPECT_TRUE(std::isnan(moving.post_earthquake_safety_factor));
  EXPECT_TRUE(std::isnan(make_record(3, Summary{}).post_earthquake_safety_factor));
  SampleRecord overturned = moving;
  overturned.overturned = 1;

  LimitState state{"after", LimitStateKind::post_earthquake_unstable, 1.0, true};
  const double alpha = 0.46;
  EXPECT_TRUE(exceeds(state, weak, alpha));
  EXPECT_FALSE(exceeds(state, strong, alpha));
  EXPECT_FALSE(exceeds(state, moving, alpha));
  EXPECT_TRUE(exceeds(state, overturned, alpha));
  state.threshold = 2.5;
  EXPECT_TRUE(exceeds(state, strong, alpha));
  state.overturned_exceeds = false;
  EXPECT_FALSE(exceeds(state, overturned, alpha));
}

}  // namespace
}  // namespace blockfrag
