// The scene's key tables (mpi_driver/config/field_table.hpp): the keys scene_json.cpp,
// ground_motion_json.cpp, dam_json.cpp and reservoir_json.cpp read and write through a table, and
// the JSON names of the scene's enums. docs/scenes.md's Domains table names each key by its
// object's prefix ("block.half_width"; the ground motions' keys bare).
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "engine/scene/parameter_domains.hpp"
#include "engine/scene/scene.hpp"
#include "mpi_driver/config/enum_names.hpp"
#include "mpi_driver/config/field_table.hpp"

namespace blockfrag {

inline constexpr EnumNames<Method, 4> method_names{
    {Method::adaptive, Method::rk4, Method::gsl_rkf45, Method::gsl_rk8pd},
    {"adaptive", "rk4", "gsl_rkf45", "gsl_rk8pd"}};
inline constexpr EnumNames<Hydrodynamic, 2> hydrodynamic_names{
    {Hydrodynamic::none, Hydrodynamic::westergaard}, {"none", "westergaard"}};
inline constexpr EnumNames<UpliftRule, 4> uplift_rule_names{
    {UpliftRule::none, UpliftRule::unchanged, UpliftRule::zero_in_gap,
     UpliftRule::full_head_in_gap},
    {"none", "unchanged", "zero_in_gap", "full_head_in_gap"}};

namespace scene_fields {

using enum Presence;

inline constexpr Field<RectangularBlock> rectangle[] = {
    {"half_width", &RectangularBlock::half_width, &domain::block_length, required},
    {"half_height", &RectangularBlock::half_height, &domain::block_length, required},
    {"mass", &RectangularBlock::mass, &domain::mass}};
// A polygon's vertices are read by mpi_driver/config/polygon_json.hpp.
inline constexpr Field<PolygonBlock> polygon_block[] = {
    {"mass", &PolygonBlock::mass, &domain::mass}};
// "rocking_restitution", a number or "housner", is read by scene_json.cpp.
inline constexpr Field<Contact> contact[] = {
    {"friction", &Contact::friction, &domain::friction, required},
    {"restitution", &Contact::restitution, &domain::restitution, required}};
// The scene's own numbers: without duration the run settles, at most max_duration.
inline constexpr Field<Scene> run[] = {{"duration", &Scene::duration, &domain::duration},
                                       {"max_duration", &Scene::max_duration, &domain::duration},
                                       {"g", &Scene::g, &domain::g}};
inline constexpr Field<InitialState> initial[] = {
    {"theta", &InitialState::theta, &domain::initial_theta},
    {"omega", &InitialState::omega, &domain::initial_omega, optional, Written::unless_default}};
// The solver's "method" selects the step's key: rk4's dt, or the others' tolerance.
inline constexpr Field<SolverSettings> solver_method[] = {
    {"method", choice_member<&SolverSettings::method, method_names>(), nullptr}};
inline constexpr Field<SolverSettings> rk4_step[] = {
    {"dt", &SolverSettings::dt, &domain::rk4_step}};
inline constexpr Field<SolverSettings> step_control[] = {
    {"tolerance", &SolverSettings::tolerance, &domain::tolerance}};
inline constexpr Field<SolverSettings> budgets[] = {
    {"max_steps", &SolverSettings::max_steps, &domain::max_steps},
    {"max_events", &SolverSettings::max_events, &domain::max_events}};
// A dam's stiffness: its period, or its height and modulus.
inline constexpr Field<DamPeriod> dam_period[] = {
    {"period", &DamPeriod::period, &domain::dam_period, required}};
inline constexpr Field<DamSize> dam_size[] = {
    {"height", &DamSize::height, &domain::dam_height, required},
    {"elastic_modulus", &DamSize::elastic_modulus, &domain::elastic_modulus, required}};
// Fenves & Chopra's keys came after the dam: written only when they change it.
inline constexpr Field<DamCrest> dam[] = {
    {"damping", &DamCrest::damping, &domain::dam_damping},
    {"participation", &DamCrest::participation, &domain::participation},
    {"reservoir_period_ratio", &DamCrest::reservoir_period_ratio, &domain::dam_period_ratio,
     optional, Written::unless_default},
    {"reservoir_damping", &DamCrest::reservoir_damping, &domain::dam_added_damping, optional,
     Written::unless_default},
    {"foundation_period_ratio", &DamCrest::foundation_period_ratio, &domain::dam_period_ratio,
     optional, Written::unless_default},
    {"foundation_damping", &DamCrest::foundation_damping, &domain::dam_added_damping, optional,
     Written::unless_default}};
inline constexpr Field<Reservoir> reservoir[] = {
    {"level", &Reservoir::level, &domain::reservoir_level, required},
    {"depth", &Reservoir::depth, &domain::reservoir_depth},
    {"density", &Reservoir::density, &domain::water_density},
    {"hydrodynamic", choice_member<&Reservoir::hydrodynamic, hydrodynamic_names>(), nullptr},
    {"uplift", choice_member<&Reservoir::uplift, uplift_rule_names>(), nullptr},
    {"uplift_area_factor", &Reservoir::uplift_area_factor, &domain::uplift_area_factor}};

}  // namespace scene_fields

// A ground motion's "type" and its keys besides "type", one specialisation per alternative of
// GroundMotion.
template <class Motion>
struct MotionKeys;

template <>
struct MotionKeys<NoMotion> {
  static constexpr std::string_view type = "none";
  static constexpr std::array<Field<NoMotion>, 0> fields{};
};

template <class Pulse>
struct PeriodicPulseKeys {
  static constexpr Field<Pulse> fields[] = {
      {"amplitude_g", &Pulse::amplitude_g, &domain::amplitude_g, Presence::required},
      {"period", &Pulse::period, &domain::pulse_period, Presence::required},
      {"cycles", &Pulse::cycles, &domain::pulse_cycles}};
};
template <>
struct MotionKeys<CosinePulse> : PeriodicPulseKeys<CosinePulse> {
  static constexpr std::string_view type = "cosine_pulse";
};
template <>
struct MotionKeys<SinePulse> : PeriodicPulseKeys<SinePulse> {
  static constexpr std::string_view type = "sine_pulse";
};

template <>
struct MotionKeys<RectangularPulse> {
  static constexpr std::string_view type = "rectangular_pulse";
  static constexpr Field<RectangularPulse> fields[] = {
      {"amplitude_g", &RectangularPulse::amplitude_g, &domain::amplitude_g, Presence::required},
      {"duration", &RectangularPulse::duration, &domain::pulse_duration, Presence::required}};
};

// A record's file and scale, the canonical form's; its "target_pga_g" (record_target below), the
// peak the scale is resolved from instead, is not written.
template <>
struct MotionKeys<RecordedMotion> {
  static constexpr std::string_view type = "record";
  static constexpr Field<RecordedMotion> fields[] = {
      {"file", &RecordedMotion::file, nullptr, Presence::required},
      {"scale", &RecordedMotion::scale, &domain::record_scale}};
};

// A record scaled to a peak ground acceleration instead of by a scale.
struct RecordTarget {
  std::optional<double> target_pga_g;
};

namespace scene_fields {
inline constexpr Field<RecordTarget> record_target[] = {
    {"target_pga_g", &RecordTarget::target_pga_g, &domain::target_pga_g}};
}  // namespace scene_fields

template <class Pulse>
struct AccelerationPulseKeys {
  static constexpr Field<Pulse> fields[] = {
      {"amplitude_g", &Pulse::amplitude_g, &domain::amplitude_g, Presence::required},
      {"period", &Pulse::period, &domain::pulse_period, Presence::required}};
};
template <>
struct MotionKeys<MakrisPulseA> : AccelerationPulseKeys<MakrisPulseA> {
  static constexpr std::string_view type = "makris_a";
};
template <>
struct MotionKeys<MakrisPulseB> : AccelerationPulseKeys<MakrisPulseB> {
  static constexpr std::string_view type = "makris_b";
};

template <>
struct MotionKeys<MakrisPulseC> {
  static constexpr std::string_view type = "makris_c";
  static constexpr Field<MakrisPulseC> fields[] = {
      {"amplitude_g", &MakrisPulseC::amplitude_g, &domain::amplitude_g, Presence::required},
      {"period", &MakrisPulseC::period, &domain::pulse_period, Presence::required},
      {"n", &MakrisPulseC::n, &domain::makris_c_n, Presence::required}};
};

// The centres are written resolved, so the canonical scene names the same motion after any change
// of their defaults.
template <>
struct MotionKeys<RickerWavelet> {
  static constexpr std::string_view type = "ricker";
  static constexpr Field<RickerWavelet> fields[] = {
      {"amplitude_g", &RickerWavelet::amplitude_g, &domain::amplitude_g, Presence::required},
      {"period", &RickerWavelet::period, &domain::pulse_period, Presence::required},
      {"t0", &RickerWavelet::t0, &domain::motion_time, Presence::optional, Written::always,
       [](const RickerWavelet& pulse) { return pulse.center(); }}};
};

// t0 must also leave the pulse's start at t >= 0: ground_motion_json.cpp checks it.
template <>
struct MotionKeys<MavroeidisPapageorgiouPulse> {
  using Pulse = MavroeidisPapageorgiouPulse;
  static constexpr std::string_view type = "mavroeidis_papageorgiou";
  static constexpr Field<Pulse> fields[] = {
      {"velocity_amplitude", &Pulse::velocity_amplitude, &domain::velocity_amplitude,
       Presence::required},
      {"period", &Pulse::period, &domain::pulse_period, Presence::required},
      {"gamma", &Pulse::gamma, &domain::mp_gamma, Presence::required},
      {"phase", &Pulse::phase, &domain::mp_phase},
      {"t0", &Pulse::t0, &domain::motion_time, Presence::optional, Written::always,
       [](const Pulse& pulse) { return pulse.center(); }}};
};

// Every table above, and a study's own (mpi_driver/config/study_fields.hpp), under the prefix
// docs/scenes.md's Domains table names its keys with ("block.", "" for the scene's own keys, the
// ground motions' and the study's).
std::vector<KeyTable> scene_key_tables();

// The ground motions' "type" names, in GroundMotion's order.
std::vector<std::string_view> ground_motion_types();

}  // namespace blockfrag
