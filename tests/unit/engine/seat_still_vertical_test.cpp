// Without vertical ground motion a block's seat system takes lambda_v as zero without asking the
// vertical piece's formula (SeatSystem::lambda_v): its forces and its turning about a pivot are
// those of the loads made with the formula's value, to the bit, whether the piece has no shape or
// a zero amplitude (whose zeros have either sign); with vertical motion they follow the formula.
#include <vector>

#include <gtest/gtest.h>

#include "engine/seat/seat_system.hpp"
#include "tests/support/fixed_uniforms.hpp"
#include "tests/support/same_bits.hpp"
#include "tests/support/type_b_block.hpp"

namespace blockfrag {
namespace {

using testing::same_bits;

struct VerticalCase {
  MotionPiece vertical;
  bool still;
};

TEST(SeatStillVertical, ForcesAndTurningAreThoseOfTheFormulasLoad) {
  const SeatContacts contacts{testing::kTypeB, testing::kTypeBSeat};
  const BlockGeometry geometry{PolygonBlock{testing::kTypeB, 1.0}};
  MotionPiece ground{{MotionPiece::Shape::cosine, 0.5, 2.3}, 0.0, 1e3};
  // A cosine of zero amplitude is -0 where the cosine is negative.
  std::vector<VerticalCase> cases = {
      {MotionPiece{MotionPiece::Formula{}, 0.0, 1e3}, true},
      {MotionPiece{{MotionPiece::Shape::cosine, 0.0, 1.9}, 0.0, 1e3}, true},
      {MotionPiece{{MotionPiece::Shape::cosine, 0.3, 1.9}, 0.0, 1e3}, false}};
  const double g = 9.81, mu = 0.8, k2 = geometry.inertia_per_mass();
  const SeatPair toe{ContactKind::block_vertex, 2, 1};
  const std::vector<ActiveContact> on_toe = {{toe, ContactState::stick}};
  testing::FixedUniforms u(4602);
  int compared = 0;
  for (int n = 0; n < 900; ++n) {
    VerticalCase& vertical = cases[static_cast<std::size_t>(n) % cases.size()];
    EXPECT_EQ(vertical.vertical.is_zero(), vertical.still);
    const SeatSystemContext context{
        &contacts, &geometry, &ground, &vertical.vertical, g, mu, 0.5 * geometry.size()};
    const BlockState s{u(4.0, 8.0), u(9.5, 11.5), u(-0.3, 0.3), u(-1, 1), u(-1, 1), u(-1, 1)};
    const double t = u(0.0, 5.0);
    const BodyLoad load = body_load(k2, ground.formula_value(t), vertical.vertical.formula_value(t),
                                    g, nullptr, s, Footing::lifted);
    const auto expected =
        one_contact_forces(contacts.pose(toe, s).contact, ContactState::stick, s, load, mu);
    ASSERT_TRUE(expected.has_value());
    SeatSystem system(context, on_toe, {}, {});
    const FixedStateForces& f = system.solve(t, s);
    EXPECT_TRUE(same_bits(f.normal[0], expected->normal[0])) << n;
    EXPECT_TRUE(same_bits(f.tangent[0], expected->tangent[0])) << n;
    EXPECT_TRUE(same_bits(f.acceleration.theta_dd, expected->acceleration.theta_dd)) << n;
    EXPECT_TRUE(same_bits(f.total.y, expected->total.y)) << n;
    // In flight the forces are none and the acceleration is the load's.
    SeatSystem flying(context, {}, {}, {});
    EXPECT_TRUE(same_bits(flying.solve(t, s).acceleration.y_dd, load.force.y)) << n;
    // Turning about the toe: against a vertical piece that is zero at t but not throughout (a
    // line through zero there), whose formula the system asks.
    MotionPiece through_zero{{MotionPiece::Shape::linear, 0.0, 0.0, 0.0, t, 1.0}, 0.0, 1e3};
    const SeatSystemContext asked{
        &contacts, &geometry, &ground, &through_zero, g, mu, 0.5 * geometry.size()};
    const Vec2 arm = contacts.pose(toe, s).contact.r;
    const double turning = *system.pivot_turning(t, s, arm);
    const double asked_turning = *SeatSystem(asked, on_toe, {}, {}).pivot_turning(t, s, arm);
    EXPECT_EQ(same_bits(turning, asked_turning), vertical.still) << n;
    ++compared;
  }
  EXPECT_EQ(compared, 900);
}

}  // namespace
}  // namespace blockfrag
