// A block that slides back into its seat's fold and stops there, nested on four pairs (the heel
// and the fold vertex on the first segment, the fold vertex and the next vertex on the incline): a
// statically indeterminate set, whose guards must not hand the block back and forth between two of
// its subsets while it stands still.
#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "engine/simulate.hpp"
#include "tests/support/type_b_rk4_scene.hpp"

namespace blockfrag {
namespace {

// The randomized wet scene that failed on the event budget (the type B block under its reservoir,
// 1.7 m below the crest, no uplift in the open crack, the Kobe TAK-090 record at 0.636), on the
// record's excerpt from 2.11 s, where the block still rests as it has since the start: it slides
// and rocks a little, rests, slides back downstream into the fold and stops there, at lambda
// 0.175 g.
Scene sliding_back_into_the_fold() {
  auto record = std::make_shared<Accelerogram>();
  record->acceleration_g = {
      0.397978,   0.478798,   0.536021,  0.560484,  0.517971,  0.394107,   0.198517,   -0.0234685,
      -0.224946,  -0.378056,  -0.475127, -0.533624, -0.557873, -0.533157,  -0.467403,  -0.383017,
      -0.309929,  -0.256828,  -0.199449, -0.111394, 0.0138686, 0.154878,   0.283906,   0.376208,
      0.42035,    0.425381,   0.408426,  0.387611,  0.369074,  0.348409,   0.332893,   0.33318,
      0.352717,   0.387273,   0.429382,  0.47636,   0.521672,  0.54469,    0.522561,   0.461378,
      0.388897,   0.325531,   0.270998,  0.213536,  0.144739,  0.0609964,  -0.038077,  -0.144198,
      -0.249428,  -0.342089,  -0.394102, -0.386469, -0.315787, -0.193148,  -0.0439233, 0.108276,
      0.249224,   0.373309,   0.483637,  0.57286,   0.615515,  0.575069,   0.470645,   0.360858,
      0.29466,    0.28632,    0.317238,  0.34781,   0.354427,  0.332041,   0.282057,   0.215867,
      0.149791,   0.0964161,  0.0608635, 0.0369202, 0.0135792, -0.0177827, -0.054081,  -0.0891178,
      -0.124373,  -0.16304,   -0.201858, -0.239508, -0.280014, -0.324066,  -0.368501,  -0.408758,
      -0.442894,  -0.475253,  -0.507187, -0.525581, -0.533181, -0.545356,  -0.559546,  -0.570364,
      -0.563845,  -0.50937,   -0.394505, -0.249475, -0.114312, -0.0158122, 0.0361412,  0.0416834,
      0.00296462, -0.0694068, -0.152104, -0.219094, -0.261506, -0.283292,
  };
  for (std::size_t k = 0; k < record->acceleration_g.size(); ++k) {
    record->times.push_back(static_cast<double>(k) / 100.0);
  }
  // The lift-off and the friction limit took turns every 1e-10 s up to a million events; a few
  // hundred fail it at once.
  Scene scene = testing::type_b_rk4_scene(
      0.307, 0.49, RecordedMotion{"Kobe TAK-090, 2.11 s to 3.2 s", 0.636, record}, 1.2, 600);
  scene.reservoir =
      Reservoir{18.1066, 100.0, 1000.0, Hydrodynamic::westergaard, UpliftRule::zero_in_gap, 1.0};
  return scene;
}

TEST(SeatNestedRest, BlockStoppingNestedInTheFoldRestsOnAllItsPairs) {
  const Summary s = simulate(sliding_back_into_the_fold());
  ASSERT_EQ(s.status, Status::ok) << s.status_reason;
  EXPECT_LT(s.events, 400);
  EXPECT_FALSE(s.fell);
  EXPECT_FALSE(s.overturned);
  ASSERT_GE(s.modes.size(), 2u);
  // It slid back into the fold and rests there, level, until the record's swing the other way.
  const ModeChange slide = s.modes[s.modes.size() - 2], rest = s.modes.back();
  EXPECT_EQ(slide.mode, ModeKind::slide);
  EXPECT_EQ(rest.mode, ModeKind::rest);
  EXPECT_GT(rest.time, 1.0);
  EXPECT_LT(rest.time, slide.time + 0.01);
  EXPECT_LT(std::abs(s.final_theta), 1e-12);
  EXPECT_LT(std::abs(s.final_slide), 1e-6);
}

}  // namespace
}  // namespace blockfrag
