// The scene's "seat" from JSON: every rule refused at its path, a seat that fits accepted, and the
// canonical scene keeping it.
#include "mpi_driver/config/seat_json.hpp"

#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "mpi_driver/config/scene_json.hpp"
#include "tests/support/scene_json_errors.hpp"

namespace blockfrag {
namespace {

using nlohmann::json;
using ::testing::HasSubstr;
using ::testing::Not;

json rectangle_on(const json& seat) {
  json scene = json::parse(R"({
    "block": {"half_width": 0.5, "half_height": 1.0},
    "contact": {"friction": 0.6, "restitution": 0.6},
    "ground_motion": {"type": "none"},
    "duration": 1.0})");
  scene["seat"] = seat;
  return scene;
}

using testing::scene_errors;

TEST(SeatJson, AFittingSeatIsAccepted) {
  EXPECT_EQ(scene_errors(rectangle_on(json::parse("[[-10, -1], [0.1, -1], [10, -1]]"))),
            "(accepted)");
}

// The canonical scene (a study's canonical config and hash, a sample written out as a scene file)
// keeps the seat: without it the scene file ran the block on the flat ground's engine.
TEST(SeatJson, TheCanonicalSceneKeepsTheSeat) {
  const json seat = json::parse("[[-10, -1], [0.1, -1], [10, -1]]");
  const json canonical = scene_to_json(scene_from_json(rectangle_on(seat), "scene.json"));
  EXPECT_EQ(canonical.at("seat"), seat);
  const Scene back = scene_from_json(canonical, "canonical.json");
  ASSERT_TRUE(back.seat.has_value());
  EXPECT_EQ(json(back.seat->points), seat);
  EXPECT_EQ(scene_to_json(back), canonical);
}

TEST(SeatJson, EveryRuleAtItsPath) {
  EXPECT_THAT(scene_errors(rectangle_on(json::parse("[[-10, -1], [10, \"a\"]]"))),
              HasSubstr("/seat/1/1:"));
  EXPECT_THAT(scene_errors(rectangle_on(json::parse("[[-10, -1], [10, -1, 3]]"))),
              HasSubstr("/seat/1: must be a point [x, y] (got 3 numbers)"));
  EXPECT_THAT(scene_errors(rectangle_on(json::parse("[[-10, -1], [-10, -1]]"))),
              HasSubstr("/seat/1: x must be greater than the previous point's"));
  EXPECT_THAT(scene_errors(rectangle_on(json::parse("[[-10, -0.9], [10, -0.9]]"))),
              HasSubstr("/seat: block vertex 0 lies"));
  EXPECT_THAT(scene_errors(rectangle_on(
                  json::parse("[[-10, -1.5], [-0.5, -1], [0, -0.9], [0.5, -1], [10, -1.5]]"))),
              HasSubstr("/seat/2: lies inside the block"));
  EXPECT_THAT(scene_errors(rectangle_on(json::parse("[[-10, -2], [10, -2]]"))),
              HasSubstr("/seat: does not touch the block"));
  EXPECT_THAT(scene_errors(rectangle_on(json::parse("{\"points\": []}"))), HasSubstr("/seat:"));
  json tilted = rectangle_on(json::parse("[[-10, -1], [0.5, -1], [0.6, 0]]"));
  tilted["initial"] = {{"theta", -0.1}};
  EXPECT_THAT(scene_errors(tilted),
              HasSubstr("/initial/theta: the block released tilted by it would enter the seat: "
                        "seat point 2: lies inside the block"));
  tilted["initial"] = {{"theta", 0.1}};
  EXPECT_EQ(scene_errors(tilted), "(accepted)");
  json sliding = rectangle_on(json::parse("[[-10, -1], [10, -1]]"));
  sliding["effects"] = {"sliding"};
  EXPECT_THAT(scene_errors(sliding),
              HasSubstr("/effects: must be \"auto\" or the full model's (rocking, sliding, impact, "
                        "flight) with a seat"));
}

// A seat's simulation watches every seat point and block vertex, 38 at most: a seat of 34 points
// under a rectangle (4 vertices) is the most it takes, one more is refused at /seat, by the
// reader, rather than as "invalid scene" by the engine without the file or the path.
TEST(SeatJson, SeatPointsAndBlockVerticesNumberAtMostThoseTheSimulationWatches) {
  const auto flat_seat = [](int points) {
    json seat = json::array();
    for (int k = 0; k < points; ++k) seat.push_back({-2.0 + 4.0 * k / (points - 1), -1.0});
    return seat;
  };
  EXPECT_EQ(scene_errors(rectangle_on(flat_seat(34))), "(accepted)");
  EXPECT_EQ(scene_errors(rectangle_on(flat_seat(35))),
            "scene.json: /seat: has 35 points; with the block's 4 vertices they number 39, more "
            "than the 38 a seat's simulation watches");
  EXPECT_THAT(scene_errors(rectangle_on(flat_seat(40))),
              HasSubstr("/seat: has 40 points; with the block's 4 vertices they number 44"));
}

// A block with errors of its own is not fitted to the seat (its vertices mean nothing).
TEST(SeatJson, NoFitForABlockWithErrors) {
  json scene = rectangle_on(json::parse("[[-10, -5], [10, -5]]"));
  scene["block"]["half_width"] = -1;
  const std::string errors = scene_errors(scene);
  EXPECT_THAT(errors, HasSubstr("/block/half_width"));
  EXPECT_THAT(errors, Not(HasSubstr("does not touch")));
}

}  // namespace
}  // namespace blockfrag
