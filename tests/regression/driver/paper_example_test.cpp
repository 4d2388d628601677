// The paper's section 3 example (configs/paper_example.json) against the paper's statements.
#include <cmath>
#include <filesystem>
#include <numbers>

#include <gtest/gtest.h>

#include "engine/simulate.hpp"
#include "mpi_driver/config/scene_json.hpp"

namespace blockfrag {
namespace {

Scene paper_scene() {
  return read_scene_file(std::filesystem::path(BLOCKFRAG_SOURCE_DIR) /
                         "configs/paper_example.json");
}

TEST(PaperExample, FrictionCannotHoldPureRockingWhenThePulseStarts) {
  // Eq. 2.7 at t = 0+: lambda = 1 needs |F|/V = mu_cr(1) = 0.6087 (Shenton), above mu = 0.6.
  const double beta = 0.5, A = 1.0;
  const double mu_cr = (A * (4 * beta * beta + 1) + 3 * beta) / (beta * beta + 4 + 3 * A * beta);
  ASSERT_GT(mu_cr, paper_scene().contact.friction);
  const Summary s = simulate(paper_scene());
  EXPECT_EQ(s.modes.at(0).mode, ModeKind::slide_rock);
  ASSERT_TRUE(s.rock_start_time.has_value());
  ASSERT_TRUE(s.slide_start_time.has_value());
  EXPECT_EQ(*s.rock_start_time, 0.0);
  EXPECT_EQ(*s.slide_start_time, 0.0);
}

TEST(PaperExample, RocksClockwiseAboutTheRightCornerThenSlipsBeforeTheFirstImpactAndJumps) {
  const auto run = simulate_with_history(paper_scene(), 0.001);
  const Summary& s = run.summary;
  ASSERT_TRUE(s.first_impact_time.has_value());
  // Clockwise (theta < 0) about the right corner up to the first impact.
  double max_clockwise = 0.0;
  for (const HistoryRow& row : run.history) {
    if (row.t < *s.first_impact_time) {
      EXPECT_LE(row.theta, 1e-12);
      max_clockwise = std::max(max_clockwise, -row.theta);
    }
  }
  // The paper: "The maximum rotation clockwise is about 23 deg, less than the critical 26.56 deg".
  EXPECT_NEAR(max_clockwise * 180 / std::numbers::pi, 23.0, 0.5);
  EXPECT_LT(max_clockwise, std::atan(0.5));
  // The pivot slips (slide-rock) again before the first impact, and the block jumps after it.
  bool slips_before_impact = false;
  for (std::size_t i = 1; i < s.modes.size(); ++i) {
    if (s.modes[i].time < *s.first_impact_time && s.modes[i].mode == ModeKind::slide_rock) {
      slips_before_impact = true;
    }
  }
  EXPECT_TRUE(slips_before_impact);
  ASSERT_FALSE(run.impacts.empty());
  EXPECT_EQ(run.impacts.front().mode_after, ModeKind::flight);
}

}  // namespace
}  // namespace blockfrag
