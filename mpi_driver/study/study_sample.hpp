// From a sample index to its scene: a pure function of (config, index). Index i belongs to level
// i / n and is member j = i % n of it (n = samples per level); its input values come from
// sampling/ (Philox streams named after the inputs, then inverse CDFs), and the scene is the base
// scene with those values and the level's amplitude. No rank, schedule or restart enters it.
#pragma once

#include <cstdint>
#include <vector>

#include "engine/scene/scene.hpp"
#include "mpi_driver/config/study_config.hpp"
#include "sampling/sampling_plan.hpp"

namespace blockfrag {

struct StudySample {
  std::int64_t index = 0;
  std::uint32_t level = 0;
  double im = 0.0;             // the level's amplitude, g (positive; direction gives the sign)
  std::vector<double> values;  // one per config.inputs; direction as +1 or -1
  Scene scene;
};

SamplingPlan sampling_plan(const StudyConfig& config);

// The base scene with the inputs' values and a pulse of amplitude direction * im. Throws
// ContractViolation if the base scene has no pulse to scale (the study config refuses such a
// scene).
Scene apply_sample(const StudyConfig& config, const std::vector<double>& values, double im);

// Draws samples of one study; keeps the current level's Latin hypercube permutations, so draw
// indices level by level when speed matters. Any order gives the same values. One per thread.
class StudySampler {
 public:
  explicit StudySampler(const StudyConfig& config);
  StudySample draw(std::int64_t index);

 private:
  const StudyConfig& config_;
  Sampler sampler_;
};

}  // namespace blockfrag
