// The scene's "reservoir" in JSON: the documented defaults, every rule refused at its path, the
// canonical form naming all of it (and nothing without it, so a dry scene keeps its form and a
// study its hash), and the engine refusing what the reader refuses.
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "engine/errors.hpp"
#include "engine/scene/scene_validation.hpp"
#include "mpi_driver/config/config_reader.hpp"
#include "mpi_driver/config/scene_json.hpp"
#include "tests/support/scene_json_errors.hpp"

namespace blockfrag {
namespace {

using nlohmann::json;
using ::testing::HasSubstr;

// A 10 m by 16 m block about its centre: its base at y = -8.
json scene_with_reservoir(const json& reservoir) {
  json scene = json::parse(R"({
    "block": {"half_width": 5.0, "half_height": 8.0, "mass": 384000},
    "contact": {"friction": 0.7, "restitution": 0.2},
    "ground_motion": {"type": "none"},
    "duration": 1.0})");
  scene["reservoir"] = reservoir;
  return scene;
}

using testing::scene_errors;

TEST(ReservoirJson, NoWaterUnlessTheSceneAsks) {
  json document = scene_with_reservoir(nullptr);
  document.erase("reservoir");
  const Scene scene = scene_from_json(document, "scene.json");
  EXPECT_FALSE(scene.reservoir.has_value());
  EXPECT_FALSE(scene_to_json(scene).contains("reservoir"));
}

TEST(ReservoirJson, ReadsALevelWithTheDocumentedDefaults) {
  const Scene scene = scene_from_json(scene_with_reservoir({{"level", 4.0}}), "scene.json");
  ASSERT_TRUE(scene.reservoir.has_value());
  EXPECT_EQ(scene.reservoir->level, 4.0);
  EXPECT_EQ(scene.reservoir->depth, 100.0);
  EXPECT_EQ(scene.reservoir->density, 1000.0);
  EXPECT_EQ(scene.reservoir->hydrodynamic, Hydrodynamic::westergaard);
  EXPECT_EQ(scene.reservoir->uplift, UpliftRule::unchanged);
  EXPECT_EQ(scene.reservoir->uplift_area_factor, 1.0);
  EXPECT_EQ(scene_to_json(scene)["reservoir"], (json{{"level", 4.0},
                                                     {"depth", 100.0},
                                                     {"density", 1000.0},
                                                     {"hydrodynamic", "westergaard"},
                                                     {"uplift", "unchanged"},
                                                     {"uplift_area_factor", 1.0}}));
}

TEST(ReservoirJson, ReadsEveryKeyAndWritesItBack) {
  for (const char* uplift : {"none", "unchanged", "zero_in_gap", "full_head_in_gap"}) {
    const json reservoir = {{"level", -2.5},     {"depth", 30.0},
                            {"density", 1020.0}, {"hydrodynamic", "none"},
                            {"uplift", uplift},  {"uplift_area_factor", 0.85}};
    const Scene scene = scene_from_json(scene_with_reservoir(reservoir), "scene.json");
    ASSERT_TRUE(scene.reservoir.has_value());
    EXPECT_EQ(scene.reservoir->hydrodynamic, Hydrodynamic::none);
    EXPECT_EQ(scene_to_json(scene)["reservoir"], reservoir);
    EXPECT_EQ(scene_to_json(scene_from_json(scene_to_json(scene), "canonical.json")),
              scene_to_json(scene));
  }
}

TEST(ReservoirJson, RefusesEachRuleAtItsPath) {
  EXPECT_EQ(scene_errors(scene_with_reservoir({{"depth", 50.0}})),
            "scene.json: /reservoir/level: is required");
  EXPECT_EQ(scene_errors(scene_with_reservoir({{"level", 2e5}})),
            "scene.json: /reservoir/level: must be in [-1e+05, 1e+05] (got 2e+05)");
  EXPECT_EQ(scene_errors(scene_with_reservoir({{"level", 4.0}, {"depth", 0.0}})),
            "scene.json: /reservoir/depth: must be in (0, 10000] (got 0)");
  EXPECT_EQ(scene_errors(scene_with_reservoir({{"level", 4.0}, {"density", -1000.0}})),
            "scene.json: /reservoir/density: must be in (0, 10000] (got -1000)");
  EXPECT_EQ(scene_errors(scene_with_reservoir({{"level", 4.0}, {"uplift_area_factor", 1.2}})),
            "scene.json: /reservoir/uplift_area_factor: must be in [0, 1] (got 1.2)");
  EXPECT_THAT(scene_errors(scene_with_reservoir({{"level", 4.0}, {"uplift", "full"}})),
              HasSubstr("/reservoir/uplift: must be one of"));
  EXPECT_THAT(scene_errors(scene_with_reservoir({{"level", 4.0}, {"hydrodynamic", "zangar"}})),
              HasSubstr("/reservoir/hydrodynamic: must be one of"));
  EXPECT_THAT(scene_errors(scene_with_reservoir({{"level", 4.0}, {"levle", 3.0}})),
              HasSubstr("/reservoir/levle: unknown key; did you mean \"level\"?"));
  EXPECT_THAT(scene_errors(scene_with_reservoir(16.7)), HasSubstr("/reservoir: must be an object"));
  // 12 m of water stands against the block (level 4, base at -8): a reservoir 10 m deep cannot.
  EXPECT_EQ(scene_errors(scene_with_reservoir({{"level", 4.0}, {"depth", 10.0}})),
            "scene.json: /reservoir/depth: must be >= the water's depth at the block, level minus "
            "the block's lowest y (12 m) (got 10)");
  EXPECT_EQ(scene_errors(scene_with_reservoir({{"level", 4.0}, {"depth", 12.0}})), "(accepted)");
  // Below the block the reservoir may be any depth: it does not touch the block.
  EXPECT_EQ(scene_errors(scene_with_reservoir({{"level", -9.0}, {"depth", 1.0}})), "(accepted)");
}

// The engine refuses a reservoir a library caller builds outside the rules.
TEST(ReservoirJson, TheEngineRefusesWhatTheReaderRefuses) {
  Scene scene = scene_from_json(scene_with_reservoir({{"level", 4.0}}), "scene.json");
  EXPECT_NO_THROW(validate_scene(scene));
  scene.reservoir->depth = 10.0;
  EXPECT_THROW(validate_scene(scene), InvalidInput);
  scene.reservoir->depth = 100.0;
  scene.reservoir->uplift_area_factor = -0.1;
  EXPECT_THROW(validate_scene(scene), InvalidInput);
}

}  // namespace
}  // namespace blockfrag
