// A randomized stress test over wide input ranges (rectangles and polygons, three pulse shapes,
// vertical motion, dam crests): every scene finishes with finite outputs, no impact gains energy,
// the contact force stays in Coulomb's cone with V >= 0, and the work is bounded. A failing scene
// is printed as a scene JSON to replay with `blockfrag simulate`.
// BLOCKFRAG_RANDOM_SCENES sets the count (default 100000; CI's sanitizer pass uses fewer).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <random>
#include <vector>

#include "engine/simulate.hpp"
#include "mpi_driver/config/scene_json.hpp"

namespace blockfrag {
namespace {

long scene_count(long fallback) {
  const char* text = std::getenv("BLOCKFRAG_RANDOM_SCENES");
  return text ? std::atol(text) : fallback;
}

double log_uniform(std::mt19937_64& rng, double lo, double hi) {
  return lo * std::pow(hi / lo, std::uniform_real_distribution<double>(0, 1)(rng));
}

Scene random_scene(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0, 1);
  Scene s;
  const double b = log_uniform(rng, 0.01, 50.0);
  s.block = {b * log_uniform(rng, 0.05, 2.0), b, log_uniform(rng, 1e-3, 1e7)};
  s.contact = {2.0 * u(rng), u(rng)};
  const double pick = u(rng);
  if (pick < 0.05) s.contact.restitution = 0.0;
  if (pick > 0.95) s.contact.restitution = 1.0;
  const double A = log_uniform(rng, 0.05, 20.0) * (u(rng) < 0.5 ? -1 : 1);
  const double T = log_uniform(rng, 0.05, 5.0);
  const int kind = static_cast<int>(3 * u(rng));
  if (kind == 0) s.ground_motion = CosinePulse{A, T, std::floor(1 + 3 * u(rng))};
  if (kind == 1) s.ground_motion = SinePulse{A, T, 0.5 * std::floor(1 + 6 * u(rng))};
  if (kind == 2) s.ground_motion = RectangularPulse{A, T};
  s.duration = std::min(10.0, 2 * T + 2);
  // The inputs of later issues: vertical motion (lift-off beyond 1 g), polygon blocks (a
  // trapezoid, or a pentagon with a gable), a dam crest between the ground and the block.
  if (u(rng) < 0.3) {
    const double Av = log_uniform(rng, 0.05, 2.0) * (u(rng) < 0.5 ? -1 : 1);
    const double Tv = log_uniform(rng, 0.05, 5.0);
    s.vertical_motion = SinePulse{Av, Tv, 0.5 * std::floor(1 + 6 * u(rng))};
  }
  if (u(rng) < 0.3) {
    const double w = s.block.half_width, h = 2 * s.block.half_height;
    const double top_left = -w + 0.9 * w * u(rng), top_right = w - 0.9 * w * u(rng);
    std::vector<std::array<double, 2>> v = {{-w, 0}, {w, 0}, {top_right, h}, {top_left, h}};
    if (u(rng) < 0.5) {
      v.insert(v.begin() + 3, {0.5 * (top_left + top_right), h * (1 + 0.3 * u(rng))});
    }
    s.polygon = PolygonBlock{v, 1.0};
  }
  if (u(rng) < 0.2) s.dam = DamCrest{DamPeriod{log_uniform(rng, 0.05, 0.5)}, 0.05, 1.0};
  s.solver.tolerance = log_uniform(rng, 1e-10, 1e-6);
  return s;
}

std::string why_bad(const Summary& s) {
  if (s.status != Status::ok) return "failed: " + s.status_reason;
  for (const double v : {s.max_abs_theta, s.final_theta, s.final_slide, s.max_abs_slide}) {
    if (!std::isfinite(v)) return "non-finite output";
  }
  if (s.max_impact_energy_gain > 1e-9) return "an impact gained energy";
  if (s.max_contact_violation > 1e-6) return "contact force outside the cone or pulling";
  // The contact tolerance (1e-9 R) lets a corner put on the ground leave the other that far under.
  if (s.max_penetration > 2e-9) return "a corner went through the ground";
  if (s.steps > 500'000 || s.events > 500'000) return "unbounded work";
  return {};
}

void run_random_scenes(unsigned seed, long count, bool paper_method) {
  std::mt19937_64 rng(seed);
  long failures = 0;
  for (long i = 0; i < count; ++i) {
    Scene scene = random_scene(rng);
    if (paper_method) {
      scene.solver.method = Method::rk4;
      scene.solver.dt = 2.5e-4;
    }
    const std::string bad = why_bad(simulate(scene));
    if (!bad.empty() && ++failures <= 20) {
      ADD_FAILURE() << "scene " << i << ": " << bad << "\n" << scene_to_json(scene).dump();
    }
  }
  EXPECT_EQ(failures, 0) << "of " << count << " scenes";
}

TEST(RandomScenes, AdaptiveMethodHoldsOnEveryScene) {
  run_random_scenes(20261121, scene_count(100'000), false);
}

TEST(RandomScenes, PaperMethodHoldsOnEveryScene) {
  run_random_scenes(1963, scene_count(100'000) / 50, true);
}

}  // namespace
}  // namespace blockfrag
