// The scene's "dam" in JSON: both ways of giving the period, the documented defaults, every rule
// refused at its path, and the canonical form reading back to the same values.
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "mpi_driver/config/config_reader.hpp"
#include "mpi_driver/config/scene_json.hpp"
#include "tests/support/scene_json_errors.hpp"

namespace blockfrag {
namespace {

using nlohmann::json;
using ::testing::HasSubstr;

json scene_with_dam(const json& dam) {
  json scene = json::parse(R"({
    "block": {"half_width": 0.5, "half_height": 1.0},
    "contact": {"friction": 0.6, "restitution": 0.6},
    "ground_motion": {"type": "sine_pulse", "amplitude_g": 0.3, "period": 0.25, "cycles": 4},
    "duration": 3.0})");
  scene["dam"] = dam;
  return scene;
}

using testing::scene_errors;

TEST(DamJson, NoDamUnlessTheSceneAsks) {
  json document = scene_with_dam(nullptr);
  document.erase("dam");
  const Scene scene = scene_from_json(document, "scene.json");
  EXPECT_FALSE(scene.dam.has_value());
  EXPECT_FALSE(scene_to_json(scene).contains("dam"));
}

TEST(DamJson, ReadsAPeriodWithTheDocumentedDefaults) {
  const Scene scene = scene_from_json(scene_with_dam({{"period", 0.3}}), "scene.json");
  ASSERT_TRUE(scene.dam.has_value());
  EXPECT_EQ(std::get<DamPeriod>(scene.dam->stiffness).period, 0.3);
  EXPECT_EQ(scene.dam->damping, 0.05);
  EXPECT_EQ(scene.dam->participation, 1.0);
}

TEST(DamJson, ReadsHeightAndModulusAndWritesThemBack) {
  const json dam = {
      {"height", 100.0}, {"elastic_modulus", 25e9}, {"damping", 0.1}, {"participation", 1.6}};
  const Scene scene = scene_from_json(scene_with_dam(dam), "scene.json");
  ASSERT_TRUE(scene.dam.has_value());
  const auto& size = std::get<DamSize>(scene.dam->stiffness);
  EXPECT_EQ(size.height, 100.0);
  EXPECT_EQ(size.elastic_modulus, 25e9);
  EXPECT_EQ(scene.dam->damping, 0.1);
  EXPECT_EQ(scene.dam->participation, 1.6);
  EXPECT_EQ(scene_to_json(scene)["dam"], dam);
  const Scene again = scene_from_json(scene_to_json(scene), "canonical.json");
  EXPECT_EQ(scene_to_json(again), scene_to_json(scene));
}

TEST(DamJson, RefusesEachRuleAtItsPath) {
  EXPECT_EQ(
      scene_errors(scene_with_dam({{"period", 0.3}, {"height", 100.0}, {"elastic_modulus", 25e9}})),
      "scene.json: /dam/period: give either period or height and elastic_modulus, not both");
  EXPECT_EQ(scene_errors(scene_with_dam({{"damping", 0.05}})),
            "scene.json: /dam: needs period, or height and elastic_modulus");
  EXPECT_EQ(scene_errors(scene_with_dam({{"height", 100.0}})),
            "scene.json: /dam/elastic_modulus: is required");
  EXPECT_EQ(scene_errors(scene_with_dam({{"period", 0.0}})),
            "scene.json: /dam/period: must be in [0.001, 10] (got 0)");
  EXPECT_EQ(scene_errors(scene_with_dam({{"period", 0.3}, {"damping", 1.0}})),
            "scene.json: /dam/damping: must be in [0, 1) (got 1)");
  EXPECT_EQ(scene_errors(scene_with_dam({{"period", 0.3}, {"damping", -0.1}})),
            "scene.json: /dam/damping: must be in [0, 1) (got -0.1)");
  EXPECT_EQ(scene_errors(scene_with_dam({{"period", 0.3}, {"participation", -1.0}})),
            "scene.json: /dam/participation: must be in (0, 100] (got -1)");
  EXPECT_THAT(scene_errors(scene_with_dam({{"period", 0.3}, {"dampng", 0.1}})),
              HasSubstr("/dam/dampng: unknown key; did you mean \"damping\"?"));
  EXPECT_THAT(scene_errors(scene_with_dam(0.3)), HasSubstr("/dam: must be an object"));
}

}  // namespace
}  // namespace blockfrag
