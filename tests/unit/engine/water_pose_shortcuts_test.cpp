// The reservoir's loads at a pose (ReservoirLoads::pose) against the plain pass over the whole
// placed outline that they shortcut, to the bit: the pose leaves out the edges that surely rise
// without placing their ends, places an edge's start only where its end is under the surface and
// an end once for the edge after it too, and a piece's added mass (AddedMassPass) takes z's
// products found once a pose, a piece cut by the surface adding its deep end's terms alone and no
// piece adding the derivatives' zero M_a parts. Random poses over every tilt, tilts on either
// side of the rising test's slack, and levels below, at and above the crest; cut and uncut pieces
// from sums that started at zero.
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "engine/scene/scene_validation.hpp"
#include "engine/sine_cosine.hpp"
#include "engine/water/hydrostatic.hpp"
#include "engine/water/reservoir_loads.hpp"
#include "engine/water/westergaard.hpp"
#include "tests/support/fixed_uniforms.hpp"
#include "tests/support/same_bits.hpp"
#include "tests/support/wet_dam_blocks.hpp"

namespace blockfrag {
namespace {

using testing::same_bits;

using testing::FixedUniforms;

void expect_same_added_mass(const AddedMass& a, const AddedMass& b) {
  EXPECT_TRUE(same_bits(a.mass, b.mass)) << a.mass << " " << b.mass;
  EXPECT_TRUE(same_bits(a.first_moment, b.first_moment)) << a.first_moment << " " << b.first_moment;
  EXPECT_TRUE(same_bits(a.second_moment, b.second_moment))
      << a.second_moment << " " << b.second_moment;
}

void expect_same_rates(const AddedMassWithRates& a, const AddedMassWithRates& b) {
  expect_same_added_mass(a.at, b.at);
  expect_same_added_mass(a.d_dy, b.d_dy);
  expect_same_added_mass(a.d_dtheta, b.d_dtheta);
}

// The pose's push and added mass as the whole outline placed and passed over gives them, every
// piece's added mass with both ends' terms.
ReservoirPose plain_pose(const Scene& scene, const ReservoirLoads& loads, const BlockState& s) {
  const BlockOutline outline(scene);
  std::vector<Vertex> world(outline.body().size());
  ReservoirPose out;
  out.turn = sine_cosine(s.theta);
  out.centre = outline.centre(s);
  outline.place(s, out.turn, world);
  const Reservoir& water = *scene.reservoir;
  const double scale = westergaard_scale(water.density, water.depth);
  const double z = water.level - out.centre[1];
  for_each_wetted_piece(world, water.level, loads.crack().edges, [&](const WettedPiece& piece) {
    add_hydrostatic_piece(out.hydrostatic, piece, water.density * scene.g, out.centre);
    if (water.hydrodynamic == Hydrodynamic::westergaard) {
      add_added_mass_piece_in_full(out.added, piece, scale, z, out.centre);
    }
  });
  return out;
}

// Tilts anywhere, near the upright, and right at a rising test's slack for the block's edges.
double random_tilt(FixedUniforms& u, int i) {
  switch (i % 5) {
    case 0: return u(-3.1, 3.1);
    case 1: return u(-0.3, 0.3);
    case 2: return u(-1e-12, 1e-12);
    case 3: return u(-1e-15, 1e-15);
    default: return (i % 10 == 4 ? 1.0 : -1.0) * u(0.0, 1e-300);
  }
}

void expect_pose_is_the_plain_pass(Scene scene, double level, Hydrodynamic hydrodynamic) {
  scene.reservoir->level = level;
  scene.reservoir->hydrodynamic = hydrodynamic;
  validate_scene(scene);
  const ReservoirLoads loads(scene);
  const BlockState rest = BlockOutline(scene).rest_state();
  FixedUniforms u(41);
  for (int i = 0; i < 400; ++i) {
    SCOPED_TRACE(::testing::Message() << "pose " << i);
    BlockState s = rest;
    s.x += u(-2.0, 2.0);
    s.y += u(-1.0, 3.0);
    s.theta = i == 0 ? 0.0 : random_tilt(u, i);
    const ReservoirPose pose = loads.pose(s), plain = plain_pose(scene, loads, s);
    EXPECT_TRUE(same_bits(pose.hydrostatic.fx, plain.hydrostatic.fx));
    EXPECT_TRUE(same_bits(pose.hydrostatic.fy, plain.hydrostatic.fy));
    EXPECT_TRUE(same_bits(pose.hydrostatic.moment, plain.hydrostatic.moment));
    expect_same_rates(pose.added, plain.added);
  }
}

TEST(ReservoirPoseShortcuts, ThePoseIsThePlainPassOverTheWholeOutline) {
  const Scene b = testing::wet_type_b_step(0.8, 0.3, UpliftRule::zero_in_gap);
  const Scene a = testing::wet_type_a_step(0.8, 0.3, UpliftRule::unchanged);
  for (const Hydrodynamic hydrodynamic : {Hydrodynamic::westergaard, Hydrodynamic::none}) {
    SCOPED_TRACE(::testing::Message() << "added mass " << static_cast<int>(hydrodynamic));
    for (const double level : {21.7, 15.0, 8.366666666666667, 25.0}) {
      SCOPED_TRACE(::testing::Message() << "type B, level " << level);
      expect_pose_is_the_plain_pass(b, level, hydrodynamic);
    }
    for (const double level : {16.7, 10.0, 20.0}) {
      SCOPED_TRACE(::testing::Message() << "type A, level " << level);
      expect_pose_is_the_plain_pass(a, level, hydrodynamic);
    }
  }
}

// A piece of a descending edge from a to b, cut by the surface at a when `cut`.
WettedPiece random_piece(FixedUniforms& u, double surface, bool cut) {
  const Vertex b{u(-5.0, 5.0), surface - u(1e-3, 20.0)};
  const Vertex a{b[0] + u(-3.0, 3.0), cut ? surface : surface - u(0.0, 0.99) * (surface - b[1])};
  return {a, b, {b[0] - a[0], b[1] - a[1]}, surface - a[1], surface - b[1]};
}

TEST(ReservoirPoseShortcuts, APieceCutByTheSurfaceAddsItsFullTermsBits) {
  FixedUniforms u(43);
  const double scale = westergaard_scale(1000.0, 100.0);
  for (int i = 0; i < 2000; ++i) {
    SCOPED_TRACE(::testing::Message() << "piece " << i);
    const double surface = u(-10.0, 30.0);
    const Vertex centre{u(-5.0, 5.0), surface + u(-25.0, 10.0)};
    // Sums that start at zero, with an uncut piece or none before.
    AddedMassWithRates shortcut_sums, full;
    AddedMassPass shortcut(shortcut_sums, scale, surface - centre[1], centre);
    if (i % 2 == 1) {
      const WettedPiece before = random_piece(u, surface, false);
      shortcut.add(before);
      add_added_mass_piece_in_full(full, before, scale, surface - centre[1], centre);
    }
    const WettedPiece piece = random_piece(u, surface, i % 3 != 2);
    shortcut.add(piece);
    add_added_mass_piece_in_full(full, piece, scale, surface - centre[1], centre);
    expect_same_rates(shortcut_sums, full);
  }
}

// A random edge's end: above, below or right at the surface.
Vertex random_end(FixedUniforms& u, double surface, int i) {
  return {u(-5.0, 5.0), i % 7 == 0 ? surface : surface + u(-20.0, 3.0)};
}

TEST(ReservoirPoseShortcuts, AnEdgesCutAndWholePiecesAddTheirFullTermsBits) {
  FixedUniforms u(47);
  const double scale = westergaard_scale(1000.0, 100.0);
  for (int i = 0; i < 2000; ++i) {
    SCOPED_TRACE(::testing::Message() << "edges " << i);
    const double surface = u(-10.0, 30.0);
    const Vertex centre{u(-5.0, 5.0), surface + u(-25.0, 10.0)};
    const double z = surface - centre[1];
    AddedMassWithRates parts_sums, full;
    AddedMassPass parts(parts_sums, scale, z, centre);
    // Two edges in a row, as an outline's: a to b, then b to c.
    const Vertex a = random_end(u, surface, i), b = random_end(u, surface, i / 2),
                 c = random_end(u, surface, i / 3);
    for (const auto& [from, to] : {std::pair{a, b}, std::pair{b, c}}) {
      visit_wetted_edge_parts(
          from, to, surface, [&](const WettedPiece& piece) { parts.add_cut(piece); },
          [&](const WettedPiece& piece) { parts.add_whole(piece); });
      visit_wetted_edge(from, to, surface, [&](const WettedPiece& piece) {
        add_added_mass_piece_in_full(full, piece, scale, z, centre);
      });
    }
    expect_same_rates(parts_sums, full);
  }
}

}  // namespace
}  // namespace blockfrag
