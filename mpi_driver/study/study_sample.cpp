#include "mpi_driver/study/study_sample.hpp"

#include <cmath>
#include <type_traits>

#include "engine/errors.hpp"
#include "engine/motion/ground_motion.hpp"

namespace blockfrag {
namespace {

// A random sign is drawn as a uniform on (-1, 1) (equal halves of u) and reduced to its sign.
double sign_of(double value) { return value < 0.0 ? -1.0 : 1.0; }

void set_pulse(GroundMotion& motion, double amplitude_g, const double* period, double g) {
  std::visit(
      [&](auto& pulse) {
        using T = std::decay_t<decltype(pulse)>;
        if constexpr (std::is_same_v<T, NoMotion>) {
          throw ContractViolation("a study's base scene needs a pulse to scale");
        } else if constexpr (std::is_same_v<T, RecordedMotion>) {
          // A record's intensity is its peak ground acceleration (study_config refuses a zero
          // peak).
          if (period) throw ContractViolation("a period input needs a cosine or sine pulse");
          pulse.scale = amplitude_g / peak_acceleration_g(*pulse.record);
        } else if constexpr (std::is_same_v<T, MavroeidisPapageorgiouPulse>) {
          // Given by its velocity: scaled so its peak |lambda| (its PGA in g) is the intensity
          // (study_config refuses a zero velocity amplitude).
          if (period) throw ContractViolation("a period input needs a cosine or sine pulse");
          pulse.velocity_amplitude = amplitude_g * std::abs(pulse.velocity_amplitude) /
                                     GroundMotionPieces(pulse, g).peak_abs_lambda();
        } else {
          pulse.amplitude_g = amplitude_g;
          if constexpr (std::is_same_v<T, CosinePulse> || std::is_same_v<T, SinePulse>) {
            if (period) pulse.period = *period;
          } else if (period) {
            throw ContractViolation("a period input needs a cosine or sine pulse");
          }
        }
      },
      motion);
}

}  // namespace

SamplingPlan sampling_plan(const StudyConfig& config) {
  SamplingPlan plan;
  plan.seed = config.seed;
  plan.design = config.design;
  plan.samples_per_level = config.samples_per_level;
  plan.levels = static_cast<std::uint32_t>(config.intensity.levels.size());
  for (const auto& spec : config.inputs)
    plan.inputs.push_back({input_key(spec.input), spec.distribution});
  return plan;
}

Scene apply_sample(const StudyConfig& config, const std::vector<double>& values, double im) {
  Scene scene = config.base_scene;
  double direction = 1.0;
  const double* period = nullptr;
  std::optional<double> alpha, radius;
  for (std::size_t k = 0; k < config.inputs.size(); ++k) {
    const double value = values.at(k);
    switch (config.inputs[k].input) {
      case StudyInput::friction: scene.contact.friction = value; break;
      case StudyInput::restitution: scene.contact.restitution = value; break;
      case StudyInput::half_width: scene.block.half_width = value; break;
      case StudyInput::half_height: scene.block.half_height = value; break;
      case StudyInput::alpha: alpha = value; break;
      case StudyInput::R: radius = value; break;
      case StudyInput::period: period = &values[k]; break;
      case StudyInput::direction: direction = sign_of(value); break;
    }
  }
  if (alpha || radius) {
    const double a0 = scene.block.half_width, b0 = scene.block.half_height;
    const double alpha_value = alpha.value_or(std::atan2(a0, b0));
    const double radius_value = radius.value_or(std::hypot(a0, b0));
    scene.block.half_width = radius_value * std::sin(alpha_value);
    scene.block.half_height = radius_value * std::cos(alpha_value);
  }
  set_pulse(scene.ground_motion, direction * im, period, scene.g);
  return scene;
}

StudySampler::StudySampler(const StudyConfig& config)
    : config_(config), sampler_(sampling_plan(config)) {}

StudySample StudySampler::draw(std::int64_t index) {
  StudySample sample;
  sample.index = index;
  sample.level = static_cast<std::uint32_t>(index / config_.samples_per_level);
  sample.im = config_.intensity.levels.at(sample.level);
  sample.values = sampler_.draw(static_cast<std::uint64_t>(index));
  for (std::size_t k = 0; k < config_.inputs.size(); ++k) {
    if (config_.inputs[k].input == StudyInput::direction)
      sample.values[k] = sign_of(sample.values[k]);
  }
  sample.scene = apply_sample(config_, sample.values, sample.im);
  return sample;
}

}  // namespace blockfrag
