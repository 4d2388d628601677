// From a sample index to its scene: a pure function of (config, index). Index i belongs to level
// i / n (a cell of a surface's grid: intensity_measure.hpp) and is member j = i % n of it (n =
// samples per level); its input values come from
// sampling/ (Philox streams named after the inputs, then inverse CDFs); with a record suite, its
// record is the suite's record_of(j, n). The scene is the base scene with those values and the
// motion scaled to the level's intensity (stripes), or by the fixed scale (a cloud). No rank,
// schedule or restart enters it.
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
  std::vector<double> values;  // one per config.inputs; direction as +1 or -1
  std::int64_t record = -1;    // the suite's record it runs; -1 for a pulse
  double scale = 1.0;          // the factor on its unit motion (> 0; direction gives the sign)
  // Its intensity, in the measure's unit: the level's for stripes, its own in a cloud.
  double im = 0.0;
  double im2 = 0.0;  // a surface's second measure: its cell's pulse period (s); 0 otherwise
  // Its motion's peak ground acceleration (g) and velocity (m/s); NaN unless drawn with measures.
  double pga_g = 0.0;
  double pgv_m_s = 0.0;
  Scene scene;
};

SamplingPlan sampling_plan(const StudyConfig& config);

// The base scene with the inputs' values, and the pulse's amplitude (or velocity amplitude) set to
// `amplitude`: the scene of a pulse study's sample before the motion is scaled. Throws
// ContractViolation if the base scene has no pulse to scale (the study config refuses one).
Scene apply_sample(const StudyConfig& config, const std::vector<double>& values, double amplitude);

// Draws samples of one study; keeps the current level's Latin hypercube permutations, so draw
// indices level by level when speed matters. Any order gives the same values. One per thread.
class StudySampler {
 public:
  explicit StudySampler(const StudyConfig& config);
  // with_measures: also the motion's PGA and PGV (a pulse's are computed, a record's scaled from
  // the suite's), for the output's columns.
  StudySample draw(std::int64_t index, bool with_measures = false);

 private:
  const StudyConfig& config_;
  Sampler sampler_;
};

}  // namespace blockfrag
