// The rocking restitution in configs: a scene's "contact": {"rocking_restitution": r or
// "housner"} read, refused at its path and written only where given (a config without it keeps its
// hash); a study's inputs.rocking_restitution drawn into each sample's scene; a spectrum spec's
// contact carrying it into every point's scene and its hash.
#include <cstdint>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "mpi_driver/config/config_reader.hpp"
#include "mpi_driver/config/scene_json.hpp"
#include "mpi_driver/config/spectrum_config.hpp"
#include "mpi_driver/config/study_config.hpp"
#include "mpi_driver/study/study_sample.hpp"
#include "tests/support/scene_json_errors.hpp"

namespace blockfrag {
namespace {

using nlohmann::json;
using ::testing::HasSubstr;
using testing::scene_errors;

json rocking_scene(const json& rocking) {
  json scene = json::parse(R"({
    "block": {"half_width": 0.25, "half_height": 1.0},
    "contact": {"friction": 0.8, "restitution": 0.3},
    "ground_motion": {"type": "sine_pulse", "amplitude_g": 0.5, "period": 1.0},
    "duration": 3.0})");
  if (!rocking.is_null()) scene["contact"]["rocking_restitution"] = rocking;
  return scene;
}

TEST(RockingRestitutionJson, IsReadAsANumberOrHousner) {
  const Scene given = scene_from_json(rocking_scene(0.85), "scene.json");
  ASSERT_TRUE(given.contact.rocking_restitution.has_value());
  EXPECT_FALSE(given.contact.rocking_restitution->housner);
  EXPECT_EQ(given.contact.rocking_restitution->ratio, 0.85);
  EXPECT_EQ(scene_to_json(given)["contact"]["rocking_restitution"], 0.85);

  const Scene housner = scene_from_json(rocking_scene("housner"), "scene.json");
  ASSERT_TRUE(housner.contact.rocking_restitution.has_value());
  EXPECT_TRUE(housner.contact.rocking_restitution->housner);
  EXPECT_EQ(scene_to_json(housner)["contact"]["rocking_restitution"], "housner");
  // The canonical form reads back to the same scene.
  EXPECT_EQ(scene_to_json(scene_from_json(scene_to_json(housner), "canonical.json")),
            scene_to_json(housner));

  EXPECT_EQ(scene_errors(rocking_scene(1.0)), "(accepted)");
}

// Without the key the canonical contact has its two keys only: a config's hash stays what it was.
TEST(RockingRestitutionJson, IsWrittenOnlyWhereGiven) {
  const Scene absent = scene_from_json(rocking_scene(nullptr), "scene.json");
  EXPECT_FALSE(absent.contact.rocking_restitution.has_value());
  EXPECT_EQ(scene_to_json(absent)["contact"], (json{{"friction", 0.8}, {"restitution", 0.3}}));
}

TEST(RockingRestitutionJson, IsRefusedAtItsPath) {
  const std::string at = "scene.json: /contact/rocking_restitution: ";
  EXPECT_EQ(scene_errors(rocking_scene(0)), at + "must be in (0, 1] (got 0)");
  EXPECT_EQ(scene_errors(rocking_scene(-0.5)), at + "must be in (0, 1] (got -0.5)");
  EXPECT_EQ(scene_errors(rocking_scene(1.05)), at + "must be in (0, 1] (got 1.05)");
  EXPECT_EQ(scene_errors(rocking_scene("Housner")),
            at + "must be a number in (0, 1] or \"housner\" (got \"Housner\")");
  EXPECT_EQ(scene_errors(rocking_scene(true)),
            at + "must be a number in (0, 1] or \"housner\" (got true)");
  // Housner's model without impacts changes the pivot without loss, Newmark's never rocks.
  for (const json& effects : {json{"rocking"}, json{"sliding"}}) {
    json document = rocking_scene(0.9);
    document["effects"] = effects;
    EXPECT_EQ(scene_errors(document), at + "needs a model with rocking impacts: effects \"auto\", "
                                           "the full model's or [\"rocking\", \"impact\"]");
  }
  json housners_model = rocking_scene(0.9);
  housners_model["effects"] = {"rocking", "impact"};
  EXPECT_EQ(scene_errors(housners_model), "(accepted)");
}

json rocking_study() {
  return json{
      {"scene", rocking_scene("housner")},
      {"inputs",
       {{"rocking_restitution", {{"distribution", "uniform"}, {"min", 0.6}, {"max", 0.95}}}}},
      {"intensity_measure", {{"levels", {0.3, 0.6}}}},
      {"samples_per_level", 4},
      {"limit_states", {{{"name", "overturn"}, {"type", "overturning"}}}},
      {"seed", 7}};
}

TEST(RockingRestitutionStudy, EachSampleTakesItsDrawnRatio) {
  const StudyConfig config = parse_study_config(rocking_study(), "study.json");
  ASSERT_EQ(config.inputs.size(), 1u);
  EXPECT_EQ(std::string(input_key(config.inputs[0].input)), "rocking_restitution");
  StudySampler sampler(config);
  for (std::int64_t i = 0; i < config.total_samples(); ++i) {
    const StudySample sample = sampler.draw(i);
    const auto& rocking = sample.scene.contact.rocking_restitution;
    ASSERT_TRUE(rocking.has_value());
    EXPECT_FALSE(rocking->housner);
    EXPECT_EQ(rocking->ratio, sample.values[0]);
    EXPECT_GE(rocking->ratio, 0.6);
    EXPECT_LE(rocking->ratio, 0.95);
  }
}

std::vector<std::string> rocking_study_messages(const json& document) {
  try {
    parse_study_config(document, "study.json");
  } catch (const ConfigError& error) {
    return error.messages();
  }
  return {};
}

TEST(RockingRestitutionStudy, IsRefusedOutsideItsDomainOrWithoutRockingImpacts) {
  json document = rocking_study();
  document["inputs"]["rocking_restitution"] = {
      {"distribution", "normal"}, {"mean", 0.9}, {"std_dev", 0.05}, {"lower", 0.0}, {"upper", 1.2}};
  EXPECT_THAT(::testing::PrintToString(rocking_study_messages(document)),
              HasSubstr("study.json: /inputs/rocking_restitution: every value must be in (0, 1], "
                        "but this distribution reaches [0, 1.2]"));
  document = rocking_study();
  document["scene"]["effects"] = {"sliding"};
  document["scene"]["contact"].erase("rocking_restitution");
  EXPECT_EQ(rocking_study_messages(document),
            std::vector<std::string>{
                "study.json: /inputs/rocking_restitution: needs a model with rocking impacts: "
                "/scene/effects \"auto\", the full model's or [\"rocking\", \"impact\"]"});
}

TEST(RockingRestitutionStudy, EntersTheStudysHash) {
  json without = rocking_study();
  without["scene"]["contact"].erase("rocking_restitution");
  without.erase("inputs");
  json housner = without;
  housner["scene"]["contact"]["rocking_restitution"] = "housner";
  const auto hash = [](const json& d) { return parse_study_config(d, "study.json").hash; };
  EXPECT_NE(hash(without), hash(housner));
  EXPECT_NE(hash(housner), hash(rocking_study()));
}

json rocking_spectrum() {
  return json::parse(R"({
    "block": {"alpha": 0.25, "R": 1.0},
    "contact": {"friction": 2.0, "restitution": 0.3, "rocking_restitution": 0.9},
    "pulse": {"type": "cosine_pulse"},
    "frequency_ratio": {"values": [1, 2, 3]},
    "amplitude_ratio": {"from": 1, "to": 3, "count": 5}})");
}

TEST(RockingRestitutionSpectrum, EveryPointsSceneTakesTheSpecsRatio) {
  const SpectrumConfig config = parse_spectrum_config(rocking_spectrum(), "spec.json");
  const Scene point = spectrum_scene(config, 2.0, 1.5);
  ASSERT_TRUE(point.contact.rocking_restitution.has_value());
  EXPECT_EQ(point.contact.rocking_restitution->ratio, 0.9);
  EXPECT_EQ(config.canonical["contact"]["rocking_restitution"], 0.9);
  json without = rocking_spectrum();
  without["contact"].erase("rocking_restitution");
  const SpectrumConfig plain = parse_spectrum_config(without, "spec.json");
  EXPECT_FALSE(plain.canonical["contact"].contains("rocking_restitution"));
  EXPECT_NE(plain.hash, config.hash);
}

TEST(RockingRestitutionSpectrum, IsRefusedAtItsPath) {
  json document = rocking_spectrum();
  document["contact"]["rocking_restitution"] = 0.0;
  try {
    parse_spectrum_config(document, "spec.json");
    FAIL() << "accepted";
  } catch (const ConfigError& error) {
    EXPECT_EQ(std::string(error.what()),
              "spec.json: /contact/rocking_restitution: must be in (0, 1] (got 0)");
  }
}

}  // namespace
}  // namespace blockfrag
