// A record that samples a cosine pulse finely drives the block as the pulse does: the record is the
// ground's acceleration (a = -lambda), linear between samples, zero after the last. Scaling to a
// target PGA is the pulse of that amplitude; the rk4 resampling of an off-grid record costs no
// short steps and keeps the result of the adaptive run on the record as it is.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "engine/simulate.hpp"
#include "mpi_driver/config/scene_json.hpp"
#include "tests/support/scene_builders.hpp"

namespace blockfrag {
namespace {

using testing::block_scene;
using testing::rk4;

// a(t_k) = -A cos(2 pi t_k / T) at t_k = k h through `cycles` periods: the pulse's -lambda.
std::shared_ptr<const Accelerogram> sampled_cosine(double A, double T, double cycles, double h) {
  auto record = std::make_shared<Accelerogram>();
  const auto n = static_cast<long>(std::llround(cycles * T / h));
  for (long k = 0; k <= n; ++k) {
    const double t = static_cast<double>(k) * h;
    record->times.push_back(t);
    record->acceleration_g.push_back(-A * std::cos(2 * std::numbers::pi * t / T));
  }
  return record;
}

Scene with_record(Scene scene, std::shared_ptr<const Accelerogram> record, double scale = 1.0) {
  scene.ground_motion = RecordedMotion{"cosine (in memory)", scale, std::move(record)};
  return scene;
}

// Linear interpolation misses a smooth f by at most h^2/8 max|f''| (and by h^2/12 |f''| on average
// over a step): for A cos(omega t) the record's forcing is the pulse's to within A delta, with
// delta = (omega h)^2 / 8, and acts on average like the pulse with its amplitude cut by 2/3 of
// that. A result therefore differs by about its sensitivity to the amplitude times delta. The
// sensitivity is measured on the pulse itself (central difference at +-1e-5 of the amplitude, well
// inside the range where the events stay the same); the allowance is twice sensitivity x delta
// (three times the mean effect), plus 1e-7 for what the solver's tolerance leaves.
struct Allowance {
  double theta, slide, time;
};

Allowance allowance(const Scene& pulse_scene, double delta) {
  const double eps = 1e-5;
  Scene up = pulse_scene, down = pulse_scene;
  std::get<CosinePulse>(up.ground_motion).amplitude_g *= 1 + eps;
  std::get<CosinePulse>(down.ground_motion).amplitude_g *= 1 - eps;
  const Summary s_up = simulate(up), s_down = simulate(down);
  const double margin = 2.0 * delta / (2 * eps);
  const double floor = 1e-7;
  return {margin * std::abs(s_up.max_abs_theta - s_down.max_abs_theta) + floor,
          margin * std::abs(s_up.final_slide - s_down.final_slide) + floor,
          s_up.overturn_time && s_down.overturn_time
              ? margin * std::abs(*s_up.overturn_time - *s_down.overturn_time) + floor
              : floor};
}

struct Case {
  const char* name;
  Scene scene;
  bool overturns;
  bool slides;
};

TEST(RecordMotion, AFinelySampledCosinePulseActsAsThePulse) {
  const double h = 1e-3;
  const Case cases[] = {
      // a/b = 0.2, mu 0.7: rocks (A > a/b), stays up; its impacts slip a little, leaving a residual
      // slide of 1.6 mm that is very sensitive to the forcing (190 mm per unit relative amplitude).
      {"rocking", block_scene(0.2, 1.0, 0.7, 0.8, CosinePulse{0.3, 1.0, 2.0}, 4.0), false, false},
      // The paper's block under the paper's pulse: slides at the start, rocks, overturns.
      {"paper", block_scene(0.5, 1.0, 0.6, 0.6, CosinePulse{1.0, 2.0, 1.0}, 4.0), true, true},
      // mu < a/b: slides only, Newmark-like.
      {"sliding", block_scene(1.0, 1.0, 0.25, 0.5, CosinePulse{0.5, 1.0, 1.0}, 3.0), false, true},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const CosinePulse pulse = std::get<CosinePulse>(c.scene.ground_motion);
    const Scene recorded =
        with_record(c.scene, sampled_cosine(pulse.amplitude_g, pulse.period, pulse.cycles, h));
    const Summary expected = simulate(c.scene), got = simulate(recorded);
    ASSERT_EQ(expected.status, Status::ok);
    ASSERT_EQ(got.status, Status::ok) << got.status_reason;
    // The cases cover what they are named for, on the pulse itself.
    EXPECT_EQ(expected.overturned, c.overturns);
    EXPECT_EQ(std::abs(expected.final_slide) > 1e-2, c.slides) << expected.final_slide;

    const double omega = 2 * std::numbers::pi / pulse.period;
    const Allowance tol = allowance(c.scene, std::pow(omega * h, 2) / 8);
    std::cout << c.name << ": max|theta| " << expected.max_abs_theta << " vs " << got.max_abs_theta
              << " (allowed " << tol.theta << "), slide " << expected.final_slide << " vs "
              << got.final_slide << " (allowed " << tol.slide << ")";
    if (expected.overturn_time) {
      std::cout << ", overturns at " << *expected.overturn_time << " vs "
                << got.overturn_time.value_or(-1) << " (allowed " << tol.time << ")";
    }
    std::cout << "\n";
    EXPECT_EQ(got.overturned, expected.overturned);
    EXPECT_NEAR(got.max_abs_theta, expected.max_abs_theta, tol.theta);
    EXPECT_NEAR(got.final_slide, expected.final_slide, tol.slide);
    if (expected.overturn_time && got.overturn_time) {
      EXPECT_NEAR(*got.overturn_time, *expected.overturn_time, tol.time);
    }
  }
}

// The record's error is O(h^2): halving the sample step cuts the difference from the pulse by 4,
// seen on the most sensitive output, the rocking block's residual slide.
TEST(RecordMotion, TheDifferenceFromThePulseFallsAsTheSquareOfTheSampleStep) {
  const Scene pulse_scene = block_scene(0.2, 1.0, 0.7, 0.8, CosinePulse{0.3, 1.0, 2.0}, 4.0);
  const double expected = simulate(pulse_scene).final_slide;
  const auto difference = [&](double h) {
    return simulate(with_record(pulse_scene, sampled_cosine(0.3, 1.0, 2.0, h))).final_slide -
           expected;
  };
  const double coarse = difference(1e-3), fine = difference(5e-4);
  std::cout << "residual slide minus the pulse's: " << coarse << " (h = 1 ms), " << fine
            << " (h = 0.5 ms)\n";
  EXPECT_GT(coarse / fine, 3.0);
  EXPECT_LT(coarse / fine, 5.0);
}

// The record is written as two columns in unit g and scaled by target_pga_g through the scene JSON:
// the resolved scale is target / max|a| (here max|a| = 1, at t = 0), and the run is the pulse of
// amplitude target.
TEST(RecordMotion, TargetPgaScalingIsThePulseOfThatAmplitude) {
  const double h = 1e-3, T = 1.0, target = 0.3;
  const auto unit = sampled_cosine(1.0, T, 2.0, h);
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / "blockfrag_unit_cosine.txt";
  {
    std::FILE* out = std::fopen(file.c_str(), "w");
    ASSERT_NE(out, nullptr);
    std::fprintf(out, "# time_s acceleration_g\n");
    for (std::size_t k = 0; k < unit->times.size(); ++k) {
      std::fprintf(out, "%.17g %.17g\n", unit->times[k], unit->acceleration_g[k]);
    }
    std::fclose(out);
  }
  const Scene pulse_scene = block_scene(0.2, 1.0, 0.7, 0.8, CosinePulse{target, T, 2.0}, 4.0);
  nlohmann::json document = scene_to_json(pulse_scene);
  document["ground_motion"] = {
      {"type", "record"}, {"file", file.string()}, {"target_pga_g", target}};
  const Scene scaled = scene_from_json(document, "record_scene.json");
  std::filesystem::remove(file);
  const auto& motion = std::get<RecordedMotion>(scaled.ground_motion);
  EXPECT_DOUBLE_EQ(motion.scale, target);

  const Summary expected = simulate(pulse_scene), got = simulate(scaled);
  const Allowance tol = allowance(pulse_scene, std::pow(2 * std::numbers::pi / T * h, 2) / 8);
  EXPECT_GT(expected.max_abs_theta, 1e-3);
  EXPECT_EQ(got.overturned, expected.overturned);
  EXPECT_NEAR(got.max_abs_theta, expected.max_abs_theta, tol.theta);
  // And the same record pre-scaled in memory, scale 1: the same forcing to the last bit.
  const Summary prescaled = simulate(with_record(pulse_scene, sampled_cosine(target, T, 2.0, h)));
  EXPECT_EQ(prescaled.max_abs_theta, got.max_abs_theta);
  EXPECT_EQ(prescaled.impacts, got.impacts);
}

// A record at 1.3 ms does not fit rk4's 0.25 ms grid: resampled, rk4 takes its full steps (about as
// many as on the pulse itself, where one short step per sample would add 1,538 over its 2 s) and
// its result stays within the resampling and rk4 errors of the adaptive run on the record as it is.
TEST(RecordMotion, Rk4ResamplesAnOffGridRecordAndAgreesWithTheAdaptiveRun) {
  const double h = 1.3e-3, dt = 2.5e-4;
  const Scene pulse_scene = block_scene(0.2, 1.0, 0.7, 0.8, CosinePulse{0.3, 1.0, 2.0}, 4.0);
  const Scene recorded = with_record(pulse_scene, sampled_cosine(0.3, 1.0, 2.0, h));
  const Summary adaptive = simulate(recorded);
  const Summary fixed = simulate(rk4(recorded, dt));
  const Summary fixed_pulse = simulate(rk4(pulse_scene, dt));
  std::cout << "rk4 steps: record " << fixed.steps << ", pulse " << fixed_pulse.steps
            << "; max|theta| adaptive " << adaptive.max_abs_theta << ", rk4 " << fixed.max_abs_theta
            << "\n";
  ASSERT_EQ(fixed.status, Status::ok);
  EXPECT_LE(fixed.steps, fixed_pulse.steps + 2 * (fixed.events + fixed_pulse.events) + 10);
  // Resampling moves the forcing by at most dt h max|f''| / 4 (the kinks it rounds off), 5e-7 of
  // the amplitude here; rk4 at the paper's step agrees with the adaptive method to ~1e-6.
  const Allowance tol = allowance(pulse_scene, dt * h * std::pow(2 * std::numbers::pi, 2) / 4);
  EXPECT_EQ(fixed.overturned, adaptive.overturned);
  EXPECT_NEAR(fixed.max_abs_theta, adaptive.max_abs_theta, tol.theta + 1e-6);
}

}  // namespace
}  // namespace blockfrag
