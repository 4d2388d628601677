// Event location: the bracket always holds the crossing, closes to the tolerance in few
// evaluations wherever the crossing lies, and stops at a guard's rounding noise when told to.
#include "engine/integrate/root_finding.hpp"

#include <cmath>

#include <gtest/gtest.h>

namespace blockfrag {
namespace {

struct CountedLine {
  double root;
  double curvature;
  int* evaluations;
  double operator()(double t) const {
    ++*evaluations;
    return (root - t) * (1.0 + curvature * t);
  }
};

TEST(LocateCrossing, ClosesTheBracketInFewEvaluationsWhereverTheCrossingLies) {
  // Secant steps that land a hair from an end used to be replaced by bisection, ~50 evaluations
  // to reach 1e-15 s; the crossings near an end are where events usually are (a guard that has
  // just gone through zero at the end of a step).
  for (const double root : {1e-12, 1e-7, 0.3, 0.5, 0.999, 1.0 - 1e-9}) {
    for (const double curvature : {0.0, 2.0, -0.9}) {
      int evaluations = 0;
      const CountedLine f{root, curvature, &evaluations};
      const Bracket at = locate_crossing(f, 0.0, 1.0, f(0.0), f(1.0), 1e-15);
      evaluations -= 2;
      SCOPED_TRACE("root " + std::to_string(root) + ", curvature " + std::to_string(curvature));
      EXPECT_LE(at.before, root);
      EXPECT_GE(at.after, root);
      EXPECT_LE(at.after - at.before, 1e-15);
      EXPECT_GT(f(at.before), 0.0);
      EXPECT_LE(f(at.after), 0.0);
      EXPECT_LE(evaluations, 20);
    }
  }
}

TEST(LocateCrossing, AnEndValueThatSaysLittleDoesNotPinTheEstimateToThatEnd) {
  // A guard that starts at zero is given the smallest positive value at the start: the secant then
  // points at the start, where the guard is still positive (a corner that lifts and lands later).
  int evaluations = 0;
  const CountedLine f{4.5e-6, 0.0, &evaluations};
  const Bracket at =
      locate_crossing(f, 0.0, 2e-4, std::numeric_limits<double>::min(), f(2e-4), 1e-15);
  EXPECT_NEAR(at.after, 4.5e-6, 1e-15);
  EXPECT_LE(evaluations, 30);
}

TEST(LocateCrossing, StopsAtTheValueToleranceOnANoisyGuard) {
  // A height that is the difference of two metre-sized numbers: below ~1e-16 m its sign is noise,
  // and a corner slower than 1e-3 m/s smears the crossing over 1e-13 s, far wider than 1e-15 s.
  int evaluations = 0;
  const auto noisy = [&](double t) {
    ++evaluations;
    return (1.0 + 1e-3 * (1e-4 - t)) - 1.0;
  };
  const Bracket at = locate_crossing(noisy, 0.0, 2e-4, noisy(0.0), noisy(2e-4), 1e-19,
                                     4 * std::numeric_limits<double>::epsilon());
  EXPECT_NEAR(at.after, 1e-4, 1e-12);
  EXPECT_LE(noisy(at.after), 0.0);
  EXPECT_LE(evaluations, 30);
}

}  // namespace
}  // namespace blockfrag
