// The equations of motion in their general form, M q'' = Q + J^T lambda
// (engine/contact/body_load.hpp), against what must equal them:
// - a constant horizontal force F per unit mass is the same as the ground's acceleration shifted
//   by F / g (its inertial force is lambda g per unit mass), in every contact mode;
// - an added mass a M on horizontal motion at the centre of mass (no lever arm), driven by the
//   ground as the block is, is a block heavier in x alone: (1 + a) x'' = (1 + a) lambda g + F_x,
//   y and theta unchanged. Sliding, that is the dry block with friction mu / (1 + a); in flight,
//   the dry block's parabola; resting, slide's onset at lambda = mu / (1 + a); rocking about a
//   corner, the energy integral with the moment of inertia about the corner plus a z^2, z the
//   centre's height over the corner.
// On a flat seat of one segment, the engine that takes the general form.
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "engine/contact/body_load.hpp"
#include "engine/seat/seat_simulation.hpp"

namespace blockfrag {
namespace {

constexpr double kLoadG = 9.81;

class ConstantPush : public ExternalLoad {
 public:
  explicit ConstantPush(double force) : force_(force) {}
  LoadAddition at(const BlockState&, double, double, Footing) const override {
    return {{force_, 0.0}, 0.0, 0.0, 0.0, 0.0};
  }

 private:
  double force_;
};

class CentredAddedMass : public ExternalLoad {
 public:
  explicit CentredAddedMass(double ratio) : ratio_(ratio) {}
  LoadAddition at(const BlockState&, double lambda, double g, Footing) const override {
    return {{ratio_ * lambda * g, 0.0}, 0.0, ratio_, 0.0, 0.0};
  }

 private:
  double ratio_;
};

// A rectangle on one flat segment far longer than any slide here, under a constant ground
// acceleration lambda = amplitude for the whole run.
Scene on_flat_seat(double half_width, double half_height, double mu, double e, double amplitude,
                   double duration) {
  Scene scene;
  scene.block = {half_width, half_height, 1.0};
  scene.contact = {mu, e};
  scene.seat = Seat{{{-100.0, -half_height}, {100.0, -half_height}}};
  scene.ground_motion = RectangularPulse{amplitude, 100.0};
  scene.duration = duration;
  scene.g = kLoadG;
  scene.solver.tolerance = 1e-10;
  return scene;
}

std::vector<ModeKind> mode_kinds(const Summary& s) {
  std::vector<ModeKind> out;
  for (const ModeChange& m : s.modes) out.push_back(m.mode);
  return out;
}

bool visits(const Summary& s, ModeKind kind) {
  for (const ModeChange& m : s.modes) {
    if (m.mode == kind) return true;
  }
  return false;
}

struct ShiftCase {
  std::string name;
  double half_width, half_height, mu, e, lambda, push_g, duration, omega;
  ModeKind visited;
};

TEST(GeneralizedLoad, AConstantHorizontalForceIsAShiftOfLambdaInEveryMode) {
  const std::vector<ShiftCase> cases{
      {"rest", 1.0, 0.5, 0.6, 0.5, 0.1, 0.2, 2.0, 0.0, ModeKind::rest},
      {"slide", 1.0, 0.5, 0.3, 0.5, 0.2, 0.3, 1.0, 0.0, ModeKind::slide},
      {"rock", 0.25, 1.0, 2.0, 0.0, 0.2, 0.1, 3.0, 0.0, ModeKind::rock},
      {"slide-rock", 0.4, 1.0, 0.45, 0.5, 0.4, 0.2, 1.0, 0.0, ModeKind::slide_rock},
      {"flight", 0.5, 1.0, 0.3, 0.9, 0.1, 0.1, 1.5, -20.0, ModeKind::flight},
  };
  for (const ShiftCase& c : cases) {
    SCOPED_TRACE(c.name);
    Scene pushed = on_flat_seat(c.half_width, c.half_height, c.mu, c.e, c.lambda, c.duration);
    pushed.initial.omega = c.omega;
    Scene shifted = pushed;
    shifted.ground_motion = RectangularPulse{c.lambda + c.push_g, 100.0};
    const ConstantPush push(c.push_g * kLoadG);
    const Summary a = simulate_on_seat(pushed, 0.0, &push).summary;
    const Summary b = simulate_on_seat(shifted, 0.0).summary;
    ASSERT_EQ(a.status, Status::ok);
    ASSERT_EQ(b.status, Status::ok);
    EXPECT_TRUE(visits(b, c.visited));
    EXPECT_EQ(mode_kinds(a), mode_kinds(b));
    EXPECT_EQ(a.overturned, b.overturned);
    EXPECT_NEAR(a.final_slide, b.final_slide, 1e-9);
    EXPECT_NEAR(a.final_theta, b.final_theta, 1e-9);
    EXPECT_NEAR(a.max_abs_theta, b.max_abs_theta, 1e-9);
    EXPECT_NEAR(a.overturn_time.value_or(-1.0), b.overturn_time.value_or(-1.0), 1e-9);
  }
}

TEST(GeneralizedLoad, ACentredAddedMassSlidesAsFrictionOverOnePlusItsRatio) {
  // Squat (b / h = 2): neither block can rock under lambda = 0.5.
  const double ratio = 0.5, mu = 0.3, lambda = 0.5, duration = 1.0;
  const CentredAddedMass added(ratio);
  const Summary wet =
      simulate_on_seat(on_flat_seat(1.0, 0.5, mu, 0.5, lambda, duration), 0.0, &added).summary;
  const Summary dry =
      simulate_on_seat(on_flat_seat(1.0, 0.5, mu / (1.0 + ratio), 0.5, lambda, duration), 0.0)
          .summary;
  EXPECT_EQ(mode_kinds(wet), std::vector<ModeKind>{ModeKind::slide});
  EXPECT_NEAR(wet.final_slide, dry.final_slide, 1e-9);
  // x'' = lambda g - mu g / (1 + a) from rest.
  EXPECT_NEAR(wet.final_slide, 0.5 * (lambda - mu / (1.0 + ratio)) * kLoadG * duration * duration,
              1e-9);
}

TEST(GeneralizedLoad, ACentredAddedMassStartsToSlideAtFrictionOverOnePlusItsRatio) {
  const double ratio = 0.5, mu = 0.3, onset = mu / (1.0 + ratio);
  const CentredAddedMass added(ratio);
  const Summary below =
      simulate_on_seat(on_flat_seat(1.0, 0.5, mu, 0.5, onset - 1e-6, 1.0), 0.0, &added).summary;
  const Summary above =
      simulate_on_seat(on_flat_seat(1.0, 0.5, mu, 0.5, onset + 1e-6, 1.0), 0.0, &added).summary;
  EXPECT_EQ(mode_kinds(below), std::vector<ModeKind>{ModeKind::rest});
  EXPECT_EQ(below.final_slide, 0.0);
  EXPECT_TRUE(visits(above, ModeKind::slide));
  EXPECT_GT(above.final_slide, 0.0);
}

TEST(GeneralizedLoad, ACentredAddedMassFliesTheDryParabola) {
  // Thrown turning fast enough to leave the ground at once, it overturns in flight.
  Scene scene = on_flat_seat(0.5, 1.0, 0.3, 0.9, 0.2, 1.5);
  scene.initial.omega = -20.0;
  const CentredAddedMass added(0.7);
  const Summary wet = simulate_on_seat(scene, 0.0, &added).summary;
  const Summary dry = simulate_on_seat(scene, 0.0).summary;
  ASSERT_EQ(mode_kinds(dry), std::vector<ModeKind>{ModeKind::flight});
  ASSERT_TRUE(dry.overturned);
  EXPECT_EQ(mode_kinds(wet), mode_kinds(dry));
  ASSERT_TRUE(wet.overturned);
  EXPECT_NEAR(*wet.overturn_time, *dry.overturn_time, 1e-9);
  EXPECT_NEAR(wet.final_slide, dry.final_slide, 1e-9);
}

// Released at rest tilted by theta0 on a corner (no ground motion, sticking), the block rocks back
// to its base: the time it takes from the energy integral
//   1/2 omega^2 (4/3 R^2 + a R^2 cos^2(alpha - theta)) = g R (cos(alpha - theta0) - cos(alpha -
//   theta)),
// by Simpson's rule in u with theta = theta0 - u^2 (which takes the release's 1/sqrt singularity).
double time_to_land(double half_width, double half_height, double ratio, double theta0) {
  const double radius = std::hypot(half_width, half_height);
  const double alpha = std::atan(half_width / half_height);
  const auto dt_du = [&](double u) {
    const double theta = theta0 - u * u;
    const double z = radius * std::cos(alpha - theta);
    const double inertia = 4.0 / 3.0 * radius * radius + ratio * z * z;
    const double drop = std::cos(alpha - theta0) - std::cos(alpha - theta);
    if (u == 0.0) {  // omega ~ sqrt(2 g R sin(alpha - theta0) u^2 / I): 2 u / omega tends to this
      return 2.0 / std::sqrt(2.0 * kLoadG * radius * std::sin(alpha - theta0) / inertia);
    }
    return 2.0 * u / std::sqrt(2.0 * kLoadG * radius * drop / inertia);
  };
  const int n = 20000;
  const double end = std::sqrt(theta0), h = end / n;
  double sum = dt_du(0.0) + dt_du(end);
  for (int i = 1; i < n; ++i) sum += (i % 2 == 1 ? 4.0 : 2.0) * dt_du(i * h);
  return sum * h / 3.0;
}

TEST(GeneralizedLoad, ACentredAddedMassRocksByTheEnergyIntegralWithItsInertia) {
  const double theta0 = 0.15;
  for (const double ratio : {0.0, 0.5, 2.0}) {
    SCOPED_TRACE(ratio);
    Scene scene = on_flat_seat(0.5, 1.0, 2.0, 0.0, 0.0, 3.0);
    scene.initial.theta = theta0;
    const CentredAddedMass added(ratio);
    const Summary s = simulate_on_seat(scene, 0.0, ratio > 0.0 ? &added : nullptr).summary;
    ASSERT_TRUE(s.first_impact_time.has_value());
    EXPECT_NEAR(*s.first_impact_time, time_to_land(0.5, 1.0, ratio, theta0), 1e-8);
  }
}

}  // namespace
}  // namespace blockfrag
