// A series of contact problems of one shape solved with their decompositions kept
// (LcpDecompositions: the rest range's search over the ground's acceleration) gives the solutions
// of each problem solved alone, to the bit: kept, a choice's column subsets that surely fail are
// screened by their solve matrices instead of solved, and those that pass are solved as alone.
// Three contacts hold the paper's type B block on its seat (heel, fold, toe on the incline): a
// statically indeterminate set whose sticking choice is solved on column subsets.
#include <cmath>
#include <cstddef>
#include <vector>

#include <gtest/gtest.h>

#include "engine/contact/contact_lcp.hpp"
#include "engine/contact/planar_contact.hpp"
#include "engine/scene/polygon_properties.hpp"
#include "engine/tolerances.hpp"
#include "tests/support/fixed_uniforms.hpp"
#include "tests/support/type_b_block.hpp"

namespace blockfrag {
namespace {

PlanarForcesInput resting_type_b(double lambda, double mu, double inertia_scale) {
  const auto properties = polygon_properties(testing::kTypeB);
  const Vec2 c{properties.centroid[0], properties.centroid[1]};
  const double g = 9.81, rise = testing::kToeY, run = testing::kToeX - testing::kFoldX;
  const double slope = std::hypot(rise, run);
  const Vec2 flat{0.0, 1.0}, incline{-rise / slope, run / slope};
  const std::vector<PlanarContact> contacts = {
      {{0.0 - c.x, 0.0 - c.y}, flat},
      {{testing::kFoldX - c.x, 0.0 - c.y}, flat},
      {{testing::kToeX - c.x, testing::kToeY - c.y}, incline}};
  PlanarForcesInput in{
      contacts, {0.0, 0.0, 0.0}, BodyInertia(inertia_scale * 40.0), {lambda * g, -g}, mu, 1e-9, g,
      12.0};
  in.tolerance = kRestTolerance;
  return in;
}

void expect_same(const PlanarForces& kept, const PlanarForces& alone, int n) {
  EXPECT_EQ(kept.states, alone.states) << n;
  EXPECT_EQ(kept.normal, alone.normal) << n;
  EXPECT_EQ(kept.tangent, alone.tangent) << n;
  EXPECT_EQ(kept.acceleration.x_dd, alone.acceleration.x_dd) << n;
  EXPECT_EQ(kept.acceleration.y_dd, alone.acceleration.y_dd) << n;
  EXPECT_EQ(kept.acceleration.theta_dd, alone.acceleration.theta_dd) << n;
  EXPECT_EQ(kept.determinacy, alone.determinacy) << n;
  EXPECT_EQ(kept.consistent_choices, alone.consistent_choices) << n;
}

TEST(ContactLcpKept, ASeriesOfOneShapeGivesEachProblemsOwnSolutionToTheBit) {
  testing::FixedUniforms u(57);
  int all_stick = 0, moving = 0;
  for (int series = 0; series < 12; ++series) {
    const double mu = u(0.3, 1.2), inertia = u(0.5, 2.0);
    const LcpSearch search =
        series % 2 == 0 ? LcpSearch::first_consistent : LcpSearch::every_choice;
    LcpDecompositions kept;
    for (int n = 0; n < 120; ++n) {
      const double lambda = n < 60 ? u(-2.0, 2.0) : u(-0.01, 0.01) * mu;
      const PlanarForcesInput in = resting_type_b(lambda, mu, inertia);
      const PlanarForces with_kept = resolve_contact_forces(in, search, &kept);
      expect_same(with_kept, resolve_contact_forces(in, search), n);
      bool sticks = true;
      for (const ContactState s : with_kept.states) sticks = sticks && s == ContactState::stick;
      (sticks ? all_stick : moving) += 1;
    }
  }
  EXPECT_GT(all_stick, 100);
  EXPECT_GT(moving, 100);
}

}  // namespace
}  // namespace blockfrag
