// Whether the first consistent choice leaves a body at rest (first_consistent_forces_are_still)
// gives what the full search's first consistent choice (resolve_contact_forces) gives, though it
// tries the choices with a slip only before the first consistent one without. The type B block
// on its seat at heel, fold and toe (the fold on the flat and the incline both: four contacts, as
// at rest on the seat) or on some of them, under lambda either way, some of them moving: the
// first consistent choice slips in many, and a choice without a slip that comes later is
// consistent in some of those, so a search that skipped the slips would be caught.
#include <cmath>
#include <cstddef>
#include <vector>

#include <gtest/gtest.h>

#include "engine/contact/contact_lcp.hpp"
#include "engine/contact/planar_contact.hpp"
#include "engine/scene/polygon_properties.hpp"
#include "engine/tolerances.hpp"
#include "tests/support/fixed_uniforms.hpp"
#include "tests/support/random_trials.hpp"
#include "tests/support/type_b_block.hpp"

namespace blockfrag {
namespace {

std::vector<PlanarContact> type_b_contacts(unsigned used) {
  const auto properties = polygon_properties(testing::kTypeB);
  const Vec2 c{properties.centroid[0], properties.centroid[1]};
  const double rise = testing::kToeY, run = testing::kToeX - testing::kFoldX;
  const double slope = std::hypot(rise, run);
  const Vec2 flat{0.0, 1.0}, incline{-rise / slope, run / slope};
  const std::vector<PlanarContact> all = {
      {{0.0 - c.x, 0.0 - c.y}, flat},
      {{testing::kFoldX - c.x, 0.0 - c.y}, flat},
      {{testing::kFoldX - c.x, 0.0 - c.y}, incline, ContactKind::seat_point},
      {{testing::kToeX - c.x, testing::kToeY - c.y}, incline}};
  std::vector<PlanarContact> out;
  for (std::size_t i = 0; i < all.size(); ++i) {
    if (used & (1u << i)) out.push_back(all[i]);
  }
  return out;
}

bool slips(const PlanarForces& f) {
  for (const ContactState s : f.states) {
    if (slip_sign(s) != 0) return true;
  }
  return false;
}

// The block's accelerations within the problem's tolerance of none.
bool at_rest(const PlanarForces& f, const PlanarForcesInput& in) {
  const double tolerance = in.tolerance * in.g;
  return std::abs(f.acceleration.x_dd) <= tolerance && std::abs(f.acceleration.y_dd) <= tolerance &&
         in.length * std::abs(f.acceleration.theta_dd) <= tolerance;
}

TEST(ContactLcpStill, TheFirstConsistentChoiceDecidesRestAsTheFullSearchFindsIt) {
  // Every contact set keeps its series, each drawn from its own stream: a share of trials runs
  // the first problems of every series (the counts' floors scale with it).
  const int trials = testing::random_trials(60);
  int slipping = 0, still = 0, resting = 0;
  for (int series = 0; series < 40; ++series) {
    testing::FixedUniforms u(91 + static_cast<unsigned>(series));
    const unsigned used = series < 20 ? 0xFu : 1u + static_cast<unsigned>(series % 15);
    const double mu = u(0.2, 1.5), g = 9.81;
    const bool moving = series % 4 == 3;
    LcpDecompositions kept;
    for (int n = 0; n < trials; ++n) {
      const double lambda = n % 3 == 0 ? u(-0.5, 0.5) * mu : u(-3.0, 3.0);
      const RigidVelocity velocity =
          moving ? RigidVelocity{u(-1.0, 1.0), u(-0.1, 0.1), u(-0.1, 0.1)} : RigidVelocity{};
      PlanarForcesInput in{type_b_contacts(used),
                           velocity,
                           BodyInertia(40.0),
                           {lambda * g, n % 10 == 0 ? g : -g},
                           mu,
                           1e-9,
                           g,
                           12.0};
      in.tolerance = kRestTolerance;
      const PlanarForces first = resolve_contact_forces(in, LcpSearch::first_consistent);
      const bool expected_still = !slips(first),
                 expected_rest = expected_still && at_rest(first, in);
      const auto any = [](const PlanarForces&) { return true; };
      const auto rest = [&](const PlanarForces& f) { return at_rest(f, in); };
      EXPECT_EQ(first_consistent_forces_are_still(in, any, nullptr), expected_still) << series;
      EXPECT_EQ(first_consistent_forces_are_still(in, any, &kept), expected_still) << series;
      EXPECT_EQ(first_consistent_forces_are_still(in, rest, &kept), expected_rest) << series;
      EXPECT_EQ(first_consistent_forces_are_still(in, rest, nullptr), expected_rest) << series;
      slipping += !expected_still;
      still += expected_still;
      resting += expected_rest;
    }
  }
  EXPECT_GT(slipping, 200 * trials / 60);
  EXPECT_GT(still, 200 * trials / 60);
  EXPECT_GT(resting, 100 * trials / 60);
}

}  // namespace
}  // namespace blockfrag
