// A choice with one slipping contact and every other off is a 1 x 1 system, one with a sticking
// contact alone or two slipping a 2 x 2 one, that solve_contact_lcp solves in closed form
// (solve_single, solve_pair) instead of with Eigen's FullPivLU: on random systems, singular and
// nearly singular ones, ties of the pivot, zeros of either sign, infinities and NaN, they find the
// same systems singular and give the same solutions to the bit, so the LCP decides and forces as
// before.
#include <array>
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

void expect_same_pair(const std::array<std::array<double, 2>, 2>& a,
                      const std::array<double, 2>& d) {
  Matrix m(2, 2);
  m << a[0][0], a[0][1], a[1][0], a[1][1];
  const Eigen::FullPivLU<Matrix> lu(m);
  Vector rhs(2);
  rhs << d[0], d[1];
  const auto closed = solve_pair(a, d);
  const bool finite = m.allFinite();
  // Where the LU finds it invertible the closed form must solve it; elsewhere it leaves it.
  ASSERT_EQ(closed.has_value(), finite && lu.isInvertible()) << m;
  if (!closed) return;
  const Vector x = lu.solve(rhs);
  for (int i = 0; i < 2; ++i) {
    EXPECT_EQ(std::bit_cast<std::uint64_t>((*closed)[static_cast<std::size_t>(i)]),
              std::bit_cast<std::uint64_t>(x(i)))
        << m << "\n"
        << rhs.transpose();
  }
}

TEST(ContactLcpSingle, SolvesTwoByTwoAsFullPivLuToTheBit) {
  testing::FixedUniforms uniform(8122026);
  const auto value = [&] {
    const double u = uniform(0, 1);
    if (u < 0.1) return uniform(0, 1) < 0.5 ? 0.0 : -0.0;
    if (u < 0.3) return std::round(uniform(-3, 3));  // ties of the pivot, exact singularity
    return (uniform(0, 1) < 0.5 ? -1 : 1) * std::pow(10.0, uniform(-20, 20));
  };
  for (int i = 0; i < 200000; ++i) {
    const std::array<std::array<double, 2>, 2> a{{{value(), value()}, {value(), value()}}};
    expect_same_pair(a, {value(), value()});
    // Nearly singular: the second row the first's multiple, nudged.
    const double f = uniform(-2, 2), e = uniform(-1e-15, 1e-15);
    const std::array<std::array<double, 2>, 2> near{
        {{a[0][0], a[0][1]}, {f * a[0][0], f * a[0][1] * (1 + e)}}};
    expect_same_pair(near, {value(), value()});
  }
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const double s : {inf, -inf, nan}) {
    expect_same_pair({{{s, 1.0}, {1.0, 2.0}}}, {1.0, 1.0});
    expect_same_pair({{{1.0, 2.0}, {3.0, 4.0}}}, {s, 1.0});
  }
}

}  // namespace
}  // namespace blockfrag
