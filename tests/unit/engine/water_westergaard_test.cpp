// Westergaard's added mass on the wetted upstream face (engine/water/westergaard.hpp) against
// the closed forms of his pressure m_w(y) = (7/8) rho sqrt(H y) per unit area (Westergaard 1933,
// Trans. ASCE 98, for a rigid vertical face in incompressible water of depth H) integrated over a
// vertical face wetted to depth d, about the face's foot (z = d - y):
//   M_a = integral_0^d (7/8) rho sqrt(H y) dy = (7/12) rho sqrt(H) d^(3/2), at 0.4 d above the
//   foot, S_a = integral m_w z dy = (7/30) rho sqrt(H) d^(5/2), I_a = integral m_w z^2 dy = (2/15)
//   rho sqrt(H) d^(7/2);
// a sloping face counts by its projected height; a reference elsewhere against a quadrature; no
// water below the block.
#include <array>
#include <cmath>
#include <cstddef>

#include <gtest/gtest.h>

#include "engine/errors.hpp"
#include "engine/water/westergaard.hpp"
#include "tests/support/water_outlines.hpp"

namespace blockfrag {
namespace {

using testing::kBaseEdge;
using testing::kWaterDensity;
using testing::rectangle_outline;

TEST(Westergaard, VerticalFaceMatchesTheClosedForms) {
  const double H = 100.0;
  for (const double d : {2.0, 6.0, 10.0}) {
    const AddedMass added =
        westergaard_added_mass(rectangle_outline(5.0, 10.0), d, kWaterDensity, H, kBaseEdge, 0.0);
    const double root = kWaterDensity * std::sqrt(H);
    const double mass = 7.0 / 12.0 * root * std::pow(d, 1.5);
    EXPECT_NEAR(added.mass, mass, 1e-12 * mass) << d;
    EXPECT_NEAR(added.first_moment, 7.0 / 30.0 * root * std::pow(d, 2.5), 1e-12 * mass * d) << d;
    EXPECT_NEAR(added.second_moment, 2.0 / 15.0 * root * std::pow(d, 3.5), 1e-12 * mass * d * d)
        << d;
    EXPECT_NEAR(added.first_moment / added.mass, 0.4 * d, 1e-12 * d) << d;
  }
}

// The face leaning back (foot 3 m upstream of its top) has the vertical face's projected height:
// the same added mass and moments (the documented choice for inclined faces).
TEST(Westergaard, SlopingFaceCountsByItsProjectedHeight) {
  const WorldPolygon vertical = rectangle_outline(5.0, 10.0);
  const WorldPolygon sloping{{-3.0, 0}, {5.0, 0}, {5.0, 10.0}, {0, 10.0}};
  const AddedMass a = westergaard_added_mass(vertical, 7.0, kWaterDensity, 50.0, kBaseEdge, 2.0);
  const AddedMass b = westergaard_added_mass(sloping, 7.0, kWaterDensity, 50.0, kBaseEdge, 2.0);
  EXPECT_NEAR(b.mass, a.mass, 1e-12 * a.mass);
  EXPECT_NEAR(b.first_moment, a.first_moment, 1e-9 * a.mass);
  EXPECT_NEAR(b.second_moment, a.second_moment, 1e-9 * a.mass);
}

// About a height inside the wetted face (the block's centre of mass) z changes sign over it:
// against the midpoint rule over the face's projected height, z = y - y_ref.
TEST(Westergaard, MomentsAboutTheCentreMatchAQuadrature) {
  const double H = 40.0, surface = 9.0, y_ref = 4.0;
  const AddedMass added = westergaard_added_mass(rectangle_outline(5.0, 12.0), surface,
                                                 kWaterDensity, H, kBaseEdge, y_ref);
  const int n = 1'000'000;
  AddedMass sum;
  for (int k = 0; k < n; ++k) {
    const double y = (k + 0.5) * surface / n, z = y - y_ref;
    const double m = 7.0 / 8.0 * kWaterDensity * std::sqrt(H * (surface - y)) * surface / n;
    sum.mass += m;
    sum.first_moment += m * z;
    sum.second_moment += m * z * z;
  }
  EXPECT_NEAR(added.mass, sum.mass, 1e-6 * sum.mass);
  EXPECT_NEAR(added.first_moment, sum.first_moment, 1e-6 * sum.mass * surface);
  EXPECT_NEAR(added.second_moment, sum.second_moment, 1e-6 * sum.mass * surface * surface);
  EXPECT_LT(added.first_moment, 0.0);  // the surface is 5 m above the reference, the foot 4 m below
}

TEST(Westergaard, NoWaterAtOrBelowTheLowestPointIsExactlyZero) {
  for (const double surface : {0.0, -2.0}) {
    const AddedMass added = westergaard_added_mass(rectangle_outline(5.0, 10.0), surface,
                                                   kWaterDensity, 100.0, kBaseEdge, 5.0);
    EXPECT_EQ(added.mass, 0.0);
    EXPECT_EQ(added.first_moment, 0.0);
    EXPECT_EQ(added.second_moment, 0.0);
  }
  EXPECT_THROW(
      westergaard_added_mass(rectangle_outline(5.0, 10.0), 5.0, kWaterDensity, 0.0, kBaseEdge, 0.0),
      ContractViolation);
}

}  // namespace
}  // namespace blockfrag
