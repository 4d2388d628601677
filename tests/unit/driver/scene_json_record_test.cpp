// The "record" ground motion in scene JSON: a relative file is taken from the scene file's folder
// (or the embedding document's), scale or target_pga_g (one at most) resolve to one scale, a record
// that cannot be read is an error at /ground_motion/file carrying the reader's file:line: reason,
// and the canonical form writes the resolved scale. A study scales a record to its intensity (PGA).
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "mpi_driver/config/config_reader.hpp"
#include "mpi_driver/config/scene_json.hpp"
#include "mpi_driver/config/study_config.hpp"
#include "mpi_driver/study/study_sample.hpp"
#include "tests/support/scene_json_errors.hpp"

namespace blockfrag {
namespace {

using nlohmann::json;
using ::testing::HasSubstr;

const std::filesystem::path record_files =
    std::filesystem::path(BLOCKFRAG_SOURCE_DIR) / "tests/data/records";
// A scene file next to the records (it need not exist: only its folder matters).
const std::string scene_file = (record_files / "scene.json").string();

// The largest |a| among the samples make_records.py wrote (before rounding to 8 digits).
double decaying_sine_peak() {
  double peak = 0.0;
  for (int k = 0; k < 400; ++k) {
    const double t = k * 0.005;
    peak = std::max(peak, std::abs(0.3 * std::exp(-t) * std::sin(4 * std::numbers::pi * t)));
  }
  return peak;
}

json record_scene_with(const json& motion) {
  return {{"block", {{"half_width", 0.2}, {"half_height", 1.0}}},
          {"contact", {{"friction", 0.7}, {"restitution", 0.8}}},
          {"ground_motion", motion},
          {"duration", 3.0}};
}

std::string record_scene_errors(const json& document, const std::string& source = scene_file) {
  return testing::scene_errors(document, source);
}

TEST(SceneJsonRecord, ARelativeFileIsTakenFromTheSceneFilesFolder) {
  const Scene scene = scene_from_json(
      record_scene_with({{"type", "record"}, {"file", "decaying_sine.AT2"}}), scene_file);
  const auto& motion = std::get<RecordedMotion>(scene.ground_motion);
  EXPECT_EQ(motion.file, "decaying_sine.AT2");
  EXPECT_EQ(motion.scale, 1.0);
  ASSERT_NE(motion.record, nullptr);
  EXPECT_EQ(motion.record->times.size(), 400u);
}

TEST(SceneJsonRecord, AnAbsoluteFileIgnoresTheFolder) {
  const std::string file = (record_files / "cosine_pulse.txt").string();
  const Scene scene =
      scene_from_json(record_scene_with({{"type", "record"}, {"file", file}, {"scale", -2.0}}),
                      "/no/such/folder/scene.json");
  const auto& motion = std::get<RecordedMotion>(scene.ground_motion);
  EXPECT_EQ(motion.scale, -2.0);
  ASSERT_NE(motion.record, nullptr);
  EXPECT_EQ(motion.record->times.size(), 51u);
}

TEST(SceneJsonRecord, TargetPgaScalesThePeakToTheTarget) {
  const Scene scene = scene_from_json(
      record_scene_with(
          {{"type", "record"}, {"file", "decaying_sine.AT2"}, {"target_pga_g", 0.45}}),
      scene_file);
  const auto& motion = std::get<RecordedMotion>(scene.ground_motion);
  // Against the formula's peak: the file keeps 8 digits, so the two agree to 5e-8 relative.
  EXPECT_NEAR(motion.scale, 0.45 / decaying_sine_peak(), 5e-8 * motion.scale);
  EXPECT_NEAR(motion.scale * peak_acceleration_g(*motion.record), 0.45, 1e-15);
}

TEST(SceneJsonRecord, CanonicalFormWritesTheFileAsGivenAndTheResolvedScale) {
  const json document = record_scene_with(
      {{"type", "record"}, {"file", "decaying_sine.AT2"}, {"target_pga_g", 0.45}});
  const json canonical = scene_to_json(scene_from_json(document, scene_file));
  const json& motion = canonical["ground_motion"];
  EXPECT_EQ(motion["type"], "record");
  EXPECT_EQ(motion["file"], "decaying_sine.AT2");
  EXPECT_NEAR(motion["scale"].get<double>(), 0.45 / decaying_sine_peak(), 5e-8);
  EXPECT_EQ(motion.size(), 3u);
  EXPECT_EQ(scene_to_json(scene_from_json(json::parse(canonical.dump()), scene_file)), canonical);
}

TEST(SceneJsonRecord, ScaleAndTargetPgaAreExclusiveAndTheFileIsRequired) {
  EXPECT_EQ(
      record_scene_errors(record_scene_with({{"type", "record"},
                                             {"file", "decaying_sine.AT2"},
                                             {"scale", 2},
                                             {"target_pga_g", 0.4}})),
      scene_file + ": /ground_motion/target_pga_g: give either scale or target_pga_g, not both");
  EXPECT_EQ(record_scene_errors(record_scene_with({{"type", "record"}, {"scale", 2}})),
            scene_file + ": /ground_motion/file: is required");
  EXPECT_EQ(record_scene_errors(record_scene_with({{"type", "record"}, {"file", ""}})),
            scene_file + ": /ground_motion/file: must not be empty");
  EXPECT_EQ(record_scene_errors(record_scene_with(
                {{"type", "record"}, {"file", "decaying_sine.AT2"}, {"target_pga_g", 0}})),
            scene_file + ": /ground_motion/target_pga_g: must be in (0, 1000] (got 0)");
  EXPECT_THAT(record_scene_errors(record_scene_with(
                  {{"type", "record"}, {"file", "decaying_sine.AT2"}, {"amplitude_g", 1}})),
              HasSubstr("/ground_motion/amplitude_g: unknown key for type \"record\""));
}

TEST(SceneJsonRecord, AnUnreadableRecordIsAnErrorAtFileWithTheReadersLineAndReason) {
  const std::filesystem::path bad = record_files / "../bad_records/non_numeric.AT2";
  EXPECT_EQ(record_scene_errors(record_scene_with(
                {{"type", "record"}, {"file", "../bad_records/non_numeric.AT2"}})),
            scene_file + ": /ground_motion/file: " + bad.string() +
                ":6: not a number: \"2.0000000E-0Z\"");
  EXPECT_EQ(record_scene_errors(record_scene_with({{"type", "record"}, {"file", "missing.AT2"}})),
            scene_file + ": /ground_motion/file: " + (record_files / "missing.AT2").string() +
                ": no such file");
}

TEST(SceneJsonRecord, ARecordOfZerosCannotBeScaledToAPeak) {
  const std::filesystem::path zeros =
      std::filesystem::temp_directory_path() / "blockfrag_zero_record.txt";
  std::ofstream(zeros) << "0 0\n0.01 0\n0.02 0\n";
  EXPECT_EQ(record_scene_errors(record_scene_with(
                {{"type", "record"}, {"file", zeros.string()}, {"target_pga_g", 0.3}})),
            scene_file + ": /ground_motion/target_pga_g: cannot scale " + zeros.string() +
                " to a peak: its accelerations are all 0");
  EXPECT_EQ(record_scene_errors(
                record_scene_with({{"type", "record"}, {"file", zeros.string()}, {"scale", 3}})),
            "(accepted)");
  std::filesystem::remove(zeros);
}

TEST(SceneJsonRecord, AnEmbeddedSceneTakesRecordsFromTheGivenFolder) {
  ConfigErrors errors("suite.json");
  const json suite_scene =
      record_scene_with({{"type", "record"}, {"file", "records/cosine_pulse.txt"}});
  const Scene scene = scene_from_json(suite_scene, JsonPointer("/scenes/0/scene"), errors,
                                      record_files.parent_path());
  EXPECT_TRUE(errors.empty());
  const auto& motion = std::get<RecordedMotion>(scene.ground_motion);
  ASSERT_NE(motion.record, nullptr);
  EXPECT_EQ(motion.record->times.size(), 51u);

  scene_from_json(suite_scene, JsonPointer("/scenes/0/scene"), errors, record_files);
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_THROW(errors.throw_if_any(), ConfigError);
}

TEST(SceneJsonRecord, AStudyScalesTheRecordsPeakToEachIntensityLevel) {
  const json study = {
      {"scene", record_scene_with({{"type", "record"}, {"file", "decaying_sine.AT2"}})},
      {"inputs", {{"direction", {{"distribution", "random_sign"}}}}},
      {"intensity_measure", {{"levels", {0.2, 0.6}}}},
      {"samples_per_level", 4},
      {"limit_states", {{{"name", "overturn"}, {"type", "overturning"}}}},
      {"seed", 7}};
  const StudyConfig config = parse_study_config(study, (record_files / "study.json").string());
  StudySampler sampler(config);
  for (std::int64_t index = 0; index < 8; ++index) {
    const StudySample sample = sampler.draw(index);
    const auto& motion = std::get<RecordedMotion>(sample.scene.ground_motion);
    const double direction = sample.values.at(0);
    EXPECT_NEAR(motion.scale * peak_acceleration_g(*motion.record), direction * sample.im, 1e-15);
    EXPECT_EQ(sample.im, index < 4 ? 0.2 : 0.6);
  }
}

}  // namespace
}  // namespace blockfrag
