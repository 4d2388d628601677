#include "mpi_driver/config/pulse_json.hpp"

#include <string>

#include "engine/number_text.hpp"
#include "engine/tolerances.hpp"

namespace blockfrag {

namespace {

using nlohmann::json;

// amplitude_g and period: what every acceleration pulse has.
template <class Pulse>
Pulse read_amplitude_and_period(ObjectReader& reader) {
  Pulse pulse;
  pulse.amplitude_g = reader.required_number("amplitude_g", Range::of(domain::amplitude_g))
                          .value_or(pulse.amplitude_g);
  pulse.period =
      reader.required_number("period", Range::of(domain::pulse_period)).value_or(pulse.period);
  return pulse;
}

MakrisPulseC read_makris_c(ObjectReader& reader) {
  auto pulse = read_amplitude_and_period<MakrisPulseC>(reader);
  pulse.n =
      static_cast<int>(reader.required_integer("n", Range::closed(1.0, 1000.0)).value_or(pulse.n));
  return pulse;
}

RickerWavelet read_ricker(ObjectReader& reader) {
  auto pulse = read_amplitude_and_period<RickerWavelet>(reader);
  pulse.t0 = reader.number("t0", Range::of(domain::motion_time));
  return pulse;
}

MavroeidisPapageorgiouPulse read_mavroeidis_papageorgiou(ObjectReader& reader) {
  MavroeidisPapageorgiouPulse pulse;
  pulse.velocity_amplitude =
      reader.required_number("velocity_amplitude", Range::of(domain::velocity_amplitude))
          .value_or(pulse.velocity_amplitude);
  const auto period = reader.required_number("period", Range::of(domain::pulse_period));
  const auto gamma = reader.required_number("gamma", Range::of(domain::mp_gamma));
  pulse.period = period.value_or(pulse.period);
  pulse.gamma = gamma.value_or(pulse.gamma);
  pulse.phase = reader.number_or("phase", pulse.phase, Range::of(domain::mp_phase));
  pulse.t0 = reader.number("t0", Range::of(domain::motion_time));
  if (pulse.t0 && period && gamma && *pulse.t0 < (1.0 - kGridRounding) * pulse.half_width()) {
    reader.add_error("t0", "must be >= gamma period / 2 = " + format_number(pulse.half_width()) +
                               " (the pulse starts at t >= 0) (got " + format_number(*pulse.t0) +
                               ")");
  }
  return pulse;
}

}  // namespace

std::optional<GroundMotion> read_near_fault_pulse(std::string_view type, ObjectReader& reader) {
  if (type == makris_a_type) return read_amplitude_and_period<MakrisPulseA>(reader);
  if (type == makris_b_type) return read_amplitude_and_period<MakrisPulseB>(reader);
  if (type == makris_c_type) return read_makris_c(reader);
  if (type == ricker_type) return read_ricker(reader);
  if (type == mavroeidis_papageorgiou_type) return read_mavroeidis_papageorgiou(reader);
  return std::nullopt;
}

json pulse_to_json(const MakrisPulseA& pulse) {
  return {{"type", makris_a_type}, {"amplitude_g", pulse.amplitude_g}, {"period", pulse.period}};
}

json pulse_to_json(const MakrisPulseB& pulse) {
  return {{"type", makris_b_type}, {"amplitude_g", pulse.amplitude_g}, {"period", pulse.period}};
}

json pulse_to_json(const MakrisPulseC& pulse) {
  return {{"type", makris_c_type},
          {"amplitude_g", pulse.amplitude_g},
          {"period", pulse.period},
          {"n", pulse.n}};
}

json pulse_to_json(const RickerWavelet& pulse) {
  return {{"type", ricker_type},
          {"amplitude_g", pulse.amplitude_g},
          {"period", pulse.period},
          {"t0", pulse.center()}};
}

json pulse_to_json(const MavroeidisPapageorgiouPulse& pulse) {
  return {{"type", mavroeidis_papageorgiou_type},
          {"velocity_amplitude", pulse.velocity_amplitude},
          {"period", pulse.period},
          {"gamma", pulse.gamma},
          {"phase", pulse.phase},
          {"t0", pulse.center()}};
}

}  // namespace blockfrag
