// A vertex slipping along a seat segment's line (SlipChart): its right-hand side turns the vertex's
// arm once, for the block's state and for the rates, and is the general one to the bit: the state
// full() gives, its forces as a system that has solved nothing finds them, and the slipping
// vertex's acceleration along the line with the arm turned by sine_cosine, over random states of
// the type B block slipping on either seat segment, dry and under the reservoir.
#include <cstddef>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "engine/scene/block_geometry.hpp"
#include "engine/scene/scene_validation.hpp"
#include "engine/scene/seat.hpp"
#include "engine/seat/seat_ode.hpp"
#include "engine/seat/seat_system.hpp"
#include "engine/sine_cosine.hpp"
#include "engine/water/reservoir_load.hpp"
#include "tests/support/fixed_uniforms.hpp"
#include "tests/support/same_bits.hpp"
#include "tests/support/wet_dam_blocks.hpp"

namespace blockfrag {
namespace {

using testing::same_bits;

// The type B block on its seat, dry or under the reservoir at its crest.
struct SlippingTypeB {
  Scene scene = [] {
    Scene s = testing::wet_type_b_step(0.6, 0.2, UpliftRule::unchanged);
    validate_scene(s);
    return s;
  }();
  ReservoirLoad water{scene};
  SeatContacts contacts{scene_block_vertices(scene), scene.seat->points};
  BlockGeometry geometry{*scene.polygon};
  MotionPiece ground{{MotionPiece::Shape::cosine, 0.3, 2.1}, 0.0, 1e3};
  MotionPiece still{MotionPiece::Formula{}, 0.0, 1e3};

  SeatSystemContext context(bool wet) {
    return {&contacts,
            &geometry,
            &ground,
            &still,
            scene.g,
            0.6,
            0.5 * geometry.size(),
            wet ? &water : nullptr};
  }
};

// The rates of the slipping vertex's chart at (t, q), found the general way.
OdeState<4> general_rates(const SeatSystemContext& context,
                          const std::vector<ActiveContact>& active, const SlipChart& chart,
                          double t, const OdeState<4>& q) {
  const BlockState s = chart.full(t, q);
  const BodyAcceleration a = SeatSystem(context, active, {}, {}).solve(t, s).acceleration;
  const SineCosine turn = sine_cosine(s.theta);
  const Vec2 r = rotate(chart.body, turn.cos, turn.sin);
  const double w2 = q[1] * q[1];
  const Vec2 vertex{a.x_dd - a.theta_dd * r.y - w2 * r.x, a.y_dd + a.theta_dd * r.x - w2 * r.y};
  return {q[1], a.theta_dd, q[3],
          vertex.x * chart.line.direction.x + vertex.y * chart.line.direction.y};
}

TEST(SeatSlipRates, AreTheGeneralRatesToTheBit) {
  SlippingTypeB block;
  testing::FixedUniforms u(97);
  int compared = 0;
  for (const bool wet : {false, true}) {
    const SeatSystemContext context = block.context(wet);
    // The heel slipping back along the base's segment, the toe down the incline.
    for (const auto& [vertex, segment, state] : {std::tuple{0, 0, ContactState::slip_negative},
                                                 std::tuple{2, 1, ContactState::slip_positive}}) {
      const std::vector<ActiveContact> active = {
          {{ContactKind::block_vertex, vertex, segment}, state}};
      const SeatLine line = block.contacts.segment_line(segment);
      const SlipChart chart{{0.0, 0.0}, line, block.contacts.body_vertex(vertex)};
      SeatSystem system(context, active, {}, {});
      const SeatOde<SlipChart> ode(system, chart);
      for (int n = 0; n < 100; ++n) {
        const OdeState<4> q{u(-0.2, 0.2), u(-1.0, 1.0), u(-2.0, 8.0), u(-1.0, 1.0)};
        const double t = u(0.0, 3.0);
        OdeState<4> dq;
        ode(t, q, dq);
        const OdeState<4> expected = general_rates(context, active, chart, t, q);
        for (std::size_t i = 0; i < 4; ++i) {
          EXPECT_TRUE(same_bits(dq[i], expected[i]))
              << wet << " " << vertex << " " << n << " " << i;
        }
        ++compared;
      }
    }
  }
  EXPECT_EQ(compared, 400);
}

}  // namespace
}  // namespace blockfrag
