// level_rest_range against the contact problem it stands in for: just inside each end of its range
// the first consistent choice of the rest search (seated_load, kRestTolerance, as
// SeatSimulation::rest_holds asks it) keeps a dry block standing on a level line still, and just
// outside it does not, for random rectangles and trapezoids whose friction is either side of their
// tip thresholds. For a rectangle the range is the flat ground's: min(mu, a/b) either way. Where a
// contact is not a block vertex pushed straight up, or the centre of mass is not between the
// outermost contacts, it gives none (the search decides).
#include "engine/seat/level_rest_range.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include <gtest/gtest.h>

#include "engine/contact/planar_contact.hpp"
#include "engine/scene/polygon_properties.hpp"
#include "engine/seat/seated_load.hpp"
#include "engine/tolerances.hpp"
#include "tests/support/fixed_uniforms.hpp"
#include "tests/support/random_trials.hpp"

namespace blockfrag {
namespace {

constexpr double kG = 9.81;

struct LevelBlock {
  std::vector<PlanarContact> base;  // the base's two corners, from the centre of mass
  double inertia_per_mass, size;
};

// A trapezoid standing on its base [0, width] at y = 0, its top [left, right] at y = height.
LevelBlock trapezoid(double width, double height, double left, double right) {
  const std::vector<Vertex> vertices = {{0.0, 0.0}, {width, 0.0}, {right, height}, {left, height}};
  const PolygonProperties p = polygon_properties(vertices);
  double size = 0.0;
  for (const Vertex& v : vertices) {
    size = std::max(size, std::hypot(v[0] - p.centroid[0], v[1] - p.centroid[1]));
  }
  const auto corner = [&](double x) {
    return PlanarContact{{x - p.centroid[0], -p.centroid[1]}, {0.0, 1.0}};
  };
  return {{corner(0.0), corner(width)}, p.inertia_per_mass, size};
}

// Whether the rest search's first consistent choice keeps the block still under lambda.
bool stays_still(const LevelBlock& block, double lambda, double mu) {
  const std::vector<ContactState> sticking(block.base.size(), ContactState::stick);
  const BodyLoad load = seated_load({block.inertia_per_mass, lambda, 0.0, kG, mu, nullptr},
                                    BlockState{}, block.base, sticking);
  PlanarForcesInput in{block.base, {0.0, 0.0, 0.0}, load.inertia, load.force, mu, 1e-6,
                       kG,         block.size};
  in.tolerance = kRestTolerance;
  in.applied_moment = load.moment;
  const double tolerance = in.tolerance * kG;
  const auto at_rest = [&](const PlanarForces& f) {
    return std::abs(f.acceleration.x_dd) <= tolerance &&
           std::abs(f.acceleration.y_dd) <= tolerance &&
           block.size * std::abs(f.acceleration.theta_dd) <= tolerance;
  };
  return first_consistent_forces_are_still(in, at_rest, nullptr);
}

TEST(LevelRestRange, EachEndIsWhereTheRestSearchStopsHoldingRest) {
  testing::FixedUniforms u(2026);
  const int trials = testing::random_trials(300);
  int friction_ends = 0, tip_ends = 0;
  for (int n = 0; n < trials; ++n) {
    const double width = u(0.2, 4.0), height = u(0.3, 8.0);
    const LevelBlock block =
        trapezoid(width, height, u(-0.3, 0.3) * width, width * (1.0 + u(-0.3, 0.3)));
    const double mu = u(0.1, 1.5);
    const std::optional<RestRange> range = level_rest_range(block.base, mu);
    ASSERT_TRUE(range.has_value()) << n;
    // The search's ends lie within its tolerance (about 1.4e-13) of the closed form's.
    constexpr double kStep = 1e-11;
    for (const double end : {range->low, range->high}) {
      const double outward = end > 0.0 ? 1.0 : -1.0;
      EXPECT_TRUE(stays_still(block, end - outward * kStep, mu)) << n << " end " << end;
      EXPECT_FALSE(stays_still(block, end + outward * kStep, mu)) << n << " end " << end;
      (std::abs(end) == mu ? friction_ends : tip_ends) += 1;
    }
  }
  EXPECT_GT(friction_ends, trials / 4);
  EXPECT_GT(tip_ends, trials / 4);
}

TEST(LevelRestRange, ARectangleRestsAsOnTheFlatGround) {
  testing::FixedUniforms u(7);
  for (int n = 0; n < 100; ++n) {
    const double a = u(0.1, 2.0), b = u(0.2, 4.0), mu = u(0.1, 1.5);
    const std::vector<PlanarContact> base = {{{-a, -b}, {0.0, 1.0}}, {{a, -b}, {0.0, 1.0}}};
    const std::optional<RestRange> range = level_rest_range(base, mu);
    ASSERT_TRUE(range.has_value());
    EXPECT_EQ(range->high, std::min(mu, a / b)) << n;
    EXPECT_EQ(range->low, -std::min(mu, a / b)) << n;
  }
}

TEST(LevelRestRange, LeavesEveryOtherStandToTheSearch) {
  const PlanarContact left{{-0.5, -1.0}, {0.0, 1.0}}, right{{0.5, -1.0}, {0.0, 1.0}};
  const double mu = 0.6;
  ASSERT_TRUE(level_rest_range(std::vector{left, right}, mu).has_value());
  // One contact.
  EXPECT_FALSE(level_rest_range(std::vector{left}, mu).has_value());
  // A contact on an incline.
  const double c = std::cos(0.1), s = std::sin(0.1);
  EXPECT_FALSE(level_rest_range(std::vector{left, PlanarContact{right.r, {-s, c}}}, mu));
  // A seat point on a block edge.
  EXPECT_FALSE(level_rest_range(
      std::vector{left, PlanarContact{right.r, right.normal, ContactKind::seat_point}}, mu));
  // The centre of mass beyond the outermost contacts.
  EXPECT_FALSE(level_rest_range(
      std::vector{PlanarContact{{0.1, -1.0}, {0.0, 1.0}}, PlanarContact{{0.5, -1.0}, {0.0, 1.0}}},
      mu));
}

TEST(LevelRestRange, PastTheSearchLimitRestHoldsForAnyLambda) {
  const std::vector<PlanarContact> squat = {{{-5000.0, -1.0}, {0.0, 1.0}},
                                            {{5000.0, -1.0}, {0.0, 1.0}}};
  const std::optional<RestRange> range = level_rest_range(squat, 2000.0);
  ASSERT_TRUE(range.has_value());
  EXPECT_EQ(range->high, std::numeric_limits<double>::infinity());
  EXPECT_EQ(range->low, -std::numeric_limits<double>::infinity());
}

}  // namespace
}  // namespace blockfrag
