// The water's loads on the paper's type A dam block (configs/dam_block_type_a.json: its upstream
// face vertical, 16.7 m high, on a 12.55 m base) with the reservoir at the crest, against the
// hand computations (rho_w = 1000 kg/m^3, g = 9.81 m/s^2, d = 16.7 m, B = 12.55 m, H = 100 m):
//   hydrostatic 1/2 rho_w g d^2 = 1.37 MN/m at d/3 above the base (USACE EM 1110-2-2200, 1995),
//   uplift 1/2 rho_w g d B = 1.03 MN/m at B/3 from the heel (head d at the heel, falling linearly
//   to zero at the toe: EM 1110-2-2200 and FERC's guidelines chapter III),
//   Westergaard's added mass (7/12) rho_w sqrt(H) d^(3/2) = 398 t/m at 0.4 d above the base
//   (Westergaard 1933, Trans. ASCE 98: m_w = (7/8) rho_w sqrt(H y) per unit area at depth y).
#include <array>
#include <cmath>
#include <cstddef>
#include <filesystem>

#include <gtest/gtest.h>

#include "engine/scene/polygon_properties.hpp"
#include "engine/water/hydrostatic.hpp"
#include "engine/water/uplift.hpp"
#include "engine/water/westergaard.hpp"
#include "mpi_driver/config/scene_json.hpp"
#include "tests/support/paper_block.hpp"
#include "tests/support/water_outlines.hpp"

namespace blockfrag {
namespace {

using testing::kGravity;
using testing::kWaterDensity;
constexpr double kDepth = 16.7, kBaseLength = 12.55, kPool = 100.0;

WorldPolygon type_a_outline() {
  const Scene scene = read_scene_file(std::filesystem::path(BLOCKFRAG_SOURCE_DIR) /
                                      "configs/dam_block_type_a.json");
  return {scene.polygon->vertices.begin(), scene.polygon->vertices.end()};
}

TEST(TypeABlockWaterLoads, ReservoirAtTheCrestMatchesTheHandValues) {
  const WorldPolygon outline = type_a_outline();
  ASSERT_EQ(outline.size(), 5u);
  // The base is edge 0, from the heel (0, 0) to the toe (12.55, 0); the crest is at 16.7 m.
  ASSERT_EQ(outline[0], (Vertex{0.0, 0.0}));
  ASSERT_EQ(outline[1], (Vertex{kBaseLength, 0.0}));
  const Vertex centre = polygon_properties(outline).centroid;
  const StillWater water{kDepth, kWaterDensity, kGravity};

  const WaterLoad push = hydrostatic_load(outline, water, testing::kBaseEdge, centre);
  const double push_hand = 0.5 * kWaterDensity * kGravity * kDepth * kDepth;
  EXPECT_NEAR(push.fx, push_hand, 1e-12 * push_hand);
  EXPECT_NEAR(push.fx / 1e6, 1.37, 0.005);
  EXPECT_EQ(push.fy, 0.0);
  EXPECT_NEAR(centre[1] - push.moment / push.fx, kDepth / 3, 1e-12 * kDepth);

  const UpliftLoad uplift = crack_uplift({0.0, kBaseLength, 0.0}, water, 1.0, centre);
  const double uplift_hand = 0.5 * kWaterDensity * kGravity * kDepth * kBaseLength;
  EXPECT_NEAR(uplift.force, uplift_hand, 1e-12 * uplift_hand);
  EXPECT_NEAR(uplift.force / 1e6, 1.03, 0.005);
  EXPECT_NEAR(uplift.point_x, kBaseLength / 3, 1e-12);

  const AddedMass added =
      westergaard_added_mass(outline, kDepth, kWaterDensity, kPool, testing::kBaseEdge, 0.0);
  const double added_hand = 7.0 / 12.0 * kWaterDensity * std::sqrt(kPool) * std::pow(kDepth, 1.5);
  EXPECT_NEAR(added.mass, added_hand, 1e-12 * added_hand);
  EXPECT_NEAR(added.mass / 1e3, 398.0, 0.5);
  EXPECT_NEAR(added.first_moment / added.mass, 0.4 * kDepth, 1e-12 * kDepth);
}

}  // namespace
}  // namespace blockfrag
