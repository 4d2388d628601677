// The key tables (mpi_driver/config/field_table.hpp) of a study's own settings and a spectrum's
// minimum refinement (spectrum_fields.hpp has its other keys), and the JSON names of the study's
// enums. docs/studies.md's Domains table names each key by its object's path
// ("intensity_measure.period"; a limit state's keys as "limit_states[].threshold_m").
#pragma once

#include "engine/scene/parameter_domains.hpp"
#include "mpi_driver/config/enum_names.hpp"
#include "mpi_driver/config/field_table.hpp"
#include "mpi_driver/config/minimum_overturning_json.hpp"
#include "mpi_driver/config/study_config.hpp"

namespace blockfrag {

inline constexpr EnumNames<ImType, 5> im_type_names{
    {ImType::pulse_amplitude, ImType::pga, ImType::pgv, ImType::sa, ImType::pga_over_g_tan_alpha},
    {"pulse_amplitude", "pga", "pgv", "sa", "pga_over_g_tan_alpha"}};
// "scaling": stripes scale every motion to a level; "none" leaves a cloud of motions as they are.
inline constexpr EnumNames<bool, 2> scaling_names{{false, true}, {"stripes", "none"}};
inline constexpr EnumNames<LimitStateKind, 4> limit_state_kind_names{
    {LimitStateKind::overturning, LimitStateKind::max_rotation, LimitStateKind::residual_slide,
     LimitStateKind::post_earthquake_unstable},
    {"overturning", "max_rotation", "residual_slide", "post_earthquake_unstable"}};
// A study's "design", and an adaptive design's "base" (its default first).
inline constexpr EnumNames<Design, 2> design_names{{Design::monte_carlo, Design::latin_hypercube},
                                                   {"monte_carlo", "latin_hypercube"}};
inline constexpr EnumNames<Design, 2> adaptive_base_names{
    {Design::latin_hypercube, Design::monte_carlo}, {"latin_hypercube", "monte_carlo"}};

// A study's direction: a random sign, or fixed at `value`.
struct DirectionLaw {
  bool fixed = false;
  double value = 1.0;
};
inline constexpr EnumNames<bool, 2> direction_law_names{{false, true}, {"random_sign", "fixed"}};

// A study's levels (an intensity measure's, or a surface's second axis's) given as a list, or as a
// range, which the reader turns into a list.
struct LevelList {
  std::vector<double> levels;
};
struct LevelRange {
  double from = 0.0;
  double to = 0.0;
  long count = 0;
};

namespace study_fields {

using enum Presence;

// What changes no sample's result (output, checkpoints, the failures allowed) is not hashed: the
// study's reader takes those keys out of the hashed form.
inline constexpr Field<StudyConfig> run[] = {
    {"checkpoint_interval_s", &StudyConfig::checkpoint_interval_s, &domain::checkpoint_interval_s},
    {"allowed_failed_fraction", &StudyConfig::allowed_failed_fraction,
     &domain::allowed_failed_fraction},
    {"bootstrap_resamples", &StudyConfig::bootstrap_resamples, &domain::bootstrap_resamples}};
// The samples of each level and the seed: two tables keep the order the study's errors are
// reported in.
inline constexpr Field<StudyConfig> samples[] = {
    {"samples_per_level", &StudyConfig::samples_per_level, &domain::samples_per_level, required}};
inline constexpr Field<StudyConfig> seed[] = {
    {"seed", &StudyConfig::seed, &domain::seed, required}};

// The study's output file (without it, STUDY.h5 in the working folder).
inline constexpr Field<StudyConfig> output[] = {{"output", &StudyConfig::output, nullptr}};

// A direction's "distribution": a random sign (drawn as Uniform{-1, 1}), which has no other key,
// or a fixed sign, {"distribution": "fixed", "value": 1 or -1}.
inline constexpr Field<DirectionLaw> direction_law[] = {
    {"distribution", choice_member<&DirectionLaw::fixed, direction_law_names>(), nullptr,
     required}};
inline constexpr Field<DirectionLaw> fixed_direction[] = {
    {"value", SignMember<DirectionLaw>{&DirectionLaw::value}, nullptr, required}};

// "type" (its default depends on the ground motion: the reader sets it first), then the keys it
// selects; "scaling", then a cloud's, or the levels below. A surface's "second" type is read by
// intensity_measure.cpp.
inline constexpr Field<IntensityMeasure> measure_type[] = {
    {"type", choice_member<&IntensityMeasure::type, im_type_names>(), nullptr}};
inline constexpr Field<IntensityMeasure> sa[] = {
    {"period", &IntensityMeasure::period, &domain::sa_period, required},
    {"damping", &IntensityMeasure::damping, &domain::dam_damping}};
inline constexpr Field<IntensityMeasure> scaling[] = {
    {"scaling", choice_member<&IntensityMeasure::cloud, scaling_names>(), nullptr}};
inline constexpr Field<IntensityMeasure> cloud[] = {
    {"scale", &IntensityMeasure::scale, &domain::cloud_scale}};
// The levels, given as a list or as a grid of "count" evenly spaced from "from" to "to", one table
// per domain of the levels: in g (or dimensionless), in m/s for "pgv", and a surface's second
// axis's pulse periods in s.
inline constexpr Domain level_list_count{1.0, domain::kMaxIntensityLevels, true, true, ""};
template <const Domain& level>
inline constexpr Field<LevelList> level_list[1] = {
    {"levels", IncreasingMember<LevelList>{&LevelList::levels, {&level_list_count, "level"}},
     &level, required}};
template <const Domain& level>
inline constexpr Field<LevelRange> level_range[3] = {
    {"from", &LevelRange::from, &level, required},
    {"to", &LevelRange::to, &level, required},
    {"count", &LevelRange::count, &domain::intensity_level_count, required}};

// A limit state's name, then its "type", which selects the threshold's key, and (but for
// overturning) whether an overturned block exceeds it.
inline constexpr Field<LimitState> limit_state_name[] = {
    {"name", &LimitState::name, nullptr, required}};
inline constexpr Field<LimitState> overturned_exceeds[] = {
    {"overturned_exceeds", &LimitState::overturned_exceeds, nullptr}};
inline constexpr Field<LimitState> limit_state_type[] = {
    {"type", choice_member<&LimitState::kind, limit_state_kind_names>(), nullptr, required}};
inline constexpr Field<LimitState> max_rotation[] = {
    {"theta_over_alpha", &LimitState::threshold, &domain::limit_state_threshold, required}};
inline constexpr Field<LimitState> residual_slide[] = {
    {"threshold_m", &LimitState::threshold, &domain::limit_state_threshold, required}};
// Its threshold defaults to 1: the reader sets it first.
inline constexpr Field<LimitState> post_earthquake_unstable[] = {
    {"threshold", &LimitState::threshold, &domain::limit_state_threshold}};

// "design": {"adaptive": {...}}; its "limit_state" is a limit state's name (none: the first's).
inline constexpr Field<AdaptiveDesign> adaptive_base[] = {
    {"base", choice_member<&AdaptiveDesign::base, adaptive_base_names>(), nullptr}};
inline constexpr Field<AdaptiveDesign> adaptive[] = {
    {"limit_state", &AdaptiveDesign::limit_state, nullptr},
    {"target_relative_width", &AdaptiveDesign::target_relative_width,
     &domain::target_relative_width},
    {"pair_probability", &AdaptiveDesign::pair_probability, &domain::pair_probability},
    {"max_samples", &AdaptiveDesign::max_samples, &domain::adaptive_samples, required}};

// A record suite's entry given as an object: its record's file and its vertical companion's (read
// by record_suite.cpp before the weight), then its weight.
inline constexpr Field<SuiteRecord> suite_record_files[] = {
    {"file", &SuiteRecord::file, nullptr, required},
    {"vertical", &SuiteRecord::vertical_file, nullptr, optional, Written::unless_default}};
inline constexpr Field<SuiteRecord> suite_record[] = {
    {"weight", &SuiteRecord::weight, &domain::record_weight}};

// A spectrum's "minimum_overturning".
inline constexpr Field<MinimumOverturningSettings> minimum_overturning[] = {
    {"tolerance", &MinimumOverturningSettings::tolerance, &domain::minimum_tolerance},
    {"resolution", &MinimumOverturningSettings::resolution, &domain::minimum_resolution},
    {"near_overturning", &MinimumOverturningSettings::near_overturning, &domain::near_overturning},
    {"max_midpoints", &MinimumOverturningSettings::max_midpoints, &domain::minimum_midpoints}};

}  // namespace study_fields

// The tables of a study's keys above and its distributions' (distribution_json.hpp), under the
// prefix docs/studies.md's Domains table names them with ("intensity_measure.", "inputs.*.").
std::vector<KeyTable> study_key_tables();

}  // namespace blockfrag
