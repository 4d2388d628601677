// The key tables (mpi_driver/config/field_table.hpp) of a spectrum's own keys: its pulse family, an
// axis given as a range, a block given as alpha and R, the bisection and the run's settings (the
// minimum's refinement is study_fields::minimum_overturning). docs/spectra.md's Domains table names
// each key by its object's path ("pulse.cycles", "frequency_ratio.count").
#pragma once

#include <vector>

#include "engine/scene/parameter_domains.hpp"
#include "mpi_driver/config/enum_names.hpp"
#include "mpi_driver/config/field_table.hpp"
#include "mpi_driver/config/spectrum_config.hpp"

namespace blockfrag {

// A spectrum's "pulse": the family, and its shape's key.
struct PulseFamily {
  SpectrumPulse pulse = SpectrumPulse::cosine;
  double cycles = 1.0;
  int n = 1;
};

inline constexpr EnumNames<SpectrumPulse, 7> spectrum_pulse_names{
    {SpectrumPulse::cosine, SpectrumPulse::sine, SpectrumPulse::rectangular,
     SpectrumPulse::makris_a, SpectrumPulse::makris_b, SpectrumPulse::makris_c,
     SpectrumPulse::ricker},
    {"cosine_pulse", "sine_pulse", "rectangular_pulse", "makris_a", "makris_b", "makris_c",
     "ricker"}};

// An axis given as {"values": [...]}, or as {"from", "to", "count", "spacing"}.
struct AxisValues {
  std::vector<double> values;
};
struct AxisRange {
  double from = 0.0;
  double to = 0.0;
  long count = 0;
  bool log = false;
};

inline constexpr EnumNames<bool, 2> axis_spacing_names{{false, true}, {"linear", "log"}};

// A block given as alpha and R, which the spectrum's reader turns into a scene's half_width and
// half_height.
struct BlockShape {
  double alpha = 0.0;
  double R = 0.0;
  double mass = 1.0;
};

namespace spectrum_fields {

using enum Presence;

// The family's "type" selects its shape's key: a cosine or sine pulse's cycles, makris_c's n.
inline constexpr Field<PulseFamily> pulse_type[] = {
    {"type", choice_member<&PulseFamily::pulse, spectrum_pulse_names>(), nullptr, required}};
inline constexpr Field<PulseFamily> periodic_family[] = {
    {"cycles", &PulseFamily::cycles, &domain::pulse_cycles}};
inline constexpr Field<PulseFamily> makris_c_family[] = {
    {"n", &PulseFamily::n, &domain::makris_c_n}};

// The frequency ratio's axis has at least one value, the amplitude ratio's two (its fit's).
inline constexpr Domain frequency_value_count{1.0, kMaxSpectrumAxis, true, true, ""};
inline constexpr Domain amplitude_value_count{2.0, kMaxSpectrumAxis, true, true, ""};
inline constexpr Field<AxisValues> frequency_values[] = {
    {"values", IncreasingMember<AxisValues>{&AxisValues::values, {&frequency_value_count, "value"}},
     &domain::spectrum_ratio, required}};
inline constexpr Field<AxisValues> amplitude_values[] = {
    {"values", IncreasingMember<AxisValues>{&AxisValues::values, {&amplitude_value_count, "value"}},
     &domain::spectrum_ratio, required}};
inline constexpr Field<AxisRange> axis_range[] = {
    {"from", &AxisRange::from, &domain::spectrum_ratio, required},
    {"to", &AxisRange::to, &domain::spectrum_ratio, required},
    {"count", &AxisRange::count, &domain::spectrum_axis_count, required},
    {"spacing", choice_member<&AxisRange::log, axis_spacing_names>(), nullptr}};

inline constexpr Field<BlockShape> block_shape[] = {
    {"alpha", &BlockShape::alpha, &domain::alpha, required},
    {"R", &BlockShape::R, &domain::block_length, required},
    {"mass", &BlockShape::mass, &domain::mass}};

// The "bisection" object, and the spectrum's own keys (read before and after "output": three
// tables keep the order its errors are reported in).
inline constexpr Field<SpectrumConfig> bisection[] = {
    {"tolerance", &SpectrumConfig::bisection_tolerance, &domain::bisection_tolerance},
    {"max_iterations", &SpectrumConfig::max_iterations, &domain::bisection_iterations}};
inline constexpr Field<SpectrumConfig> settle[] = {
    {"settle_allowance_tau", &SpectrumConfig::settle_allowance_tau, &domain::settle_allowance_tau}};
inline constexpr Field<SpectrumConfig> output[] = {{"output", &SpectrumConfig::output, nullptr}};
inline constexpr Field<SpectrumConfig> checkpoint[] = {{"checkpoint_interval_s",
                                                        &SpectrumConfig::checkpoint_interval_s,
                                                        &domain::checkpoint_interval_s}};

}  // namespace spectrum_fields

// The tables above and the minimum's refinement under the prefix docs/spectra.md's Domains table
// names them with ("pulse.", "frequency_ratio.").
std::vector<KeyTable> spectrum_key_tables();

}  // namespace blockfrag
