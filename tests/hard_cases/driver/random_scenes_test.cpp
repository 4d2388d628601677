// A randomized stress test over wide input ranges (rectangles and polygons, three pulse shapes,
// vertical motion, dam crests): every scene finishes with finite outputs, no impact gains energy,
// the contact force stays in Coulomb's cone with V >= 0, and the work is bounded. A failing scene
// is printed as a scene JSON to replay with `blockfrag simulate`.
// BLOCKFRAG_RANDOM_SCENES sets the count (default 100000; CI's sanitizer pass uses fewer).
// Scene i draws every input from its own Philox stream (sampling/philox_stream.hpp), counted by i:
// the uniforms are the same bits on every platform and standard library, and each input maps them
// to its range by plain arithmetic (log-uniform ranges through std::pow) or, for a choice among n,
// by index_below; no std::*_distribution, no rejection.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include <gtest/gtest.h>

#include "engine/simulate.hpp"
#include "mpi_driver/config/scene_json.hpp"
#include "sampling/philox_stream.hpp"

namespace blockfrag {
namespace {

long scene_count(long fallback) {
  const char* text = std::getenv("BLOCKFRAG_RANDOM_SCENES");
  return text ? std::atol(text) : fallback;
}

// The random inputs of scene `index`, each from the stream of its name.
class SceneDraws {
 public:
  SceneDraws(std::uint64_t seed, std::uint64_t index) : seed_(seed), index_(index) {}

  // Uniform in (0, 1).
  double uniform(std::string_view input) const {
    return uniform_open01(seed_, stream_id(input), index_);
  }
  double uniform(std::string_view input, double lo, double hi) const {
    return lo + (hi - lo) * uniform(input);
  }
  // Log-uniform in (lo, hi).
  double log_uniform(std::string_view input, double lo, double hi) const {
    return lo * std::pow(hi / lo, uniform(input));
  }
  // One of 0, 1, ..., n - 1.
  std::uint32_t choice(std::string_view input, std::uint32_t n) const {
    return index_below(random_bits(seed_, stream_id(input), index_, 0), n);
  }
  bool chance(std::string_view input, double p) const { return uniform(input) < p; }
  double sign(std::string_view input) const { return choice(input, 2) == 0 ? -1.0 : 1.0; }

 private:
  std::uint64_t seed_, index_;
};

Scene random_scene(const SceneDraws& d) {
  Scene s;
  const double b = d.log_uniform("half_height", 0.01, 50.0);
  s.block = {b * d.log_uniform("aspect_ratio", 0.05, 2.0), b, d.log_uniform("mass", 1e-3, 1e7)};
  s.contact = {d.uniform("friction", 0.0, 2.0), d.uniform("restitution")};
  const double pick = d.uniform("restitution_extreme");
  if (pick < 0.05) s.contact.restitution = 0.0;
  if (pick > 0.95) s.contact.restitution = 1.0;
  const double A = d.log_uniform("amplitude", 0.05, 20.0) * d.sign("amplitude_sign");
  const double T = d.log_uniform("period", 0.05, 5.0);
  const std::uint32_t kind = d.choice("pulse_kind", 3);
  if (kind == 0) s.ground_motion = CosinePulse{A, T, 1.0 + d.choice("cosine_cycles", 3)};
  if (kind == 1) s.ground_motion = SinePulse{A, T, 0.5 * (1 + d.choice("sine_cycles", 6))};
  if (kind == 2) s.ground_motion = RectangularPulse{A, T};
  s.duration = std::min(10.0, 2 * T + 2);
  // The inputs of later issues: vertical motion (lift-off beyond 1 g), polygon blocks (a
  // trapezoid, or a pentagon with a gable), a rocking restitution, a dam crest between the ground
  // and the block.
  if (d.chance("vertical", 0.3)) {
    const double Av = d.log_uniform("vertical_amplitude", 0.05, 2.0) * d.sign("vertical_sign");
    const double Tv = d.log_uniform("vertical_period", 0.05, 5.0);
    s.vertical_motion = SinePulse{Av, Tv, 0.5 * (1 + d.choice("vertical_cycles", 6))};
  }
  if (d.chance("polygon", 0.3)) {
    const double w = s.block.half_width, h = 2 * s.block.half_height;
    const double top_left = -w + 0.9 * w * d.uniform("top_left");
    const double top_right = w - 0.9 * w * d.uniform("top_right");
    std::vector<std::array<double, 2>> v = {{-w, 0}, {w, 0}, {top_right, h}, {top_left, h}};
    if (d.chance("gable", 0.5)) {
      v.insert(v.begin() + 3,
               {0.5 * (top_left + top_right), h * (1 + 0.3 * d.uniform("gable_height"))});
    }
    s.polygon = PolygonBlock{v, 1.0};
  }
  if (d.chance("rocking_restitution", 0.3)) {
    s.contact.rocking_restitution =
        d.chance("housner", 0.2) ? RockingRestitution{true, 1.0}
                                 : RockingRestitution{false, d.uniform("rocking_ratio", 0.3, 1.0)};
  }
  if (d.chance("dam", 0.2))
    s.dam = DamCrest{DamPeriod{d.log_uniform("dam_period", 0.05, 0.5)}, 0.05, 1.0};
  s.solver.tolerance = d.log_uniform("tolerance", 1e-10, 1e-6);
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

void run_random_scenes(std::uint64_t seed, long count, bool paper_method) {
  long failures = 0;
  // The largest relative kinetic-energy gain at any event of any scene (impacts and layings of a
  // landing block on its contacts): printed, the energy check's figure.
  double largest_gain = 0.0;
  long largest_at = -1;
  for (long i = 0; i < count; ++i) {
    Scene scene = random_scene(SceneDraws(seed, static_cast<std::uint64_t>(i)));
    if (paper_method) {
      scene.solver.method = Method::rk4;
      scene.solver.dt = 2.5e-4;
    }
    const Summary summary = simulate(scene);
    if (summary.max_impact_energy_gain > largest_gain) {
      largest_gain = summary.max_impact_energy_gain;
      largest_at = i;
    }
    const std::string bad = why_bad(summary);
    if (!bad.empty() && ++failures <= 20) {
      ADD_FAILURE() << "scene " << i << ": " << bad << "\n" << scene_to_json(scene).dump();
    }
  }
  std::printf("largest kinetic-energy gain at an event over %ld scenes: %.3g (scene %ld)\n", count,
              largest_gain, largest_at);
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
