// The reservoir's loads found once per pose against the same loads found anew, at random poses,
// velocities, ground accelerations and openings: the head at the crack's mouth taken from the
// placed outline (ReservoirLoads::pose) is the placed crack's, and the seated loads a search for
// the crack's opening tries at one state (ReservoirLoad::search_openings) are seated_opened's, to
// the bit; the closed and the whole open crack's uplift, found once on the unturned block and
// turned with it, is the crack's pressure integrated at the pose to 1e-12.
#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "engine/scene/scene_validation.hpp"
#include "engine/sine_cosine.hpp"
#include "engine/water/reservoir_load.hpp"
#include "engine/water/reservoir_loads.hpp"
#include "tests/support/fixed_uniforms.hpp"
#include "tests/support/same_bits.hpp"
#include "tests/support/wet_dam_blocks.hpp"

namespace blockfrag {
namespace {

using testing::same_bits;

using testing::FixedUniforms;

constexpr int kWetPoses = 300;

BlockState random_wet_state(FixedUniforms& u, const BlockState& rest) {
  BlockState s = rest;
  s.x += u(-0.5, 0.5);
  s.y += u(-0.2, 0.5);
  s.theta = u(-0.3, 0.3);
  s.vx = u(-1.0, 1.0);
  s.vy = u(-1.0, 1.0);
  s.omega = u(-0.5, 0.5);
  return s;
}

// The type B block on its seat: its crack runs from the heel over the fold to the toe, all
// vertices.
Scene wet_type_b(UpliftRule rule) { return testing::wet_type_b_step(0.8, 0.3, rule); }

// The same block on a seat that ends halfway up the incline: the crack ends inside an edge.
Scene wet_type_b_short_seat(UpliftRule rule) {
  Scene scene = wet_type_b(rule);
  const Vertex fold = scene.seat->points[1], toe = scene.seat->points[2];
  scene.seat->points[2] = {0.5 * (fold[0] + toe[0]), 0.5 * (fold[1] + toe[1])};
  return scene;
}

// The crack at the pose, as the general uplift places it.
std::vector<Vertex> placed_crack(const ReservoirLoads& loads, const ReservoirPose& pose) {
  std::vector<Vertex> placed(loads.crack().points.size());
  place_crack(loads.crack().points, pose.turn.cos, pose.turn.sin, pose.centre, placed);
  return placed;
}

void expect_mouth_head_of_placed_crack(const Scene& scene) {
  validate_scene(scene);
  const ReservoirLoads loads(scene);
  const Reservoir& water = *scene.reservoir;
  const BlockState rest = BlockOutline(scene).rest_state();
  FixedUniforms u(17);
  for (int i = 0; i < kWetPoses; ++i) {
    const BlockState s = random_wet_state(u, rest);
    const ReservoirPose pose = loads.pose(s);
    const SineCosine turn = sine_cosine(s.theta);
    ASSERT_TRUE(same_bits(pose.turn.sin, turn.sin) && same_bits(pose.turn.cos, turn.cos));
    const double head = std::max(0.0, water.level - placed_crack(loads, pose).front()[1]);
    EXPECT_TRUE(same_bits(pose.full_head, water.density * scene.g * head)) << i;
  }
}

TEST(ReservoirPose, TheHeadAtAMouthOnAVertexIsThePlacedCracks) {
  expect_mouth_head_of_placed_crack(wet_type_b(UpliftRule::zero_in_gap));
}

TEST(ReservoirPose, TheHeadAtAMouthInsideAnEdgeIsThePlacedCracks) {
  Scene scene = wet_type_b(UpliftRule::zero_in_gap);
  // The seat from the middle of the base: the crack's mouth lies inside the base.
  scene.seat->points[0] = {0.5 * scene.seat->points[1][0], 0.0};
  ASSERT_NE(ReservoirLoads(scene).crack().points.front()[0], BlockOutline(scene).body().front()[0]);
  expect_mouth_head_of_placed_crack(scene);
}

void expect_fixed_uplifts_turned(const Scene& scene) {
  validate_scene(scene);
  const ReservoirLoads loads(scene);
  const std::vector<double> lengths = segment_lengths(loads.crack().points);
  const BlockState rest = BlockOutline(scene).rest_state();
  FixedUniforms u(29);
  for (int i = 0; i < kWetPoses; ++i) {
    const BlockState s = random_wet_state(u, rest);
    const ReservoirPose pose = loads.pose(s);
    for (const CrackOpening open : {CrackOpening::closed(), CrackOpening::whole()}) {
      const WaterLoad general =
          crack_pressure_load(placed_crack(loads, pose), lengths,
                              crack_pressure(scene.reservoir->uplift, loads.crack().length(),
                                             pose.closed_mouth, pose.full_head, open),
                              pose.centre);
      const WaterLoad turned = loads.uplift(pose, open);
      const double force = std::max({std::abs(general.fx), std::abs(general.fy), 1.0});
      const double arm = loads.crack().length();
      EXPECT_NEAR(turned.fx, general.fx, 1e-12 * force) << i;
      EXPECT_NEAR(turned.fy, general.fy, 1e-12 * force) << i;
      EXPECT_NEAR(turned.moment, general.moment, 1e-12 * force * arm) << i;
    }
  }
}

TEST(ReservoirPose, TheFixedOpeningsUpliftTurnedIsThePressureIntegratedAtThePose) {
  for (const UpliftRule rule :
       {UpliftRule::unchanged, UpliftRule::zero_in_gap, UpliftRule::full_head_in_gap}) {
    SCOPED_TRACE(static_cast<int>(rule));
    expect_fixed_uplifts_turned(wet_type_b(rule));
    expect_fixed_uplifts_turned(wet_type_b_short_seat(rule));
  }
}

// Records the loads a search tries, to compare once the search is over.
class RecordingSearch final : public CrackOpeningSearch {
 public:
  explicit RecordingSearch(std::vector<std::pair<LiftingSide, double>> tries)
      : tries_(std::move(tries)) {}
  void search(const CrackOpenings& openings) override {
    for (const auto& [side, fraction] : tries_) found_.push_back(openings.opened(side, fraction));
  }
  const std::vector<std::pair<LiftingSide, double>>& tries() const { return tries_; }
  const std::vector<LoadAddition>& found() const { return found_; }

 private:
  std::vector<std::pair<LiftingSide, double>> tries_;
  std::vector<LoadAddition> found_;
};

void expect_same_addition(const LoadAddition& a, const LoadAddition& b) {
  EXPECT_TRUE(same_bits(a.force.x, b.force.x));
  EXPECT_TRUE(same_bits(a.force.y, b.force.y));
  EXPECT_TRUE(same_bits(a.moment, b.moment));
  EXPECT_TRUE(same_bits(a.xx, b.xx));
  EXPECT_TRUE(same_bits(a.xtheta, b.xtheta));
  EXPECT_TRUE(same_bits(a.thetatheta, b.thetatheta));
}

void expect_openings_are_seated_opened(const Scene& scene) {
  validate_scene(scene);
  const ReservoirLoad load(scene);
  const BlockState rest = BlockOutline(scene).rest_state();
  FixedUniforms u(23);
  for (int i = 0; i < kWetPoses; ++i) {
    const BlockState s = random_wet_state(u, rest);
    const double lambda = u(-1.0, 1.0);
    std::vector<std::pair<LiftingSide, double>> tries{{LiftingSide::upstream, 0.0},
                                                      {LiftingSide::downstream, 1.0}};
    for (int k = 0; k < 4; ++k) {
      tries.emplace_back(u(0.0, 1.0) < 0.5 ? LiftingSide::upstream : LiftingSide::downstream,
                         u(0.0, 1.0));
    }
    RecordingSearch search(tries);
    load.search_openings(s, lambda, scene.g, search);
    ASSERT_EQ(search.found().size(), tries.size());
    for (std::size_t k = 0; k < tries.size(); ++k) {
      SCOPED_TRACE(::testing::Message() << "state " << i << ", opening " << k);
      expect_same_addition(search.found()[k],
                           load.seated_opened(s, lambda, scene.g, tries[k].first, tries[k].second));
    }
  }
}

TEST(ReservoirPose, EveryOpeningASearchTriesIsSeatedOpeneds) {
  for (const UpliftRule rule : {UpliftRule::zero_in_gap, UpliftRule::full_head_in_gap,
                                UpliftRule::unchanged, UpliftRule::none}) {
    SCOPED_TRACE(static_cast<int>(rule));
    expect_openings_are_seated_opened(wet_type_b(rule));
    expect_openings_are_seated_opened(wet_type_b_short_seat(rule));
  }
}

}  // namespace
}  // namespace blockfrag
