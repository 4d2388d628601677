// Fenves & Chopra's reservoir and foundation on the dam crest filter (engine/motion/dam_crest.hpp):
//   T1' = R_r R_f T1,   zeta1' = zeta1 / (R_r R_f^3) + zeta_r + zeta_f
// (Fenves & Chopra 1987, the simplified analysis of concrete gravity dams; USACE EP 1110-2-12,
// 1995, Seismic Design Provisions for Roller Compacted Concrete Dams, appendix C), against that
// pamphlet's worked example; the defaults leave the dam's own mode to the bit; and the crest is
// the one a dry dam of the lengthened period and added damping would give.
#include <vector>

#include <gtest/gtest.h>

#include "engine/motion/dam_crest.hpp"
#include "tests/support/paper_block.hpp"

namespace blockfrag {
namespace {

using testing::kGravity;

// EP 1110-2-12's example: T1 = 0.443 s, R_r = 1.110, R_f = 1.190, zeta1 = 7 %, zeta_r = 0.0158,
// zeta_f = 0.0701 give T1' = 0.585 s and zeta1' = 12.33 %. By hand: 1.110 x 1.190 x 0.443 =
// 0.58516 s; 0.07 / (1.110 x 1.190^3) = 0.03742, + 0.0158 + 0.0701 = 0.12332.
TEST(DamInteraction, ReproducesTheWorkedExampleOfEp1110_2_12) {
  const DamMode mode = fenves_chopra_mode({0.443, 0.07}, 1.110, 0.0158, 1.190, 0.0701);
  EXPECT_NEAR(mode.period, 0.585, 0.0005);
  EXPECT_NEAR(100 * mode.damping, 12.33, 0.005);

  DamCrest dam;
  dam.stiffness = DamPeriod{0.443};
  dam.damping = 0.07;
  dam.reservoir_period_ratio = 1.110;
  dam.reservoir_damping = 0.0158;
  dam.foundation_period_ratio = 1.190;
  dam.foundation_damping = 0.0701;
  EXPECT_EQ(dam_mode(dam).period, mode.period);
  EXPECT_EQ(dam_mode(dam).damping, mode.damping);
}

// Ratios of 1 and no added damping: the dam's own period and damping, bit for bit, whether the
// period is given or estimated from the dam's size.
TEST(DamInteraction, DefaultsLeaveTheDamsOwnModeToTheBit) {
  for (const double period : {0.001, 0.1, 0.2413, 0.3, 1.0 / 3.0, 10.0}) {
    for (const double damping : {0.0, 0.02, 0.05, 0.1 + 0.2, 0.999}) {
      DamCrest dam;
      dam.stiffness = DamPeriod{period};
      dam.damping = damping;
      EXPECT_EQ(dam_mode(dam).period, period);
      EXPECT_EQ(dam_mode(dam).damping, damping);
    }
  }
  DamCrest sized;
  sized.stiffness = DamSize{87.0, 31e9};
  EXPECT_EQ(dam_mode(sized).period, fenves_chopra_period(87.0, 31e9));
}

// The filter runs the lengthened, more damped mode: its crest is, node for node, that of a dam on
// rigid rock with an empty reservoir given T1' and zeta1' directly.
TEST(DamInteraction, CrestIsTheDryDamOfTheLengthenedPeriodAndAddedDamping) {
  const GroundMotionPieces foundation(SinePulse{0.3, 0.4, 3.0});
  DamCrest wet;
  wet.stiffness = DamPeriod{0.25};
  wet.damping = 0.05;
  wet.reservoir_period_ratio = 1.3;
  wet.reservoir_damping = 0.02;
  wet.foundation_period_ratio = 1.1;
  wet.foundation_damping = 0.04;
  wet.participation = 1.4;
  DamCrest dry;
  dry.stiffness = DamPeriod{1.3 * 1.1 * 0.25};
  dry.damping = 0.05 / (1.3 * 1.1 * 1.1 * 1.1) + 0.02 + 0.04;
  dry.participation = 1.4;
  const CrestHistory a = dam_crest_history(foundation, wet, 3.0, kGravity);
  const CrestHistory b = dam_crest_history(foundation, dry, 3.0, kGravity);
  ASSERT_EQ(a.times.size(), b.times.size());
  EXPECT_EQ(a.times, b.times);
  EXPECT_EQ(a.crest_lambda, b.crest_lambda);
  // And not the dam's own: the reservoir and foundation change the crest.
  DamCrest own = wet;
  own.reservoir_period_ratio = own.foundation_period_ratio = 1.0;
  own.reservoir_damping = own.foundation_damping = 0.0;
  EXPECT_NE(dam_crest_history(foundation, own, 3.0, kGravity).crest_lambda, a.crest_lambda);
}

}  // namespace
}  // namespace blockfrag
