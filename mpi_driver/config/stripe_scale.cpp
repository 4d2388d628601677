#include "mpi_driver/config/stripe_scale.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <type_traits>

#include "engine/motion/ground_motion.hpp"
#include "engine/motion/intensity_measures.hpp"
#include "engine/scene/block_geometry.hpp"
#include "engine/scene/parameter_domains.hpp"

namespace blockfrag {
namespace {

// A number for a message, to three significant digits.
std::string three_digits(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

// The largest tan(alpha) a sample's block can have: the base block's, or the extreme of the
// sampled geometry's supports (alpha, or a / b from half_width and half_height).
double largest_tan_alpha(const StudyConfig& config) {
  double a = config.base_scene.block.half_width, b = config.base_scene.block.half_height;
  std::optional<double> alpha;
  for (const auto& spec : config.inputs) {
    const auto [low, high] = support_of(spec.distribution);
    if (spec.input == StudyInput::alpha) alpha = high;
    if (spec.input == StudyInput::half_width) a = high;
    if (spec.input == StudyInput::half_height) b = low;
  }
  if (alpha) return std::tan(*alpha);
  const bool fixed_shape = config.base_scene.polygon || config.base_scene.seat;
  return fixed_shape ? std::tan(block_alpha(config.base_scene)) : a / b;
}

// A record's measure as recorded in the study's measure; the dimensionless one at the largest
// tan(alpha) a sample's block can have, whose stripes need the largest scale.
double record_unit_measure(const IntensityMeasure& measure, const SuiteRecord& record,
                           double tan_alpha) {
  double unit = record.measures.pga_g;
  if (measure.type == ImType::pgv) unit = record.measures.pgv;
  if (measure.type == ImType::sa) unit = record.measures.sa_g.front();
  if (measure.type == ImType::pga_over_g_tan_alpha) unit /= tan_alpha;
  return unit;
}

// A pulse's measure in the study's measure at unit amplitude (1 g, or 1 m/s for the
// Mavroeidis-Papageorgiou pulse, which a velocity defines), as each sample measures its own; NaN
// where it differs between samples (a sampled period) or cannot be measured.
double pulse_unit_measure(const StudyConfig& config) {
  const IntensityMeasure& measure = config.intensity;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  if (measure.type == ImType::pulse_amplitude) return 1.0;
  for (const auto& spec : config.inputs) {
    if (spec.input == StudyInput::period) return nan;
  }
  GroundMotion motion = config.base_scene.ground_motion;
  std::visit(
      [](auto& pulse) {
        using T = std::decay_t<decltype(pulse)>;
        if constexpr (std::is_same_v<T, MavroeidisPapageorgiouPulse>) {
          pulse.velocity_amplitude = 1.0;
        } else if constexpr (requires { pulse.amplitude_g; }) {
          pulse.amplitude_g = 1.0;
        }
      },
      motion);
  try {
    const GroundMotionPieces unit(motion, config.base_scene.g);
    switch (measure.type) {
      case ImType::pga: return peak_ground_acceleration_g(unit);
      case ImType::pga_over_g_tan_alpha:
        return peak_ground_acceleration_g(unit) / largest_tan_alpha(config);
      case ImType::pgv: return peak_ground_velocity(unit, config.base_scene.g);
      case ImType::sa: return spectral_acceleration_g(unit, measure.period, measure.damping);
      case ImType::pulse_amplitude: break;
    }
  } catch (const InvalidInput&) {  // every sample's scene is refused alike
  }
  return nan;
}

}  // namespace

void measure_suite(StudyConfig& config, ConfigErrors& errors, bool single_record) {
  const IntensityMeasure& measure = config.intensity;
  const std::vector<double> periods =
      measure.type == ImType::sa ? std::vector<double>{measure.period} : std::vector<double>{};
  const double tan_alpha = largest_tan_alpha(config);
  for (std::size_t k = 0; k < config.suite->records.size(); ++k) {
    SuiteRecord& record = config.suite->records[k];
    const JsonPointer where = single_record ? JsonPointer("/scene/ground_motion/file")
                                            : JsonPointer("/scene/ground_motion/records") / k;
    try {
      record.measures =
          intensity_measures(*record.record, periods, measure.damping, config.base_scene.g);
    } catch (const InvalidInput& refused) {  // an Sa period the record cannot be stepped at
      errors.add(JsonPointer("/intensity_measure/period"), record.file + ": " + refused.what());
      return;
    }
    const double unit = record_unit_measure(measure, record, tan_alpha);
    if (!(unit > 0)) {
      errors.add(where, record.file + ": its " + im_label(measure) +
                            " is 0, so no scale brings it to an intensity");
      continue;
    }
    const double top = measure.cloud ? measure.scale * unit : measure.levels.back();
    if (!measure.cloud && top / unit > kMaxRecordScale) {
      errors.add(where, record.file + ": reaching the level " + format_number(top) + " " +
                            im_unit(measure.type) + " needs a scale of " +
                            three_digits(top / unit) + ", more than " +
                            format_number(kMaxRecordScale) + " (its " + im_label(measure) + " is " +
                            format_number(unit) + " " + im_unit(measure.type) + ")");
    }
  }
}

StripeCap stripe_cap(const StudyConfig& config) {
  const IntensityMeasure& measure = config.intensity;
  StripeCap cap{largest_level(measure.type), "the measure's largest level"};
  if (!config.suite) {
    // A sample scaled past its pulse's amplitude domain is refused (status 2), as at a fixed level.
    const bool velocity =
        std::holds_alternative<MavroeidisPapageorgiouPulse>(config.base_scene.ground_motion);
    const Domain& amplitude = velocity ? domain::velocity_amplitude : domain::amplitude_g;
    const double unit = pulse_unit_measure(config);
    double level = amplitude.high * unit;
    // A margin for the dimensionless measure, whose tan(alpha) each sample rounds on its own.
    if (measure.type == ImType::pga_over_g_tan_alpha) level *= 1.0 - 1e-12;
    while (level / unit > amplitude.high) level = std::nextafter(level, 0.0);
    if (level < cap.level) {
      cap.level = level;
      cap.reason = format_number(level) + " " + im_unit(measure.type) +
                   ", the largest level within the pulse's " +
                   (velocity ? "velocity_amplitude" : "amplitude_g") + " domain (at most " +
                   format_number(amplitude.high) + " " + amplitude.unit + "; its " +
                   im_label(measure) + " is " + format_number(unit) + " " + im_unit(measure.type) +
                   " at 1 " + amplitude.unit + ")";
    }
    return cap;
  }
  const double tan_alpha = largest_tan_alpha(config);
  for (const SuiteRecord& record : config.suite->records) {
    const double unit = record_unit_measure(measure, record, tan_alpha);
    double level = kMaxRecordScale * unit;
    if (!(level < cap.level)) continue;
    // The refusal of a fixed level divides by the unit: the cap must pass that test exactly.
    while (level / unit > kMaxRecordScale) level = std::nextafter(level, 0.0);
    cap.level = level;
    cap.reason = format_number(level) + " " + im_unit(measure.type) +
                 ", the largest level a scale of " + format_number(kMaxRecordScale) + " gives " +
                 record.file + " (its " + im_label(measure) + " is " + format_number(unit) + " " +
                 im_unit(measure.type) + ")";
  }
  return cap;
}

}  // namespace blockfrag
