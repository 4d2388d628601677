// A contact's accelerations (engine/contact/planar_contact.hpp) are written out without Eigen for
// the seat's forces, which ask for them at every right-hand side and guard: they are the rows of
// engine/contact/contact_lcp.hpp's contact_row times q'' as Eigen multiplies them, plus the
// velocity-product terms, to the bit, over random contacts of both kinds.
#include <cmath>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "engine/contact/contact_lcp.hpp"
#include "engine/contact/planar_contact.hpp"
#include "tests/support/fixed_uniforms.hpp"
#include "tests/support/same_bits.hpp"

namespace blockfrag {
namespace {

using testing::same_bits;

TEST(ContactAcceleration, IsTheContactRowsTimesTheAccelerationsAsEigenGivesThem) {
  testing::FixedUniforms u(4603);
  for (int n = 0; n < 20000; ++n) {
    const double turn = u(-3.2, 3.2);
    const PlanarContact c{{u(-10, 10), u(-10, 10)},
                          {std::cos(turn), std::sin(turn)},
                          n % 2 == 0 ? ContactKind::block_vertex : ContactKind::seat_point};
    const RigidVelocity v{u(-3, 3), u(-3, 3), u(-2, 2)};
    const BodyAcceleration a{u(-20, 20), u(-20, 20), u(-5, 5)};
    const Eigen::Vector3d q_dd(a.x_dd, a.y_dd, a.theta_dd);
    const Vec2 t = contact_tangent(c);
    const double w2 = v.omega * v.omega;
    double normal_terms = -w2 * (c.normal.x * c.r.x + c.normal.y * c.r.y);
    if (c.kind == ContactKind::seat_point) {
      normal_terms -= 2.0 * v.omega * contact_velocity(c, v).tangent;
    }
    const double tangent = contact_row(c, t).dot(q_dd) + -w2 * (t.x * c.r.x + t.y * c.r.y);
    const double normal = contact_row(c, c.normal).dot(q_dd) + normal_terms;
    const ContactAcceleration got = contact_acceleration(c, v, a);
    ASSERT_TRUE(same_bits(got.tangent, tangent)) << n;
    ASSERT_TRUE(same_bits(got.normal, normal)) << n;
  }
}

}  // namespace
}  // namespace blockfrag
