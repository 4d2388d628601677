// The fits' backtracking line search on concave quadratics, whose maximum and whose gain along any
// step are known in closed form: the length it returns is the first halving that passes Armijo's
// test as computed here, a step along a descent direction fails, and only a Newton step whose gain
// is below what the value can resolve is taken whole unchecked.
#include "postproc/fragility/backtracking_line_search.hpp"

#include <array>
#include <cmath>
#include <optional>
#include <vector>

#include <gtest/gtest.h>

namespace blockfrag {
namespace {

using Vector2 = std::array<double, 2>;

// f(x) = b . x - x' A x / 2 with A = [[2, 1/2], [1/2, 1]] and b = (1, -1): concave, its maximum at
// A^-1 b = (6/7, -10/7), its gradient b - A x.
double quadratic(const Vector2& x) {
  const double ax0 = 2.0 * x[0] + 0.5 * x[1], ax1 = 0.5 * x[0] + 1.0 * x[1];
  return 1.0 * x[0] - 1.0 * x[1] - 0.5 * (x[0] * ax0 + x[1] * ax1);
}

Vector2 quadratic_gradient(const Vector2& x) {
  return {1.0 - (2.0 * x[0] + 0.5 * x[1]), -1.0 - (0.5 * x[0] + 1.0 * x[1])};
}

struct Search {
  std::optional<double> length;
  std::vector<double> lengths_tried;
  Vector2 last_point{};
};

// The search from x along d on the quadratic, recording every length it tried.
Search search_quadratic(const Vector2& x, const Vector2& d, bool newton, double value_scale = 0.0) {
  const Vector2 g = quadratic_gradient(x);
  Search search;
  const AscentStart start{quadratic(x), value_scale, g[0] * d[0] + g[1] * d[1], newton};
  search.length = backtracking_line_search(start, [&](double t) {
    search.lengths_tried.push_back(t);
    search.last_point = {x[0] + t * d[0], x[1] + t * d[1]};
    return quadratic(search.last_point);
  });
  return search;
}

bool passes_armijo(const Vector2& x, const Vector2& d, double t) {
  const Vector2 g = quadratic_gradient(x);
  const Vector2 moved{x[0] + t * d[0], x[1] + t * d[1]};
  return quadratic(moved) >= quadratic(x) + 1e-4 * t * (g[0] * d[0] + g[1] * d[1]);
}

TEST(BacktrackingLineSearch, TakesNewtonsWholeStepToAQuadraticsMaximum) {
  const Vector2 x{0.0, 0.0}, newton{6.0 / 7.0, -10.0 / 7.0};
  const Search search = search_quadratic(x, newton, true);
  ASSERT_TRUE(search.length.has_value());
  EXPECT_EQ(*search.length, 1.0);
  EXPECT_NEAR(search.last_point[0], 6.0 / 7.0, 1e-15);
  EXPECT_NEAR(search.last_point[1], -10.0 / 7.0, 1e-15);
}

// Four times Newton's step: at 2 it lands where it started (the quadratic is symmetric about its
// maximum), which gains nothing and must fail the test; at 1 it lands on the maximum.
TEST(BacktrackingLineSearch, HalvesAnOvershootingStepUntilArmijosTestPasses) {
  const Vector2 x{0.0, 0.0}, overshoot{4.0 * 6.0 / 7.0, -4.0 * 10.0 / 7.0};
  const Search search = search_quadratic(x, overshoot, false);
  ASSERT_TRUE(search.length.has_value());
  EXPECT_EQ(*search.length, 0.25);
  EXPECT_EQ(search.lengths_tried, (std::vector<double>{1.0, 0.5, 0.25}));
  EXPECT_FALSE(passes_armijo(x, overshoot, 0.5));
  EXPECT_TRUE(passes_armijo(x, overshoot, 0.25));
  EXPECT_NEAR(search.last_point[0], 6.0 / 7.0, 1e-15);
  EXPECT_NEAR(search.last_point[1], -10.0 / 7.0, 1e-15);
}

// Along the gradient scaled far past the maximum from an off-centre start: the length returned is
// the longest halving that passes the test, whatever the step's scale.
TEST(BacktrackingLineSearch, ReturnsTheFirstHalvingThatPassesArmijosTest) {
  const Vector2 x{3.0, 2.0};
  const Vector2 g = quadratic_gradient(x);
  for (const double scale : {1.0, 10.0, 1e3, 1e6}) {
    const Vector2 d{scale * g[0], scale * g[1]};
    const Search search = search_quadratic(x, d, false);
    ASSERT_TRUE(search.length.has_value()) << scale;
    EXPECT_TRUE(passes_armijo(x, d, *search.length)) << scale;
    if (*search.length < 1.0) {
      EXPECT_FALSE(passes_armijo(x, d, 2.0 * *search.length)) << scale;
    }
    EXPECT_EQ(search.lengths_tried.back(), *search.length) << scale;
    EXPECT_GT(quadratic(search.last_point), quadratic(x)) << scale;
  }
}

// Downhill every length loses value: all 60 halvings from 1 down to 2^-59 are tried, none passes.
// From the origin, where f is 0 and every length moves the point; elsewhere a length below the
// coordinates' rounding leaves the point and f as they were and passes the test, gaining nothing.
TEST(BacktrackingLineSearch, FailsAlongADescentDirection) {
  const Vector2 x{0.0, 0.0};
  const Vector2 g = quadratic_gradient(x);
  const Search search = search_quadratic(x, {-g[0], -g[1]}, false);
  EXPECT_FALSE(search.length.has_value());
  ASSERT_EQ(search.lengths_tried.size(), 60u);
  EXPECT_EQ(search.lengths_tried.back(), std::ldexp(1.0, -59));
}

// A gain of 1e-8 against terms of magnitude 1e6 is below what the value resolves (1e-13 of it):
// Newton's step is taken whole even though the value falls; a steepest-ascent step, or a gain
// above that, is not.
TEST(BacktrackingLineSearch, TakesAnUnresolvableNewtonStepWhole) {
  const AscentStart newton{-5.0, 1e6, 1e-8, true};
  int calls = 0;
  const auto falling = [&](double) {
    ++calls;
    return -5.0 - 1e-9;
  };
  EXPECT_EQ(backtracking_line_search(newton, falling), 1.0);
  EXPECT_EQ(calls, 1);
  AscentStart steepest = newton;
  steepest.newton = false;
  EXPECT_FALSE(backtracking_line_search(steepest, falling).has_value());
  AscentStart resolvable = newton;
  resolvable.predicted_gain = 1e-6;
  EXPECT_FALSE(backtracking_line_search(resolvable, falling).has_value());
}

}  // namespace
}  // namespace blockfrag
