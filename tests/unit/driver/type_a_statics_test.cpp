// `blockfrag statics` of the paper's type A dam block (configs/dam_block_type_a.json and
// configs/dam_block_type_a_reservoir.json: a 12.55 m base, 16.7 m high, 411,204 kg per metre, mu
// 1.05) against hand computations. Its centre of mass from its two parts: a 10 m x 16.7 m
// rectangle (area 167, centroid (5, 8.35)) and the toe's triangle (10, 0), (12.55, 0), (10, 3.4)
// (area 4.335, centroid (10.85, 3.4/3)). With the water d deep against its vertical upstream face
// (rho_w = 1000, g = 9.81, H = 100 m): P = 1/2 rho g d^2 at d/3, U = 1/2 rho g d B at B/3 from the
// heel, M_a = (7/12) rho sqrt(H) d^(3/2), S_base = (7/30) rho sqrt(H) d^(5/2); the yield
// accelerations and factors as in engine/water/block_statics.hpp, about the toe (12.55, 0) and the
// heel (0, 0). Dry: slides at mu, rocks at (12.55 - x_G) / y_G downstream and x_G / y_G upstream.
#include <cmath>
#include <filesystem>

#include <gtest/gtest.h>

#include "engine/water/block_statics.hpp"
#include "mpi_driver/config/scene_json.hpp"
#include "mpi_driver/io/statics_json.hpp"

namespace blockfrag {
namespace {

constexpr double kTypeAG = 9.81, kTypeARho = 1000.0, kTypeAMass = 411204.0, kTypeAMu = 1.05;
constexpr double kTypeABase = 12.55, kTypeACrest = 16.7;

Scene type_a(const char* file) {
  return read_scene_file(std::filesystem::path(BLOCKFRAG_SOURCE_DIR) / "configs" / file);
}

struct TypeAHand {
  double area = 167.0 + 4.335;
  double x_g = (167.0 * 5.0 + 4.335 * 10.85) / area;
  double y_g = (167.0 * 8.35 + 4.335 * 3.4 / 3) / area;
  double w = kTypeAMass * kTypeAG;
};

TEST(TypeAStatics, DryBlockSlidesAtMuAndRocksAtItsTipThresholds) {
  const TypeAHand hand;
  const BlockStatics statics = block_statics(type_a("dam_block_type_a.json"));
  EXPECT_NEAR(statics.weight, hand.w, 1e-9);
  EXPECT_NEAR(statics.weight / 1e6, 4.03, 0.005);
  EXPECT_NEAR(statics.yield.slide_downstream, kTypeAMu, 1e-14);
  EXPECT_NEAR(statics.yield.slide_upstream, kTypeAMu, 1e-14);
  EXPECT_NEAR(statics.yield.rock_downstream, (kTypeABase - hand.x_g) / hand.y_g, 1e-12);
  EXPECT_NEAR(statics.yield.rock_upstream, hand.x_g / hand.y_g, 1e-12);
}

// The water at the crest (d = 16.7 m: the 1.37 MN/m, 1.03 MN/m, 398 t/m and the sliding
// resistance falling from 1.05 g to about 0.2 g) and at 5 m freeboard (d = 11.7 m).
TEST(TypeAStatics, WetBlockMatchesTheHandComputations) {
  const TypeAHand hand;
  for (const double freeboard : {0.0, 5.0}) {
    Scene scene = type_a("dam_block_type_a_reservoir.json");
    scene.reservoir->level = kTypeACrest - freeboard;
    const double d = kTypeACrest - freeboard, b = kTypeABase;
    const double push = 0.5 * kTypeARho * kTypeAG * d * d;
    const double uplift = 0.5 * kTypeARho * kTypeAG * d * b;
    const double added = 7.0 / 12.0 * kTypeARho * 10.0 * std::pow(d, 1.5);
    const double s_base = 7.0 / 30.0 * kTypeARho * 10.0 * std::pow(d, 2.5);
    const BlockStatics statics = block_statics(scene);
    EXPECT_NEAR(statics.hydrostatic_x, push, 1e-12 * push) << freeboard;
    EXPECT_NEAR(statics.uplift_y, uplift, 1e-12 * uplift) << freeboard;
    EXPECT_NEAR(statics.added_mass, added, 1e-12 * added) << freeboard;
    const double inertia = (kTypeAMass + added) * kTypeAG;
    const double tipping = (kTypeAMass * hand.y_g + s_base) * kTypeAG;
    EXPECT_NEAR(statics.yield.slide_downstream, (kTypeAMu * (hand.w - uplift) - push) / inertia,
                1e-12);
    EXPECT_NEAR(statics.yield.slide_upstream, (kTypeAMu * (hand.w - uplift) + push) / inertia,
                1e-12);
    EXPECT_NEAR(statics.yield.rock_downstream,
                (hand.w * (b - hand.x_g) - push * d / 3 - uplift * 2 * b / 3) / tipping, 1e-12);
    EXPECT_NEAR(statics.yield.rock_upstream,
                (hand.w * hand.x_g + push * d / 3 - uplift * b / 3) / tipping, 1e-12);
    const double k = 0.1;
    const SafetyFactors f = pseudo_static_safety_factors(scene, k);
    EXPECT_NEAR(f.sliding, kTypeAMu * (hand.w - uplift) / (push + k * hand.w + k * kTypeAG * added),
                1e-12);
    EXPECT_NEAR(
        f.overturning,
        hand.w * (b - hand.x_g) /
            (push * d / 3 + uplift * 2 * b / 3 + k * hand.w * hand.y_g + k * kTypeAG * s_base),
        1e-12);
  }
  const BlockStatics crest = block_statics(type_a("dam_block_type_a_reservoir.json"));
  EXPECT_NEAR(crest.hydrostatic_x / 1e6, 1.37, 0.005);
  EXPECT_NEAR(crest.uplift_y / 1e6, 1.03, 0.005);
  EXPECT_NEAR(crest.added_mass / 1e3, 398.0, 0.5);
  EXPECT_NEAR(crest.yield.slide_downstream, 0.2, 0.03);
}

// The command's JSON: every key, the infinite factors of a dry block at rest as null.
TEST(TypeAStatics, JsonHasEveryKey) {
  const Scene dry = type_a("dam_block_type_a.json");
  const auto statics =
      statics_to_json(block_statics(dry), 0.0, pseudo_static_safety_factors(dry, 0.0));
  for (const char* key : {"weight_N", "hydrostatic_force_N", "uplift_force_N",
                          "uplift_horizontal_force_N", "added_mass_kg", "yield_acceleration_g",
                          "coefficient", "sliding_safety_factor", "overturning_safety_factor"}) {
    EXPECT_TRUE(statics.contains(key)) << key;
  }
  EXPECT_TRUE(statics["sliding_safety_factor"].is_null());
  EXPECT_EQ(statics["hydrostatic_force_N"], (nlohmann::json{0.0, 0.0}));
  EXPECT_EQ(statics["yield_acceleration_g"].size(), 4u);
  EXPECT_FALSE(statics_to_json(block_statics(dry), std::nullopt, std::nullopt)
                   .contains("sliding_safety_factor"));
}

}  // namespace
}  // namespace blockfrag
