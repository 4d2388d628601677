// A block on one contact of its seat under the reservoir: the load pivot_turning finds at a state
// is the one the system's solve there takes next (SeatSystem keeps it), so the forces solved
// after a turning at the same state, at another state, or without one are the same to the bit, and
// so is the turning itself; in flight the forces are the general solve's without contacts.

#include <gtest/gtest.h>

#include "engine/scene/block_geometry.hpp"
#include "engine/scene/scene_validation.hpp"
#include "engine/scene/seat.hpp"
#include "engine/seat/seat_system.hpp"
#include "engine/water/block_outline.hpp"
#include "engine/water/reservoir_load.hpp"
#include "tests/support/fixed_uniforms.hpp"
#include "tests/support/same_bits.hpp"
#include "tests/support/wet_dam_blocks.hpp"

namespace blockfrag {
namespace {

using testing::same_bits;

using testing::FixedUniforms;

void expect_same_forces(const FixedStateForces& a, const FixedStateForces& b) {
  EXPECT_TRUE(same_bits(a.acceleration.x_dd, b.acceleration.x_dd));
  EXPECT_TRUE(same_bits(a.acceleration.y_dd, b.acceleration.y_dd));
  EXPECT_TRUE(same_bits(a.acceleration.theta_dd, b.acceleration.theta_dd));
  EXPECT_TRUE(same_bits(a.normal[0], b.normal[0]));
  EXPECT_TRUE(same_bits(a.tangent[0], b.tangent[0]));
  EXPECT_TRUE(same_bits(a.total.x, b.total.x));
  EXPECT_TRUE(same_bits(a.total.y, b.total.y));
}

struct WetTypeB {
  Scene scene = [] {
    Scene s = testing::wet_type_b_step(0.8, 0.3, UpliftRule::unchanged);
    validate_scene(s);
    return s;
  }();
  ReservoirLoad water{scene};
  SeatContacts contacts{scene_block_vertices(scene), scene.seat->points};
  BlockGeometry geometry{*scene.polygon};
  MotionPiece ground{{MotionPiece::Shape::cosine, 0.4, 3.0}, 0.0, 1e3};
  MotionPiece still{MotionPiece::Formula{}, 0.0, 1e3};
  SeatSystemContext context{
      &contacts, &geometry, &ground, &still, scene.g, 0.8, 0.5 * geometry.size(), &water};
  // Rocking on its toe (vertex 2 at the seat's end), sticking there.
  SeatSystem on_toe() const {
    return SeatSystem(context, {{{ContactKind::block_vertex, 2, 1}, ContactState::stick}}, {}, {});
  }
};

TEST(SeatLiftedLoad, ForcesAndTurningAreTheSameWhateverWasFoundBefore) {
  const WetTypeB wet;
  const BlockState rest = BlockOutline(wet.scene).rest_state();
  FixedUniforms u(5);
  SeatSystem reused = wet.on_toe();
  for (int i = 0; i < 200; ++i) {
    BlockState s = rest, other = rest;
    s.theta = u(-0.2, 0.0);
    s.omega = u(-0.5, 0.5);
    s.vx = u(-0.5, 0.5);
    other.theta = u(-0.2, 0.0);
    const double t = u(0.0, 2.0);
    const Vec2 arm{u(-8.0, 8.0), u(-12.0, 0.0)};
    SeatSystem fresh = wet.on_toe();
    const FixedStateForces alone = fresh.solve(t, s);
    const double turning_alone = *wet.on_toe().pivot_turning(t, s, arm);
    // A turning at the state, then the forces there; a turning elsewhere, then the forces here.
    const double turning = *reused.pivot_turning(t, s, arm);
    EXPECT_TRUE(same_bits(turning, turning_alone)) << i;
    expect_same_forces(reused.solve(t, s), alone);
    reused.pivot_turning(t, other, arm);
    expect_same_forces(wet.on_toe().solve(t, s), alone);
    SeatSystem after_other = wet.on_toe();
    after_other.pivot_turning(t, other, arm);
    expect_same_forces(after_other.solve(t, s), alone);
  }
}

// In flight (no contact) the system's forces are the general solve's without contacts under the
// lifted block's load, to the bit.
TEST(SeatLiftedLoad, AFlyingBlocksForcesAreTheGeneralSolvesWithoutContacts) {
  const WetTypeB wet;
  const BlockState rest = BlockOutline(wet.scene).rest_state();
  FixedUniforms u(7);
  SeatSystem flying(wet.context, {}, {}, {});
  MotionPiece ground{{MotionPiece::Shape::cosine, 0.4, 3.0}, 0.0, 1e3};  // wet.ground's
  for (int i = 0; i < 200; ++i) {
    BlockState s = rest;
    s.y += u(0.0, 0.5);
    s.theta = u(-0.2, 0.2);
    s.vx = u(-0.5, 0.5);
    s.vy = u(-0.5, 0.5);
    s.omega = u(-0.5, 0.5);
    const double t = u(0.0, 2.0);
    const BodyLoad load = body_load(wet.geometry.inertia_per_mass(), ground.lambda(t), 0.0,
                                    wet.scene.g, &wet.water, s, Footing::lifted);
    expect_same_forces(flying.solve(t, s), fixed_state_forces({}, {}, s, load, 0.8));
  }
}

}  // namespace
}  // namespace blockfrag
