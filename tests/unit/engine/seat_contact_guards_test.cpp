// A block's seat system takes a block vertex's contact from that vertex alone, and its guards from
// the world vertices the other guards turn, not from SeatContacts::pose: the forces it solves
// (those the guards solve are kept for the next asks at that time and state) and the guards made
// of them and of the contacts' velocities are those of the contacts pose() gives, to the bit, over
// random states of the paper's type B block with one or two contacts, sticking or slipping.
#include <cmath>
#include <cstddef>
#include <vector>

#include <gtest/gtest.h>

#include "engine/seat/seat_system.hpp"
#include "engine/seat/seated_load.hpp"
#include "tests/support/fixed_uniforms.hpp"
#include "tests/support/same_bits.hpp"
#include "tests/support/type_b_seat_system.hpp"

namespace blockfrag {
namespace {

using testing::same_bits;

void expect_same_kept_forces(const FixedStateForces& kept, const FixedStateForces& posed,
                             std::size_t count, int n) {
  EXPECT_TRUE(same_bits(kept.acceleration.x_dd, posed.acceleration.x_dd)) << n;
  EXPECT_TRUE(same_bits(kept.acceleration.y_dd, posed.acceleration.y_dd)) << n;
  EXPECT_TRUE(same_bits(kept.acceleration.theta_dd, posed.acceleration.theta_dd)) << n;
  EXPECT_TRUE(same_bits(kept.total.x, posed.total.x)) << n;
  EXPECT_TRUE(same_bits(kept.total.y, posed.total.y)) << n;
  for (std::size_t i = 0; i < count; ++i) {
    EXPECT_TRUE(same_bits(kept.normal[i], posed.normal[i])) << n << " " << i;
    EXPECT_TRUE(same_bits(kept.tangent[i], posed.tangent[i])) << n << " " << i;
  }
}

// The forces of the active contacts at s as pose() gives them, solved as the system solves them
// without vertical motion.
FixedStateForces posed_forces(const SeatContacts& contacts,
                              const std::vector<ActiveContact>& active, const BlockState& s,
                              double k2, double lambda, double g, double mu) {
  std::vector<PlanarContact> posed;
  std::vector<ContactState> states;
  for (const ActiveContact& a : active) {
    posed.push_back(contacts.pose(a.pair, s).contact);
    states.push_back(a.state);
  }
  if (active.size() >= 2) {
    const BodyLoad load = seated_load({k2, lambda, 0.0, g, mu, nullptr}, s, posed, states);
    return fixed_state_forces(posed, states, s, load, mu);
  }
  const BodyLoad load = body_load(k2, lambda, 0.0, g, nullptr, s, Footing::lifted);
  const auto one = one_contact_forces(posed[0], states[0], s, load, mu);
  return one ? *one : fixed_state_forces(posed, states, s, load, mu);
}

TEST(SeatContactGuards, AreThoseOfTheContactsPoseGivesToTheBit) {
  const SeatContacts contacts{testing::kTypeB, testing::kTypeBSeat};
  const BlockGeometry geometry{PolygonBlock{testing::kTypeB, 1.0}};
  MotionPiece ground{{MotionPiece::Shape::cosine, 0.4, 1.7}, 0.0, 1e3};
  MotionPiece still{MotionPiece::Formula{}, 0.0, 1e3};
  const double g = 9.81, mu = 0.7;
  const SeatSystemContext context{
      &contacts, &geometry, &ground, &still, g, mu, 0.5 * geometry.size()};
  const std::vector<std::vector<ActiveContact>> sets = testing::type_b_contact_sets();
  const double velocity_scale = std::sqrt(g * geometry.size());
  testing::FixedUniforms u(4601);
  int compared = 0;
  for (int n = 0; n < 1200; ++n) {
    const std::vector<ActiveContact>& active = sets[static_cast<std::size_t>(n) % sets.size()];
    SeatSystem system(context, active, {}, {});
    const BlockState s{u(4.0, 8.0), u(9.5, 11.5), u(-0.3, 0.3), u(-1, 1), u(-1, 1), u(-1, 1)};
    const double t = u(0.0, 5.0);
    const auto guards = system.guards(t, s);
    const FixedStateForces f =
        posed_forces(contacts, active, s, geometry.inertia_per_mass(), ground.lambda(t), g, mu);
    expect_same_kept_forces(system.solve(t, s), f, active.size(), n);
    // A system that has solved nothing yet.
    expect_same_kept_forces(SeatSystem(context, active, {}, {}).solve(t, s), f, active.size(), n);
    for (std::size_t i = 0; i < active.size(); ++i) {
      const std::size_t base = 2 + kSeatContactGuards * i;
      EXPECT_TRUE(same_bits(guards[base], f.normal[i] / g)) << n << " " << i;
      const int slip = slip_sign(active[i].state);
      const PlanarContact c = contacts.pose(active[i].pair, s).contact;
      const double second =
          slip == 0 ? (mu * f.normal[i] - std::abs(f.tangent[i])) / g
                    : slip * contact_velocity(c, {s.vx, s.vy, s.omega}).tangent / velocity_scale;
      EXPECT_TRUE(same_bits(guards[base + 1], second)) << n << " " << i;
      ++compared;
    }
  }
  EXPECT_EQ(compared, 1800);
}

}  // namespace
}  // namespace blockfrag
