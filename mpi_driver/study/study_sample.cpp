#include "mpi_driver/study/study_sample.hpp"

#include <cmath>
#include <limits>
#include <type_traits>

#include "engine/errors.hpp"
#include "engine/motion/ground_motion.hpp"
#include "engine/motion/intensity_measures.hpp"
#include "engine/scene/block_geometry.hpp"

namespace blockfrag {
namespace {

// A random sign is drawn as a uniform on (-1, 1) (equal halves of u) and reduced to its sign.
double sign_of(double value) { return value < 0.0 ? -1.0 : 1.0; }

// Sets the pulse's amplitude (its velocity amplitude for the Mavroeidis-Papageorgiou pulse, which
// a velocity defines) and its period when the study samples one.
void set_pulse(GroundMotion& motion, double amplitude, const double* period) {
  std::visit(
      [&](auto& pulse) {
        using T = std::decay_t<decltype(pulse)>;
        if constexpr (std::is_same_v<T, NoMotion> || std::is_same_v<T, RecordedMotion>) {
          throw ContractViolation("a pulse study's base scene needs a pulse to scale");
        } else if constexpr (std::is_same_v<T, MavroeidisPapageorgiouPulse>) {
          if (period) throw ContractViolation("a period input needs a cosine or sine pulse");
          pulse.velocity_amplitude = amplitude;
        } else {
          pulse.amplitude_g = amplitude;
          if constexpr (std::is_same_v<T, CosinePulse> || std::is_same_v<T, SinePulse>) {
            if (period) pulse.period = *period;
          } else if (period) {
            throw ContractViolation("a period input needs a cosine or sine pulse");
          }
        }
      },
      motion);
}

// The measure `type` of a motion of unit scale (a pulse of amplitude 1 g or 1 m/s, a record as
// recorded), in the measure's unit; the dimensionless one divides the PGA by tan(alpha).
double unit_measure(const IntensityMeasure& measure, double pga_g, double pgv_m_s, double sa_g,
                    double alpha) {
  switch (measure.type) {
    case ImType::pulse_amplitude: return 1.0;
    case ImType::pga: return pga_g;
    case ImType::pgv: return pgv_m_s;
    case ImType::sa: return sa_g;
    case ImType::pga_over_g_tan_alpha: return pga_g / std::tan(alpha);
  }
  return 0.0;
}

}  // namespace

SamplingPlan sampling_plan(const StudyConfig& config) {
  SamplingPlan plan;
  plan.seed = config.seed;
  plan.design = config.design;
  plan.samples_per_level = config.samples_per_level;
  plan.levels = static_cast<std::uint32_t>(config.intensity.level_count());
  for (const auto& spec : config.inputs)
    plan.inputs.push_back({input_key(spec.input), spec.distribution});
  return plan;
}

Scene apply_sample(const StudyConfig& config, const std::vector<double>& values, double amplitude) {
  Scene scene = config.base_scene;
  const double* period = nullptr;
  std::optional<double> alpha, radius;
  for (std::size_t k = 0; k < config.inputs.size(); ++k) {
    const double value = values.at(k);
    switch (config.inputs[k].input) {
      case StudyInput::friction: scene.contact.friction = value; break;
      case StudyInput::restitution: scene.contact.restitution = value; break;
      case StudyInput::rocking_restitution:
        scene.contact.rocking_restitution = RockingRestitution{false, value};
        break;
      case StudyInput::half_width: scene.block.half_width = value; break;
      case StudyInput::half_height: scene.block.half_height = value; break;
      case StudyInput::alpha: alpha = value; break;
      case StudyInput::R: radius = value; break;
      case StudyInput::period: period = &values[k]; break;
      case StudyInput::direction: break;
    }
  }
  if (alpha || radius) {
    const double a0 = scene.block.half_width, b0 = scene.block.half_height;
    const double alpha_value = alpha.value_or(std::atan2(a0, b0));
    const double radius_value = radius.value_or(std::hypot(a0, b0));
    scene.block.half_width = radius_value * std::sin(alpha_value);
    scene.block.half_height = radius_value * std::cos(alpha_value);
  }
  if (!config.suite) set_pulse(scene.ground_motion, amplitude, period);
  return scene;
}

StudySampler::StudySampler(const StudyConfig& config)
    : config_(config), sampler_(sampling_plan(config)) {}

StudySample StudySampler::draw(std::int64_t index, bool with_measures) {
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  const IntensityMeasure& measure = config_.intensity;
  StudySample sample;
  sample.index = index;
  sample.level = static_cast<std::uint32_t>(index / config_.samples_per_level);
  sample.values = sampler_.draw(static_cast<std::uint64_t>(index));
  double direction = 1.0;
  for (std::size_t k = 0; k < config_.inputs.size(); ++k) {
    if (config_.inputs[k].input != StudyInput::direction) continue;
    sample.values[k] = sign_of(sample.values[k]);
    direction = sample.values[k];
  }
  // The unit motion first: its measure gives the scale.
  sample.scene = apply_sample(config_, sample.values, 1.0);
  if (measure.surface()) {  // the cell's period, before the motion is measured
    sample.im2 = measure.periods[sample.level % measure.periods.size()];
    set_pulse(sample.scene.ground_motion, 1.0, &sample.im2);
  }
  const double alpha = block_alpha(sample.scene);
  double pga = nan, pgv = nan, sa = nan;
  const SuiteRecord* record = nullptr;
  if (config_.suite) {
    const auto member = static_cast<std::uint32_t>(index % config_.samples_per_level);
    sample.record =
        static_cast<std::int64_t>(config_.suite->record_of(member, config_.samples_per_level));
    record = &config_.suite->records[static_cast<std::size_t>(sample.record)];
    pga = record->measures.pga_g;
    pgv = record->measures.pgv;
    if (!record->measures.sa_g.empty()) sa = record->measures.sa_g.front();
  } else if (measure.type != ImType::pulse_amplitude || with_measures) {
    const GroundMotionPieces unit(sample.scene.ground_motion, sample.scene.g);
    pga = peak_ground_acceleration_g(unit);
    pgv = peak_ground_velocity(unit, sample.scene.g);
    if (measure.type == ImType::sa)
      sa = spectral_acceleration_g(unit, measure.period, measure.damping);
  }
  const double unit = unit_measure(measure, pga, pgv, sa, alpha);
  if (measure.cloud) {
    sample.scale = measure.scale;
    sample.im = unit * measure.scale;
  } else {
    sample.im = measure.levels.at(measure.first_level(sample.level));
    sample.scale = sample.im / unit;
  }
  const double signed_scale = direction * sample.scale;
  if (record) {
    sample.scene.ground_motion = RecordedMotion{record->file, signed_scale, record->record};
    if (record->vertical) {
      sample.scene.vertical_motion =
          RecordedMotion{record->vertical_file, sample.scale, record->vertical};
    }
  } else {
    set_pulse(sample.scene.ground_motion, signed_scale, nullptr);
  }
  sample.pga_g = pga * sample.scale;
  sample.pgv_m_s = pgv * sample.scale;
  return sample;
}

}  // namespace blockfrag
