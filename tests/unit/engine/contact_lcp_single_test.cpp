// A choice with one slipping contact and every other off is a 1 x 1 system that solve_contact_lcp
// solves in closed form (solve_single) instead of with Eigen's FullPivLU: on random systems, and on
// zeros of either sign, infinities and NaN, it finds the same systems singular and gives the same
// solutions to the bit, so the LCP decides and forces as before.
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "engine/contact/contact_lcp.hpp"
#include "tests/support/fixed_uniforms.hpp"

namespace blockfrag {
namespace {

// The matrix type solve_contact_lcp decomposes: dynamic, at most 12 x 12.
using Matrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 12, 12>;
using Vector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 12, 1>;

std::optional<double> by_lu(double a, double d) {
  const Eigen::FullPivLU<Matrix> lu(Matrix::Constant(1, 1, a));
  if (!lu.isInvertible()) return std::nullopt;
  const Vector x = lu.solve(Vector::Constant(1, d));
  return x(0);
}

void expect_same(double a, double d) {
  const std::optional<double> closed = solve_single(a, d), lu = by_lu(a, d);
  ASSERT_EQ(closed.has_value(), lu.has_value()) << "a = " << a << ", d = " << d;
  if (closed) {
    EXPECT_EQ(std::bit_cast<std::uint64_t>(*closed), std::bit_cast<std::uint64_t>(*lu))
        << "a = " << a << ", d = " << d;
  }
}

TEST(ContactLcpSingle, SolvesAsFullPivLuToTheBit) {
  testing::FixedUniforms uniform(20261208);
  for (int i = 0; i < 100000; ++i) {
    const double a = (uniform(0, 1) < 0.5 ? -1 : 1) * std::pow(10.0, uniform(-300, 300));
    const double d = (uniform(0, 1) < 0.5 ? -1 : 1) * std::pow(10.0, uniform(-300, 300));
    expect_same(a, d);
    expect_same(uniform(-1, 1), uniform(-1, 1));
  }
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double tiny = std::numeric_limits<double>::denorm_min();
  const std::vector<double> special = {0.0, -0.0, 1.0, -2.5, tiny, -tiny, inf, -inf, nan};
  for (const double a : special) {
    for (const double d : special) expect_same(a, d);
  }
}

}  // namespace
}  // namespace blockfrag
