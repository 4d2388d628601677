// Study configs: values and defaults as documented, from/to/count levels, the command-line
// overrides, the canonical hash (what changes it and what does not), several errors reported at
// once with their paths; the sample-to-scene mapping (level i / n, pure and independent of the
// order of the draws, geometry from alpha/R, direction as the pulse's sign); and the fragility
// counts per level against hand-counted records.
#include "mpi_driver/config/study_config.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "mpi_driver/config/config_reader.hpp"
#include "mpi_driver/study/limit_states.hpp"
#include "mpi_driver/study/study_sample.hpp"

namespace blockfrag {
namespace {

using nlohmann::json;
using ::testing::HasSubstr;

json small_study() {
  return json::parse(R"({
    "scene": {
      "block": {"half_width": 0.5, "half_height": 1.0},
      "contact": {"friction": 0.7, "restitution": 0.7},
      "ground_motion": {"type": "cosine_pulse", "amplitude_g": 1.0, "period": 1.0},
      "duration": 2.0},
    "inputs": {
      "friction": {"distribution": "uniform", "min": 0.55, "max": 0.9},
      "restitution": {"distribution": "uniform", "min": 0.6, "max": 0.9},
      "period": {"distribution": "lognormal", "median": 1.0, "beta": 0.3, "lower": 0.3, "upper": 3.0},
      "direction": {"distribution": "random_sign"}},
    "intensity_measure": {"levels": [0.3, 0.6, 0.9]},
    "samples_per_level": 8,
    "design": "latin_hypercube",
    "limit_states": [
      {"name": "overturn", "type": "overturning"},
      {"name": "rock", "type": "max_rotation", "theta_over_alpha": 0.5},
      {"name": "slide", "type": "residual_slide", "threshold_m": 0.05}],
    "seed": 42,
    "output": "small.h5",
    "checkpoint_interval_s": 5})");
}

std::vector<std::string> messages_of(const json& document) {
  try {
    parse_study_config(document, "study.json");
  } catch (const ConfigError& error) {
    return error.messages();
  }
  return {};
}

TEST(StudyConfig, ReadsEveryValue) {
  const StudyConfig config = parse_study_config(small_study(), "study.json");
  EXPECT_EQ(config.intensity.levels, (std::vector<double>{0.3, 0.6, 0.9}));
  EXPECT_EQ(config.samples_per_level, 8u);
  EXPECT_EQ(config.total_samples(), 24);
  EXPECT_EQ(config.design, Design::latin_hypercube);
  EXPECT_EQ(config.seed, 42u);
  EXPECT_EQ(config.output, "small.h5");
  EXPECT_EQ(config.checkpoint_interval_s, 5.0);
  ASSERT_EQ(config.inputs.size(), 4u);
  // Columns come in the documented input order, whatever the JSON order.
  EXPECT_EQ(config.inputs[0].input, StudyInput::friction);
  EXPECT_EQ(config.inputs[1].input, StudyInput::restitution);
  EXPECT_EQ(config.inputs[2].input, StudyInput::period);
  EXPECT_EQ(config.inputs[3].input, StudyInput::direction);
  const auto& uniform = std::get<Uniform>(config.inputs[0].distribution);
  EXPECT_EQ(uniform.min, 0.55);
  EXPECT_EQ(uniform.max, 0.9);
  ASSERT_EQ(config.limit_states.size(), 3u);
  EXPECT_EQ(config.limit_states[1].kind, LimitStateKind::max_rotation);
  EXPECT_EQ(config.limit_states[1].threshold, 0.5);
  EXPECT_EQ(config.limit_states[2].kind, LimitStateKind::residual_slide);
  EXPECT_EQ(config.limit_states[2].threshold, 0.05);
}

TEST(StudyConfig, DefaultsAreMonteCarloSixtySecondsAndTheStudyName) {
  json document = small_study();
  document.erase("design");
  document.erase("checkpoint_interval_s");
  document.erase("output");
  const StudyConfig config = parse_study_config(document, "some/folder/dam.json");
  EXPECT_EQ(config.design, Design::monte_carlo);
  EXPECT_EQ(config.checkpoint_interval_s, 60.0);
  EXPECT_EQ(config.output, "dam.h5");
}

TEST(StudyConfig, FromToCountGivesEquallySpacedLevelsEndingExactlyAtTo) {
  json document = small_study();
  document["intensity_measure"] = {{"from", 0.2}, {"to", 2.0}, {"count", 10}};
  const StudyConfig config = parse_study_config(document, "study.json");
  ASSERT_EQ(config.intensity.levels.size(), 10u);
  for (int k = 0; k < 10; ++k) EXPECT_NEAR(config.intensity.levels[k], 0.2 + 0.2 * k, 1e-15);
  EXPECT_EQ(config.intensity.levels.back(), 2.0);
}

TEST(StudyConfig, OverridesReplaceTheConfigValues) {
  const StudyConfig config = parse_study_config(small_study(), "study.json", {"elsewhere.h5", 3});
  EXPECT_EQ(config.output, "elsewhere.h5");
  EXPECT_EQ(config.samples_per_level, 3u);
  EXPECT_EQ(config.canonical["samples_per_level"], 3);
  EXPECT_EQ(config.canonical["output"], "elsewhere.h5");
}

// A dam study's hash is the one it had before the dam took Fenves & Chopra's reservoir and
// foundation: their keys enter the canonical config only when they change the dam.
TEST(StudyConfig, DamReservoirAndFoundationHashOnlyWhenTheyChangeTheDam) {
  json dam_study = small_study();
  dam_study["scene"]["dam"] = {{"period", 0.3}};
  const StudyConfig dry = parse_study_config(dam_study, "study.json");
  EXPECT_EQ(dry.canonical["scene"]["dam"],
            (json{{"period", 0.3}, {"damping", 0.05}, {"participation", 1.0}}));
  const json defaults = {{"reservoir_period_ratio", 1.0},
                         {"reservoir_damping", 0.0},
                         {"foundation_period_ratio", 1.0},
                         {"foundation_damping", 0.0}};
  json spelled = dam_study;
  spelled["scene"]["dam"].update(defaults);
  EXPECT_EQ(parse_study_config(spelled, "study.json").hash, dry.hash);
  for (const auto& [key, value] :
       std::vector<std::pair<std::string, double>>{{"reservoir_period_ratio", 1.1},
                                                   {"reservoir_damping", 0.02},
                                                   {"foundation_period_ratio", 1.2},
                                                   {"foundation_damping", 0.05}}) {
    json changed = dam_study;
    changed["scene"]["dam"][key] = value;
    EXPECT_NE(parse_study_config(changed, "study.json").hash, dry.hash) << key;
  }
}

TEST(StudyConfig, HashIgnoresOutputIntervalAndSpellingButNotTheScience) {
  const auto hash = parse_study_config(small_study(), "study.json").hash;

  json moved = small_study();
  moved["output"] = "other.h5";
  moved["checkpoint_interval_s"] = 600;
  EXPECT_EQ(parse_study_config(moved, "study.json").hash, hash);

  // Equivalent ways to write the same study hash alike: defaults spelled out, levels as a range.
  json spelled = small_study();
  spelled["scene"]["g"] = 9.81;
  spelled["scene"]["block"]["mass"] = 1.0;
  EXPECT_EQ(parse_study_config(spelled, "study.json").hash, hash);

  for (const auto& [pointer, value] :
       std::vector<std::pair<std::string, json>>{{"/seed", 43},
                                                 {"/samples_per_level", 9},
                                                 {"/design", "monte_carlo"},
                                                 {"/inputs/friction/max", 0.91},
                                                 {"/scene/duration", 2.5},
                                                 {"/scene/seat", {{-10, -1}, {10, -1}}},
                                                 {"/limit_states/1/theta_over_alpha", 0.6},
                                                 {"/limit_states/2/overturned_exceeds", false},
                                                 {"/bootstrap_resamples", 200},
                                                 {"/intensity_measure/levels/2", 1.0}}) {
    json changed = small_study();
    changed[JsonPointer(pointer)] = value;
    EXPECT_NE(parse_study_config(changed, "study.json").hash, hash) << pointer;
  }
}

TEST(StudyConfig, ReportsEveryErrorAtOnceWithItsPath) {
  json document = small_study();
  document["inputs"]["friction"]["min"] = -0.2;
  document["inputs"]["restitution"] = {{"distribution", "normal"}, {"mean", 0.7}, {"std_dev", 0.1}};
  document["seed"] = -1;
  document["limit_states"][0]["nmae"] = "x";
  const auto messages = messages_of(document);
  ASSERT_EQ(messages.size(), 4u) << ::testing::PrintToString(messages);
  const std::string all = ::testing::PrintToString(messages);
  EXPECT_THAT(all, HasSubstr("study.json: /inputs/friction: every value must be in [0, 10000]"));
  EXPECT_THAT(all, HasSubstr("study.json: /inputs/restitution: every value must be in [0, 1]"));
  EXPECT_THAT(all, HasSubstr("study.json: /seed: must be >= 0"));
  EXPECT_THAT(all, HasSubstr("study.json: /limit_states/0/nmae: unknown key"));
}

// The keys of a fixed direction and of a limit state read and write through their tables: a sign,
// a boolean, a string.
TEST(StudyConfig, AFixedDirectionAndALimitStatesFlagReadBackInTheCanonicalForm) {
  json document = small_study();
  document["inputs"]["direction"] = {{"distribution", "fixed"}, {"value", -1}};
  document["limit_states"][1]["overturned_exceeds"] = false;
  const StudyConfig config = parse_study_config(document, "study.json");
  EXPECT_EQ(config.canonical["inputs"]["direction"],
            (json{{"distribution", "fixed"}, {"value", -1.0}}));
  EXPECT_EQ(config.canonical["limit_states"][1], (json{{"name", "rock"},
                                                       {"type", "max_rotation"},
                                                       {"theta_over_alpha", 0.5},
                                                       {"overturned_exceeds", false}}));
  EXPECT_EQ(config.canonical["samples_per_level"], 8);
  EXPECT_EQ(config.canonical["seed"], 42);

  document["inputs"]["direction"]["value"] = 0.5;
  document["limit_states"][1]["overturned_exceeds"] = "no";
  document["limit_states"][2]["name"] = 7;
  EXPECT_EQ(
      messages_of(document),
      (std::vector<std::string>{
          "study.json: /inputs/direction/value: must be 1 or -1 (got 0.5)",
          "study.json: /limit_states/1/overturned_exceeds: must be true or false (got \"no\")",
          "study.json: /limit_states/2/name: must be a string (got 7)"}));
}

TEST(StudyConfig, LevelsAreOneToAMillionIncreasingNumbersInTheMeasuresDomain) {
  json document = small_study();
  document["intensity_measure"]["levels"] = json::array();
  EXPECT_EQ(messages_of(document),
            std::vector<std::string>{
                "study.json: /intensity_measure/levels: must have 1 to 1000000 levels (got 0)"});
  document["intensity_measure"] = {{"type", "pgv"}, {"levels", {0.3, 0.3, 200}}};
  EXPECT_EQ(messages_of(document),
            (std::vector<std::string>{"study.json: /intensity_measure/levels/1: must be greater "
                                      "than the level before it (levels increase)",
                                      "study.json: /intensity_measure/levels/2: must be in (0, "
                                      "100] (got 200)"}));
}

TEST(StudyConfig, LimitStatesNestUnlessToldAndTheBootstrapDefaultsToAThousand) {
  json document = small_study();
  document["limit_states"][2]["overturned_exceeds"] = false;
  const StudyConfig config = parse_study_config(document, "study.json");
  EXPECT_TRUE(config.limit_states[1].overturned_exceeds);
  EXPECT_FALSE(config.limit_states[2].overturned_exceeds);
  EXPECT_EQ(config.canonical["limit_states"][1]["overturned_exceeds"], true);
  EXPECT_EQ(config.bootstrap_resamples, 1000);

  // Overturning is its own limit state: the option means nothing there.
  document["limit_states"][0]["overturned_exceeds"] = false;
  document["bootstrap_resamples"] = 100'001;
  const std::string all = ::testing::PrintToString(messages_of(document));
  EXPECT_THAT(all, HasSubstr("study.json: /limit_states/0/overturned_exceeds: unknown key"));
  EXPECT_THAT(all, HasSubstr("study.json: /bootstrap_resamples: must be"));
}

TEST(StudyConfig, AnAdaptiveDesignNamesItsLimitStateAndBudget) {
  json document = small_study();
  document["design"] = {{"adaptive", {{"base", "monte_carlo"}, {"max_samples", 240}}}};
  const StudyConfig config = parse_study_config(document, "study.json");
  ASSERT_TRUE(config.adaptive.has_value());
  EXPECT_EQ(config.design, Design::monte_carlo);
  EXPECT_EQ(config.adaptive->limit_state, "overturn");  // the first, by default
  EXPECT_EQ(config.adaptive->target_relative_width, 0.05);
  EXPECT_EQ(config.adaptive->max_samples, 240);
  EXPECT_NE(config.hash, parse_study_config(small_study(), "study.json").hash);
  json narrower = document;
  narrower["design"]["adaptive"]["target_relative_width"] = 0.02;
  EXPECT_NE(parse_study_config(narrower, "study.json").hash, config.hash);

  document["design"]["adaptive"]["limit_state"] = "slid";
  document["design"]["adaptive"]["max_samples"] = 23;  // the first batch is 3 levels of 8
  document["design"]["adaptive"]["target_relative_width"] = 0.0;
  const auto messages = messages_of(document);
  ASSERT_EQ(messages.size(), 3u) << ::testing::PrintToString(messages);
  const std::string all = ::testing::PrintToString(messages);
  EXPECT_THAT(messages,
              ::testing::Contains(
                  "study.json: /design/adaptive/limit_state: \"slid\" is not a limit state"));
  EXPECT_THAT(all,
              HasSubstr("study.json: /design/adaptive/max_samples: must hold the first batch"));
  EXPECT_THAT(all, HasSubstr("study.json: /design/adaptive/target_relative_width: must be in"));

  // Each batch costs a round of messages and a fit: a budget of millions of tiny batches is
  // refused.
  document = small_study();
  document["samples_per_level"] = 1;
  document["design"] = {{"adaptive", {{"max_samples", 1'000'000}}}};
  EXPECT_THAT(::testing::PrintToString(messages_of(document)),
              HasSubstr("study.json: /design/adaptive/max_samples: allows 499998 batches"));
}

TEST(StudyConfig, TruncationMakesAnUnboundedLawAcceptable) {
  json document = small_study();
  document["inputs"]["restitution"] = {
      {"distribution", "normal"}, {"mean", 0.7}, {"std_dev", 0.2}, {"lower", 0.0}, {"upper", 1.0}};
  document["inputs"]["friction"] = {
      {"distribution", "normal"}, {"mean", 0.7}, {"std_dev", 0.2}, {"lower", 0.0}};
  // Friction's domain is bounded above too: truncated below only, the law still leaves it.
  EXPECT_THAT(::testing::PrintToString(messages_of(document)),
              HasSubstr("/inputs/friction: every value must be in [0, 10000], but this "
                        "distribution reaches [0, inf]"));
  document["inputs"]["friction"]["upper"] = 2.0;
  EXPECT_TRUE(messages_of(document).empty()) << ::testing::PrintToString(messages_of(document));
}

TEST(StudyConfig, SceneErrorsCarryTheScenePrefix) {
  json document = small_study();
  document["scene"]["contact"]["restitution"] = 1.5;
  const auto messages = messages_of(document);
  ASSERT_EQ(messages.size(), 1u);
  EXPECT_THAT(messages[0], HasSubstr("study.json: /scene/contact/restitution: must be in [0, 1]"));
}

// A seat fits one block at rest: a drawn size would leave the block floating above it (once a
// segfault: no contact to measure alpha over) or sunk into it. Each sized input is refused at its
// path; friction and the rest still vary.
TEST(StudyConfig, ASeatFixesTheBlocksGeometry) {
  json document = small_study();
  document["scene"]["seat"] = {{-2, -1}, {2, -1}};
  EXPECT_TRUE(messages_of(document).empty()) << ::testing::PrintToString(messages_of(document));
  const std::string rule =
      ": varies the block's size, but /scene/seat fixes the block's geometry (a seat fits one "
      "block at rest)";
  document["inputs"]["half_height"] = {{"distribution", "uniform"}, {"min", 0.5}, {"max", 2.0}};
  EXPECT_EQ(messages_of(document),
            std::vector<std::string>{"study.json: /inputs/half_height" + rule});
  document["inputs"].erase("half_height");
  document["inputs"]["alpha"] = {{"distribution", "uniform"}, {"min", 0.3}, {"max", 0.5}};
  document["inputs"]["R"] = {{"distribution", "fixed"}, {"value", 1.2}};
  EXPECT_EQ(messages_of(document), (std::vector<std::string>{"study.json: /inputs/alpha" + rule,
                                                             "study.json: /inputs/R" + rule}));
}

// --- The sample-to-scene mapping
// -------------------------------------------------------------------

TEST(StudySample, IndexMapsToLevelAndAmplitudeWithTheDirectionsSign) {
  const StudyConfig config = parse_study_config(small_study(), "study.json");
  StudySampler sampler(config);
  int negative = 0;
  for (std::int64_t i = 0; i < config.total_samples(); ++i) {
    const StudySample sample = sampler.draw(i);
    EXPECT_EQ(sample.level, static_cast<std::uint32_t>(i / 8));
    EXPECT_EQ(sample.im, config.intensity.levels[static_cast<std::size_t>(i / 8)]);
    const auto& pulse = std::get<CosinePulse>(sample.scene.ground_motion);
    const double direction = sample.values[3];
    ASSERT_TRUE(direction == 1.0 || direction == -1.0);
    EXPECT_EQ(pulse.amplitude_g, direction * sample.im);
    EXPECT_EQ(pulse.period, sample.values[2]);
    EXPECT_EQ(sample.scene.contact.friction, sample.values[0]);
    EXPECT_EQ(sample.scene.contact.restitution, sample.values[1]);
    EXPECT_GE(sample.values[0], 0.55);
    EXPECT_LE(sample.values[0], 0.9);
    EXPECT_GE(sample.values[2], 0.3);
    EXPECT_LE(sample.values[2], 3.0);
    negative += direction < 0;
    // Untouched parts of the base scene stay as they were.
    EXPECT_EQ(sample.scene.block.half_width, 0.5);
    EXPECT_EQ(sample.scene.duration, 2.0);
  }
  // Latin hypercube on the sign: each level's 8 samples split 4 and 4 between the halves of u.
  EXPECT_EQ(negative, 12);
}

TEST(StudySample, DrawsArePureWhateverTheOrderAndTheSampler) {
  const StudyConfig config = parse_study_config(small_study(), "study.json");
  StudySampler in_order(config);
  std::vector<StudySample> expected;
  for (std::int64_t i = 0; i < config.total_samples(); ++i) expected.push_back(in_order.draw(i));
  std::vector<std::int64_t> order(static_cast<std::size_t>(config.total_samples()));
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<std::int64_t>(i);
  std::shuffle(order.begin(), order.end(), std::mt19937(7));
  StudySampler shuffled(config);
  for (const auto i : order) {
    const StudySample sample = shuffled.draw(i);
    EXPECT_EQ(sample.values, expected[static_cast<std::size_t>(i)].values) << i;
    // A fresh sampler per draw: nothing is carried between draws.
    EXPECT_EQ(StudySampler(config).draw(i).values, sample.values) << i;
  }
}

TEST(StudySample, LatinHypercubeFillsEveryStratumOfEveryLevel) {
  const StudyConfig config = parse_study_config(small_study(), "study.json");
  StudySampler sampler(config);
  for (std::uint32_t level = 0; level < 3; ++level) {
    std::vector<int> strata(8, 0);
    for (std::int64_t j = 0; j < 8; ++j) {
      const double friction = sampler.draw(level * 8 + j).values[0];
      // Uniform(0.55, 0.9): stratum s of u is [0.55 + 0.35 s / 8, 0.55 + 0.35 (s + 1) / 8).
      ++strata[static_cast<std::size_t>(std::floor((friction - 0.55) / 0.35 * 8))];
    }
    EXPECT_EQ(strata, std::vector<int>(8, 1)) << "level " << level;
  }
}

TEST(StudySample, AlphaAndRGiveTheRectangle) {
  json document = small_study();
  document["inputs"]["alpha"] = {{"distribution", "fixed"}, {"value", std::atan(0.5)}};
  document["inputs"]["R"] = {{"distribution", "fixed"}, {"value", std::sqrt(1.25) * 2}};
  const StudyConfig config = parse_study_config(document, "study.json");
  const StudySample sample = StudySampler(config).draw(5);
  EXPECT_NEAR(sample.scene.block.half_width, 1.0, 1e-14);
  EXPECT_NEAR(sample.scene.block.half_height, 2.0, 1e-14);
}

TEST(StudySample, ChangingTheSeedChangesTheDraws) {
  json document = small_study();
  const StudyConfig first = parse_study_config(document, "study.json");
  document["seed"] = 43;
  const StudyConfig second = parse_study_config(document, "study.json");
  EXPECT_NE(StudySampler(first).draw(3).values, StudySampler(second).draw(3).values);
}

// --- Fragility counts ---------------------------------------------------------------------------

SampleRecord record(std::int64_t index, bool overturned, double max_abs_theta, double final_slide,
                    SampleStatus status = SampleStatus::ok) {
  SampleRecord r;
  r.index = index;
  r.status = static_cast<std::int64_t>(status);
  r.overturned = overturned;
  r.max_abs_theta = max_abs_theta;
  r.final_slide = final_slide;
  return r;
}

TEST(StudyFragility, CountsPerLevelExcludeFailedSamples) {
  json document = small_study();
  document["samples_per_level"] = 4;
  document["intensity_measure"]["levels"] = {0.5, 1.0};
  const StudyConfig config = parse_study_config(document, "study.json");
  const double alpha = std::atan(0.5);
  const std::vector<SampleRecord> records = {
      record(0, false, 0.1 * alpha, 0.0),
      record(1, false, 0.6 * alpha, -0.06),  // rocks past 0.5 alpha, slides 6 cm the other way
      record(2, true, 1.6, 0.01, SampleStatus::failed),  // excluded whatever it says
      record(3, false, 0.4 * alpha, 0.04),
      record(4, true, std::numbers::pi / 2, 0.3),
      record(5, true, std::numbers::pi / 2, 0.0),  // on its side: past every limit, slid or not
      record(6, false, 0.0, 0.0, SampleStatus::rejected),
      record(7, false, 0.55 * alpha, 0.05),  // exactly at the slide threshold: not above it
  };
  const std::vector<double> alphas(8, alpha);
  const auto overturn = fragility_curve(config, config.limit_states[0], records, alphas);
  const auto rock = fragility_curve(config, config.limit_states[1], records, alphas);
  const auto slide = fragility_curve(config, config.limit_states[2], records, alphas);
  EXPECT_EQ(overturn.trials, (std::vector<std::int64_t>{3, 3}));
  EXPECT_EQ(overturn.exceedances, (std::vector<std::int64_t>{0, 2}));
  EXPECT_EQ(rock.exceedances, (std::vector<std::int64_t>{1, 3}));
  EXPECT_EQ(slide.exceedances, (std::vector<std::int64_t>{1, 2}));
  EXPECT_EQ(overturn.im, (std::vector<double>{0.5, 1.0}));
  EXPECT_DOUBLE_EQ(rock.probability[0], 1.0 / 3.0);
  EXPECT_EQ(rock.probability[1], 1.0);

  // The raw measures: an overturned block counts only by its own rotation and slide.
  LimitState raw_slide = config.limit_states[2];
  raw_slide.overturned_exceeds = false;
  EXPECT_EQ(fragility_curve(config, raw_slide, records, alphas).exceedances,
            (std::vector<std::int64_t>{1, 1}));
}

TEST(StudyFragility, ABlockThatFellOffItsSeatIsLostLikeAnOverturnedOne) {
  const StudyConfig config = parse_study_config(small_study(), "study.json");
  const double alpha = std::atan(0.5);
  SampleRecord fell = record(0, false, 0.1 * alpha, -0.01);  // little rotation, a short slide
  fell.fell = 1;
  SampleRecord stayed = fell;
  stayed.fell = 0;
  for (const LimitState& state : config.limit_states) {
    EXPECT_TRUE(exceeds(state, fell, alpha)) << state.name;
    EXPECT_FALSE(exceeds(state, stayed, alpha)) << state.name;
  }
  // Counted only by its raw measure, the slide limit sees the short slide before it fell.
  LimitState raw_slide = config.limit_states[2];
  raw_slide.overturned_exceeds = false;
  EXPECT_FALSE(exceeds(raw_slide, fell, alpha));
}

TEST(StudyFragility, WilsonIntervalAndFitMatchTheReferenceData) {
  // docs/references.md (Baker 2015): levels 0.2 .. 1.0, n = 40, z = 0 0 0 4 6 13 12 16 ->
  // theta = 1.076116, beta = 0.429237, -ln L = 10.797705; Wilson 16/40 -> (0.2635, 0.5540).
  const std::vector<double> levels = {0.2, 0.3, 0.4, 0.6, 0.7, 0.8, 0.9, 1.0};
  const std::vector<int> z = {0, 0, 0, 4, 6, 13, 12, 16};
  json document = small_study();
  document["samples_per_level"] = 40;
  document["intensity_measure"]["levels"] = levels;
  const StudyConfig config = parse_study_config(document, "study.json");
  std::vector<SampleRecord> records;
  for (std::size_t level = 0; level < levels.size(); ++level) {
    for (int j = 0; j < 40; ++j)
      records.push_back(record(static_cast<std::int64_t>(level * 40 + j), j < z[level], 0.0, 0.0));
  }
  const auto curve = fragility_curve(config, config.limit_states[0], records,
                                     std::vector<double>(records.size(), 0.46));
  EXPECT_NEAR(curve.median, 1.076116, 1e-5);
  EXPECT_NEAR(curve.beta, 0.429237, 1e-5);
  EXPECT_NEAR(curve.log_likelihood, -10.797705, 1e-5);
  EXPECT_EQ(curve.fit_status, "ok");
  EXPECT_NEAR(curve.ci_low[7], 0.2635, 5e-5);
  EXPECT_NEAR(curve.ci_high[7], 0.5540, 5e-5);
  EXPECT_EQ(curve.ci_low[0], 0.0);
  EXPECT_NEAR(curve.ci_high[0], 0.0876, 5e-5);
}

TEST(StudyFragility, NoFitWithoutExceedances) {
  const StudyConfig config = parse_study_config(small_study(), "study.json");
  std::vector<SampleRecord> records;
  for (std::int64_t i = 0; i < config.total_samples(); ++i)
    records.push_back(record(i, false, 0.0, 0.0));
  const auto curve = fragility_curve(config, config.limit_states[0], records,
                                     std::vector<double>(records.size(), 0.46));
  EXPECT_TRUE(std::isnan(curve.median));
  EXPECT_TRUE(std::isnan(curve.beta));
  EXPECT_TRUE(std::isnan(curve.log_likelihood));
  EXPECT_EQ(curve.fit_status, "no_exceedances");
}

// A stripe study's bootstrap refits over every level: a grid of thousands of levels gets fewer
// resamples (1e6 levels x resamples), a few levels the config's.
TEST(StudyFragility, TheBootstrapOfManyLevelsIsCappedAtAMillionLevelResamples) {
  json document = small_study();
  document["bootstrap_resamples"] = 100;
  for (const int count : {2, 20'000}) {
    document["intensity_measure"] = {{"from", 0.3}, {"to", 1.5}, {"count", count}};
    const StudyConfig config = parse_study_config(document, "study.json");
    std::vector<std::int64_t> trials(static_cast<std::size_t>(count), 10), exceedances;
    for (int k = 0; k < count; ++k) exceedances.push_back(k < count / 2 ? 3 : 7);
    const FragilityCurve curve =
        stripe_curve(config, config.limit_states[0], trials, std::move(exceedances));
    ASSERT_EQ(curve.fit_status, "ok");
    EXPECT_EQ(curve.bootstrap.resamples, count == 2 ? 100 : 50) << count;
  }
}

}  // namespace
}  // namespace blockfrag
