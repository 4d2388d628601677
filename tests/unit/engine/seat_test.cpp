// Seats (engine/scene/seat.hpp): which polylines a block fits at rest, where it touches them, and
// the tilt its results are measured in (alpha).
#include "engine/scene/seat.hpp"

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "engine/errors.hpp"
#include "engine/scene/scene_validation.hpp"
#include "tests/support/type_b_block.hpp"

namespace blockfrag {
namespace {

using ::testing::HasSubstr;

constexpr double kTolerance = 1e-9;

// A 1 x 2 rectangle about its centre, as scene_block_vertices lists it.
const std::vector<Vertex> kRectangle = {{-0.5, -1}, {0.5, -1}, {0.5, 1}, {-0.5, 1}};

using testing::kFoldX;
using testing::kTypeB;
using testing::kTypeBSeat;

std::string defect_of(const std::vector<Vertex>& seat, const std::vector<Vertex>& block) {
  const auto defect = seat_defect(seat, block, kTolerance);
  return defect ? std::to_string(defect->point) + ": " + defect->rule : "";
}

TEST(Seat, FlatSeatsFit) {
  EXPECT_EQ(defect_of({{-10, -1}, {10, -1}}, kRectangle), "");
  // Two collinear segments meeting under the block, and a seat just as wide as the base.
  EXPECT_EQ(defect_of({{-10, -1}, {0.1, -1}, {10, -1}}, kRectangle), "");
  EXPECT_EQ(defect_of({{-0.5, -1}, {0.5, -1}}, kRectangle), "");
}

TEST(Seat, TypeBBlockFitsItsSeatAndTouchesAtHeelFoldAndToe) {
  EXPECT_EQ(defect_of(kTypeBSeat, kTypeB), "");
  const std::vector<RestContact> contacts = rest_contacts(kTypeBSeat, kTypeB, kTolerance);
  // Block vertices on seat segments: heel and fold on the horizontal one, fold and toe on the
  // incline; seat points on block edges: the heel (2 edges), the fold (2) and the toe (2).
  int horizontal = 0, incline = 0;
  for (const RestContact& c : contacts) {
    if (c.normal[0] == 0.0 && c.normal[1] == 1.0) ++horizontal;
    if (std::abs(c.normal[0] + 0.6) < 1e-15 && std::abs(c.normal[1] - 0.8) < 1e-15) ++incline;
  }
  EXPECT_EQ(contacts.size(), 10u);
  EXPECT_EQ(horizontal, 4);  // heel, fold on the horizontal segment; seat heel, fold on the base
  EXPECT_EQ(incline, 4);     // fold, toe on the incline; seat fold, toe on the crack's incline
}

// The centroid of a polygon by the shoelace formula, written out here rather than taken from
// polygon_properties, which seat_alpha uses.
Vertex shoelace_centroid(const std::vector<Vertex>& p) {
  double area = 0, x = 0, y = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vertex& a = p[i];
    const Vertex& b = p[(i + 1) % p.size()];
    const double w = a[0] * b[1] - b[0] * a[1];
    area += w / 2;
    x += (a[0] + b[0]) * w / 6;
    y += (a[1] + b[1]) * w / 6;
  }
  return {x / area, y / area};
}

// On a flat seat the rectangle balances on a base corner at atan(a/b); the type B block on its seat
// tips over its heel (the origin) before its toe (12.525, 5): atan(c_x / c_y) against
// atan((12.525 - c_x) / (c_y - 5)), about 0.433 and 0.894 rad.
TEST(Seat, AlphaIsTheTiltOverTheOutermostSupport) {
  EXPECT_NEAR(seat_alpha({{-10, -1}, {10, -1}}, kRectangle, kTolerance), std::atan2(0.5, 1.0),
              1e-15);
  EXPECT_NEAR(seat_alpha({{-10, -1}, {0.1, -1}, {10, -1}}, kRectangle, kTolerance),
              std::atan2(0.5, 1.0), 1e-15);
  const Vertex c = shoelace_centroid(kTypeB);
  const double heel = std::atan2(c[0], c[1]), toe = std::atan2(12.525 - c[0], c[1] - 5);
  ASSERT_LT(heel, toe);
  EXPECT_NEAR(seat_alpha(kTypeBSeat, kTypeB, kTolerance), heel, 1e-14);
  EXPECT_NEAR(heel, 0.4328, 1e-4);
}

// A block above its seat (a study once drew a taller block over a seat fitted to another) touches
// it nowhere: no support to measure alpha over or to tilt about, which is the scene's fault.
TEST(Seat, ABlockThatDoesNotTouchItsSeatHasNoAlphaAndNoPivot) {
  const std::vector<Vertex> seat = {{-2, -1.5}, {2, -1.5}};
  EXPECT_THAT(defect_of(seat, kRectangle), HasSubstr("does not touch the block"));
  try {
    seat_alpha(seat, kRectangle, kTolerance);
    FAIL() << "seat_alpha measured a block that does not touch its seat";
  } catch (const InvalidInput& error) {
    EXPECT_THAT(error.what(), HasSubstr("invalid scene: seat: does not touch the block"));
  }
  EXPECT_THROW(tilt_on_seat(seat, kRectangle, 0.1, kTolerance), InvalidInput);
  EXPECT_THROW(tilt_on_seat(seat, kRectangle, -0.1, kTolerance), InvalidInput);
}

TEST(Seat, PointsMustRunLeftToRight) {
  EXPECT_THAT(defect_of({{-10, -1}}, kRectangle), HasSubstr("at least 2 points"));
  EXPECT_THAT(defect_of({{-10, -1}, {0, -1}, {0, -1}, {10, -1}}, kRectangle),
              HasSubstr("2: x must be greater than the previous point's"));
  EXPECT_THAT(defect_of({{10, -1}, {-10, -1}}, kRectangle),
              HasSubstr("1: x must be greater than the previous point's"));
}

TEST(Seat, TheBlockMustNotBeInTheSeat) {
  // The ground 1 mm above the base: both base corners are below it.
  EXPECT_THAT(defect_of({{-10, -0.999}, {10, -0.999}}, kRectangle),
              HasSubstr("-1: block vertex 0 lies 0.001"));
  // A ridge poking up into the base between its corners, which rest on the seat.
  EXPECT_THAT(defect_of({{-10, -1.5}, {-0.5, -1}, {0, -0.9}, {0.5, -1}, {10, -1.5}}, kRectangle),
              HasSubstr("2: lies inside the block"));
}

TEST(Seat, TheBlockMustRestOnIt) {
  EXPECT_THAT(defect_of({{-10, -1.001}, {10, -1.001}}, kRectangle),
              HasSubstr("does not touch the block"));
  // Only the left corner touches: the centre of mass is not over the support.
  EXPECT_THAT(defect_of({{-10, -1}, {-0.5, -1}, {10, -12}}, kRectangle),
              HasSubstr("does not carry the block at rest"));
  // On one incline the block would need friction (a square turned by 45 degrees, a face on it).
  const std::vector<Vertex> diamond = {{0, 0}, {1, 1}, {0, 2}, {-1, 1}};
  EXPECT_THAT(defect_of({{-10, -10}, {10, 10}}, diamond),
              HasSubstr("does not carry the block at rest"));
  // In a V of two inclines normal pushes alone carry it.
  EXPECT_EQ(defect_of({{-10, 10}, {0, 0}, {10, 10}}, diamond), "");
  // The type B block on the horizontal part alone is carried (its centre of mass is over it), but
  // not when that part starts at x = 5.5, past its centre of mass (x = 5.07): the heel hangs over
  // the reservoir.
  EXPECT_EQ(defect_of({{0, 0}, {kFoldX, 0}}, kTypeB), "");
  EXPECT_THAT(defect_of({{5.5, 0}, {kFoldX, 0}, {12.525, 5}}, kTypeB),
              HasSubstr("does not carry the block at rest"));
}

// validate_scene refuses the scene, naming `rule`.
void expect_scene_refused(const Scene& scene, const std::string& rule) {
  try {
    validate_scene(scene);
    ADD_FAILURE() << "accepted; expected a refusal naming: " << rule;
  } catch (const InvalidInput& error) {
    EXPECT_THAT(error.what(), HasSubstr(rule));
  }
}

TEST(Seat, SceneWithASeatIsChecked) {
  Scene scene;
  scene.seat = Seat{{{-10, -1}, {10, -1}}};
  EXPECT_NO_THROW(validate_scene(scene));
  scene.seat = Seat{{{-10, -0.9}, {10, -0.9}}};
  expect_scene_refused(scene, "seat: block vertex 0 lies");
  // Released tilted, the block turns about the base corner the tilt lowers: clear of a flat seat,
  // but not of an incline rising from its right corner steeper than its face turned clockwise
  // about that corner.
  scene.seat = Seat{{{-10, -1}, {10, -1}}};
  scene.initial.theta = 0.1;
  EXPECT_NO_THROW(validate_scene(scene));
  scene.initial.theta = -0.1;
  EXPECT_NO_THROW(validate_scene(scene));
  scene.seat = Seat{{{-10, -1}, {0.5, -1}, {0.6, 0.0}}};
  scene.initial.theta = 0.1;
  EXPECT_NO_THROW(validate_scene(scene));  // turning about the left corner lifts the face
  scene.initial.theta = -0.1;
  expect_scene_refused(scene,
                       "initial theta: the block released tilted by it would enter the seat");
  scene.seat = Seat{{{-10, -1}, {0.5, -1}, {0.8, 1.0}}};
  EXPECT_NO_THROW(validate_scene(scene));  // less steep than the turned face: clear of it
  scene.initial.theta = 0.0;
  // The seat's simulation is the full model's: a reduced one named is refused, not ignored.
  scene.initial.theta = 0.0;
  scene.effects = Effects{false, true, false, true, false, false};  // Housner with impacts
  expect_scene_refused(scene, "effects on a seat must be \"auto\" or the full");
  scene.effects = Effects{false, true, true, true, true, false};
  EXPECT_NO_THROW(validate_scene(scene));
}

}  // namespace
}  // namespace blockfrag
