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
using ::testing::Not;

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

// Fenves & Chopra's reservoir and foundation: read, written back only when they change the dam
// (so a scene without them, or with their defaults spelled out, keeps its canonical form).
TEST(DamJson, ReadsTheReservoirAndFoundationAndWritesThemOnlyWhenSet) {
  const json wet = {{"period", 0.443},
                    {"damping", 0.07},
                    {"participation", 1.0},
                    {"reservoir_period_ratio", 1.11},
                    {"reservoir_damping", 0.0158},
                    {"foundation_period_ratio", 1.19},
                    {"foundation_damping", 0.0701}};
  const Scene scene = scene_from_json(scene_with_dam(wet), "scene.json");
  ASSERT_TRUE(scene.dam.has_value());
  EXPECT_EQ(scene.dam->reservoir_period_ratio, 1.11);
  EXPECT_EQ(scene.dam->reservoir_damping, 0.0158);
  EXPECT_EQ(scene.dam->foundation_period_ratio, 1.19);
  EXPECT_EQ(scene.dam->foundation_damping, 0.0701);
  EXPECT_EQ(scene_to_json(scene)["dam"], wet);

  const json spelled = {{"period", 0.3},
                        {"reservoir_period_ratio", 1.0},
                        {"reservoir_damping", 0.0},
                        {"foundation_period_ratio", 1.0},
                        {"foundation_damping", 0.0}};
  const json canonical = scene_to_json(scene_from_json(scene_with_dam(spelled), "scene.json"));
  EXPECT_EQ(canonical["dam"], (json{{"period", 0.3}, {"damping", 0.05}, {"participation", 1.0}}));
  EXPECT_EQ(canonical, scene_to_json(scene_from_json(scene_with_dam({{"period", 0.3}}), "s.json")));
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
  EXPECT_EQ(scene_errors(scene_with_dam({{"period", 0.3}, {"reservoir_period_ratio", 0.9}})),
            "scene.json: /dam/reservoir_period_ratio: must be in [1, 10] (got 0.9)");
  EXPECT_EQ(scene_errors(scene_with_dam({{"period", 0.3}, {"foundation_period_ratio", 11}})),
            "scene.json: /dam/foundation_period_ratio: must be in [1, 10] (got 11)");
  EXPECT_EQ(scene_errors(scene_with_dam({{"period", 0.3}, {"reservoir_damping", -0.01}})),
            "scene.json: /dam/reservoir_damping: must be in [0, 1) (got -0.01)");
  EXPECT_EQ(scene_errors(scene_with_dam({{"period", 0.3}, {"foundation_damping", 1.0}})),
            "scene.json: /dam/foundation_damping: must be in [0, 1) (got 1)");
  // Each damping in its range, but the mode's (0.5 / (1 x 1) + 0.25 + 0.25 = 1) overdamped.
  EXPECT_EQ(scene_errors(scene_with_dam({{"period", 0.3},
                                         {"damping", 0.5},
                                         {"reservoir_damping", 0.25},
                                         {"foundation_damping", 0.25}})),
            "scene.json: /dam: the damping with the reservoir and foundation, damping / "
            "(reservoir_period_ratio foundation_period_ratio^3) + reservoir_damping + "
            "foundation_damping, must be < 1 (got 1)");
  EXPECT_THAT(scene_errors(scene_with_dam({{"period", 0.3}, {"dampng", 0.1}})),
              HasSubstr("/dam/dampng: unknown key; did you mean \"damping\"?"));
  EXPECT_THAT(scene_errors(scene_with_dam(0.3)), HasSubstr("/dam: must be an object"));
}

// The crest history is a node per period / 100 over the run, at most 2,000,000: a scene that
// needs more is refused at /dam by the reader, before any work, and not by the engine once the run
// starts without the file or the path. Counts by hand, at steps of 0.001 s / 100: a 10 s cosine
// pulse and the 60 s a settling run allows after it, 1,000,000 + 6,000,000 steps, a node more for
// each of the two pieces and one to start with; a fixed 3 s run, 300,000 steps.
TEST(DamJson, RefusesACrestHistoryOfMoreNodesThanARunHolds) {
  EXPECT_EQ(scene_errors(scene_with_dam({{"period", 0.001}})), "(accepted)");
  json settling = scene_with_dam({{"period", 0.001}});
  settling.erase("duration");
  settling["ground_motion"] = {{"type", "cosine_pulse"}, {"amplitude_g", 1.0}, {"period", 10.0}};
  EXPECT_EQ(scene_errors(settling),
            "scene.json: /dam: the dam's period (0.001 s) is too short for the run (70 s): the "
            "crest motion would need 7000003 nodes (one per period / 100), more than 2000000; give "
            "a longer period, or a duration or max_duration that ends the run sooner");
  settling["max_duration"] = 20.0;
  EXPECT_THAT(scene_errors(settling), HasSubstr("too short for the run (20 s)"));
  settling["max_duration"] = 19.0;
  EXPECT_EQ(scene_errors(settling), "(accepted)");
  // The reservoir and foundation lengthen the period the crest is stepped at: 2 x 0.001 s.
  settling["max_duration"] = 39.0;
  settling["dam"]["reservoir_period_ratio"] = 2.0;
  EXPECT_EQ(scene_errors(settling), "(accepted)");
  settling["max_duration"] = 41.0;
  EXPECT_THAT(
      scene_errors(settling),
      HasSubstr("the dam's period (0.002 s, with its reservoir and foundation) is too short "
                "for the run (41 s)"));
  // Other errors first: the crest is counted only for an otherwise valid scene.
  settling["contact"]["friction"] = -1;
  EXPECT_THAT(scene_errors(settling), Not(HasSubstr("/dam")));
}

}  // namespace
}  // namespace blockfrag
