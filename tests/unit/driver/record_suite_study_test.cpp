// Studies over record suites and intensity measures: which record each sample runs (every level
// sees each record in proportion to its weight), that the scaled motion a sample runs has the
// level's measure (checked on the motion itself), the dimensionless measure with each sample's own
// alpha, a cloud's own measures, and the inputs refused before any work with their JSON paths.
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "engine/motion/ground_motion.hpp"
#include "engine/motion/intensity_measures.hpp"
#include "engine/scene/block_geometry.hpp"
#include "mpi_driver/config/record_suite.hpp"
#include "mpi_driver/config/study_config.hpp"
#include "mpi_driver/study/study_sample.hpp"

namespace blockfrag {
namespace {

using nlohmann::json;
using ::testing::HasSubstr;

const std::filesystem::path records_folder =
    std::filesystem::path(BLOCKFRAG_SOURCE_DIR) / "tests/data/records";
const std::string study_file = (records_folder / "study.json").string();

json suite_study(const json& suite_records, const json& measure, int per_level) {
  return {{"scene",
           {{"block", {{"half_width", 0.4}, {"half_height", 1.0}}},
            {"contact", {{"friction", 0.7}, {"restitution", 0.5}}},
            {"ground_motion", {{"type", "record_suite"}, {"records", suite_records}}}}},
          {"inputs",
           {{"direction", {{"distribution", "random_sign"}}},
            {"half_width", {{"distribution", "uniform"}, {"min", 0.2}, {"max", 0.6}}}}},
          {"intensity_measure", measure},
          {"samples_per_level", per_level},
          {"limit_states", {{{"name", "overturn"}, {"type", "overturning"}}}},
          {"seed", 7}};
}

const json three_records = {"decaying_sine.AT2", "cosine_pulse.txt", "old_header.at2"};

std::vector<std::string> suite_errors(const json& document) {
  try {
    parse_study_config(document, study_file);
  } catch (const ConfigError& error) {
    return error.messages();
  }
  return {};
}

TEST(RecordSuite, EveryLevelSeesEachRecordInProportionToItsWeight) {
  RecordSuite equal;
  equal.records.resize(3);
  std::map<std::size_t, int> counts;
  for (std::uint32_t j = 0; j < 12; ++j) ++counts[equal.record_of(j, 12)];
  EXPECT_EQ(counts, (std::map<std::size_t, int>{{0, 4}, {1, 4}, {2, 4}}));
  RecordSuite weighted;
  weighted.records.resize(2);
  weighted.records[1].weight = 3.0;  // 1 : 3 of 8 samples: 2 and 6
  counts.clear();
  for (std::uint32_t j = 0; j < 8; ++j) ++counts[weighted.record_of(j, 8)];
  EXPECT_EQ(counts, (std::map<std::size_t, int>{{0, 2}, {1, 6}}));
}

// The scaled motion of every sample, measured by itself, has the level's measure.
void expect_samples_reach_their_levels(const json& measure, double tolerance) {
  const StudyConfig config = parse_study_config(suite_study(three_records, measure, 6), study_file);
  ASSERT_TRUE(config.suite.has_value());
  ASSERT_EQ(config.suite->records.size(), 3u);
  StudySampler sampler(config);
  std::map<std::int64_t, int> per_record;
  for (std::int64_t i = 0; i < config.total_samples(); ++i) {
    const StudySample sample = sampler.draw(i, true);
    const double level = config.intensity.levels[sample.level];
    EXPECT_EQ(sample.im, level);
    ++per_record[sample.record];
    const auto& motion = std::get<RecordedMotion>(sample.scene.ground_motion);
    EXPECT_EQ(motion.file, three_records[static_cast<std::size_t>(sample.record)]);
    const GroundMotionPieces pieces(sample.scene.ground_motion, sample.scene.g);
    double measured = peak_ground_acceleration_g(pieces);
    if (config.intensity.type == ImType::pgv)
      measured = peak_ground_velocity(pieces, sample.scene.g);
    if (config.intensity.type == ImType::sa) {
      measured = spectral_acceleration_g(pieces, config.intensity.period, config.intensity.damping);
    }
    if (config.intensity.type == ImType::pga_over_g_tan_alpha) {
      measured /= std::tan(block_alpha(sample.scene));
    }
    EXPECT_NEAR(measured, level, tolerance * level) << "sample " << i;
    EXPECT_NEAR(sample.pga_g, peak_ground_acceleration_g(pieces), 1e-12 * sample.pga_g);
    EXPECT_NEAR(sample.pgv_m_s, peak_ground_velocity(pieces, sample.scene.g),
                1e-12 * sample.pgv_m_s);
    // The direction input gives the sign of the scale.
    const double direction = sample.values.back();  // inputs in StudyInput order: direction last
    EXPECT_EQ(motion.scale, direction * sample.scale);
  }
  EXPECT_EQ(per_record, (std::map<std::int64_t, int>{{0, 4}, {1, 4}, {2, 4}}));  // 2 levels x 2
}

TEST(RecordSuiteStudy, StripesScaleEachRecordToThePgaLevel) {
  expect_samples_reach_their_levels({{"type", "pga"}, {"levels", {0.2, 0.5}}}, 1e-14);
}

TEST(RecordSuiteStudy, StripesScaleEachRecordToThePgvLevel) {
  expect_samples_reach_their_levels({{"type", "pgv"}, {"levels", {0.05, 0.2}}}, 1e-13);
}

TEST(RecordSuiteStudy, StripesScaleEachRecordToTheSpectralAccelerationLevel) {
  expect_samples_reach_their_levels(
      {{"type", "sa"}, {"period", 0.3}, {"damping", 0.05}, {"levels", {0.3, 0.8}}}, 1e-12);
}

TEST(RecordSuiteStudy, TheDimensionlessMeasureUsesEachSamplesOwnAlpha) {
  expect_samples_reach_their_levels({{"type", "pga_over_g_tan_alpha"}, {"levels", {0.5, 1.5}}},
                                    1e-14);
}

TEST(RecordSuiteStudy, ACloudRunsEveryRecordAtTheFixedScaleAndKeepsItsOwnMeasure) {
  const StudyConfig config = parse_study_config(
      suite_study(three_records, {{"type", "pgv"}, {"scaling", "none"}, {"scale", 2.0}}, 6),
      study_file);
  ASSERT_TRUE(config.intensity.cloud);
  EXPECT_EQ(config.total_samples(), 6);
  StudySampler sampler(config);
  for (std::int64_t i = 0; i < 6; ++i) {
    const StudySample sample = sampler.draw(i, true);
    EXPECT_EQ(sample.scale, 2.0);
    const GroundMotionPieces pieces(sample.scene.ground_motion, sample.scene.g);
    EXPECT_NEAR(sample.im, peak_ground_velocity(pieces, sample.scene.g), 1e-12 * sample.im);
    // As recorded, times 2.
    const auto& suite_record = config.suite->records[static_cast<std::size_t>(sample.record)];
    EXPECT_NEAR(sample.im, 2.0 * suite_record.measures.pgv, 1e-15 * sample.im);
  }
}

TEST(RecordSuiteStudy, AVerticalCompanionIsScaledWithItsRecordButNotTurned) {
  const json suite =
      json::array({json{{"file", "decaying_sine.AT2"}, {"vertical", "cosine_pulse.txt"}}});
  const StudyConfig config =
      parse_study_config(suite_study(suite, {{"type", "pga"}, {"levels", {0.4}}}, 4), study_file);
  StudySampler sampler(config);
  for (std::int64_t i = 0; i < 4; ++i) {
    const StudySample sample = sampler.draw(i);
    const auto& horizontal = std::get<RecordedMotion>(sample.scene.ground_motion);
    const auto& vertical = std::get<RecordedMotion>(sample.scene.vertical_motion);
    EXPECT_EQ(vertical.file, "cosine_pulse.txt");
    EXPECT_EQ(vertical.scale, sample.scale);
    EXPECT_EQ(std::abs(horizontal.scale), sample.scale);
  }
}

TEST(RecordSuiteStudy, BadSuitesAndMeasuresAreRefusedAtTheirPaths) {
  const json pga = {{"type", "pga"}, {"levels", {0.2}}};
  EXPECT_THAT(suite_errors(suite_study({"decaying_sine.AT2", "missing.AT2"}, pga, 2)),
              ::testing::ElementsAre(HasSubstr("study.json: /scene/ground_motion/records/1: " +
                                               (records_folder / "missing.AT2").string() +
                                               ": no such file")));
  EXPECT_THAT(suite_errors(suite_study(
                  json::array({json{{"file", "cosine_pulse.txt"}, {"weight", 0}}}), pga, 2)),
              ::testing::ElementsAre(
                  HasSubstr("/scene/ground_motion/records/0/weight: must be in (0, 1e+06]")));
  EXPECT_THAT(suite_errors(suite_study(json::array(), pga, 2)),
              ::testing::ElementsAre(
                  HasSubstr("/scene/ground_motion/records: must list 1 to 10000 records")));
  EXPECT_THAT(
      suite_errors(
          suite_study(three_records, {{"type", "sa"}, {"period", 12.0}, {"levels", {0.2}}}, 2)),
      ::testing::ElementsAre(HasSubstr("/intensity_measure/period: must be in (0, 10] (got 12)")));
  EXPECT_THAT(
      suite_errors(
          suite_study(three_records,
                      {{"type", "sa"}, {"period", 1.0}, {"damping", 1.0}, {"levels", {0.2}}}, 2)),
      ::testing::ElementsAre(HasSubstr("/intensity_measure/damping: must be in [0, 1) (got 1)")));
  EXPECT_THAT(
      suite_errors(suite_study(three_records, {{"type", "pulse_amplitude"}, {"levels", {0.2}}}, 2)),
      ::testing::ElementsAre(
          HasSubstr("/intensity_measure/type: a record has no pulse amplitude")));
  // cosine_pulse.txt peaks at 0.4 g: 50 g would need a scale of 125.
  EXPECT_THAT(
      suite_errors(
          suite_study({"cosine_pulse.txt"}, {{"type", "pga"}, {"levels", {0.2, 50.0}}}, 2)),
      ::testing::ElementsAre(HasSubstr(
          "/scene/ground_motion/records/0: cosine_pulse.txt: reaching the level 50 g needs a "
          "scale of 125, more than 100")));
  EXPECT_THAT(suite_errors(suite_study(
                  three_records, {{"type", "pga"}, {"scaling", "none"}, {"levels", {0.2}}}, 2)),
              ::testing::ElementsAre(HasSubstr(
                  "/intensity_measure/levels: a cloud (\"scaling\": \"none\") has no levels")));
}

TEST(RecordSuite, ASuitePastItsSampleCapIsRefusedAtTheRecordThatCrossesIt) {
  // Every rank holds every record: the cap bounds the suite's memory, whatever the file count.
  const json document = {{"records", {"cosine_pulse.txt", "cosine_pulse.txt", "cosine_pulse.txt"}}};
  ConfigErrors errors(study_file);
  ObjectReader reader(document, JsonPointer{}, errors);
  const std::optional<RecordSuite> uncapped = read_record_suite(reader, records_folder);
  ASSERT_TRUE(uncapped);
  const std::size_t per_record = uncapped->records[0].record->times.size();
  ConfigErrors capped(study_file);
  ObjectReader small(document, JsonPointer{}, capped);
  EXPECT_FALSE(read_record_suite(small, records_folder, 2 * per_record + 1));
  try {
    capped.throw_if_any();
    ADD_FAILURE() << "the capped suite was read without an error";
  } catch (const ConfigError& error) {
    EXPECT_THAT(error.messages(),
                ::testing::ElementsAre(
                    HasSubstr("study.json: /records/2: the suite's records up to this one hold " +
                              std::to_string(3 * per_record) + " samples, more than the " +
                              std::to_string(2 * per_record + 1) + " a suite may hold")));
  }
}

// On a seat the dimensionless measure's alpha is the seat's (the tilt over its outermost support),
// in the check of the largest scale as in each sample: the 0.4 x 1 block on a seat 0.6 m wide has
// tan alpha 0.3, not a / b = 0.4. cosine_pulse.txt peaks at 0.4 g, so the level 120 needs a scale
// of 120 x 0.3 / 0.4 = 90 there (with a / b it would be 120, more than 100).
TEST(RecordSuiteStudy, OnASeatTheLargestScaleTakesTheSeatsAlpha) {
  json study = suite_study({"cosine_pulse.txt"},
                           {{"type", "pga_over_g_tan_alpha"}, {"levels", {1.0, 120.0}}}, 2);
  study["inputs"].erase("half_width");
  study["scene"]["seat"] = {{-0.3, -1.0}, {0.3, -1.0}};
  EXPECT_THAT(suite_errors(study), ::testing::ElementsAre());
  study["intensity_measure"]["levels"] = {1.0, 140.0};
  EXPECT_THAT(suite_errors(study), ::testing::ElementsAre(::testing::AllOf(
                                       HasSubstr("cosine_pulse.txt: reaching the level 140"),
                                       HasSubstr("needs a scale of 105, more than 100"))));
}

TEST(RecordSuiteStudy, AnSaPeriodTooShortToStepIsRefusedAtItsPath) {
  EXPECT_THAT(
      suite_errors(
          suite_study(three_records, {{"type", "sa"}, {"period", 1e-7}, {"levels", {0.2}}}, 2)),
      ::testing::Contains(HasSubstr("study.json: /intensity_measure/period: decaying_sine.AT2: ")));
}

TEST(RecordSuiteStudy, ARecordOfZerosCannotBeScaled) {
  const std::filesystem::path folder =
      std::filesystem::temp_directory_path() / "blockfrag_zero_record";
  std::filesystem::create_directories(folder);
  {
    std::ofstream out(folder / "zeros.txt");
    out << "0 0\n0.01 0\n0.02 0\n";
  }
  json study = suite_study({"zeros.txt"}, {{"type", "pga"}, {"levels", {0.2}}}, 2);
  try {
    parse_study_config(study, (folder / "study.json").string());
    ADD_FAILURE() << "accepted";
  } catch (const ConfigError& error) {
    EXPECT_THAT(error.messages(), ::testing::ElementsAre(HasSubstr(
                                      "/scene/ground_motion/records/0: zeros.txt: its PGA is 0")));
  }
  std::filesystem::remove_all(folder);
}

TEST(RecordSuiteStudy, TheConfigHashFollowsWhatTheRecordsHold) {
  const std::filesystem::path folder =
      std::filesystem::temp_directory_path() / "blockfrag_hash_record";
  std::filesystem::create_directories(folder);
  const auto write = [&](double value) {
    std::ofstream out(folder / "r.txt");
    out << "0 0\n0.01 " << value << "\n0.02 0\n";
  };
  const json suite = suite_study({"r.txt"}, {{"type", "pga"}, {"levels", {0.2}}}, 2);
  json single = suite;  // the same record as the scene's one "record"
  single["scene"]["ground_motion"] = {{"type", "record"}, {"file", "r.txt"}};
  const std::string source = (folder / "study.json").string();
  write(0.1);
  const auto suite_first = parse_study_config(suite, source).hash;
  const auto single_first = parse_study_config(single, source).hash;
  write(0.2);
  EXPECT_NE(parse_study_config(suite, source).hash, suite_first);
  EXPECT_NE(parse_study_config(single, source).hash, single_first);
  std::filesystem::remove_all(folder);
}

}  // namespace
}  // namespace blockfrag
