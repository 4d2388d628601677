#include "mpi_driver/config/study_fields.hpp"

#include "mpi_driver/config/distribution_json.hpp"

namespace blockfrag {

std::vector<KeyTable> study_key_tables() {
  return {
      {"", describe_fields<StudyConfig>(study_fields::run)},
      {"", describe_fields<StudyConfig>(study_fields::samples)},
      {"", describe_fields<StudyConfig>(study_fields::seed)},
      {"", describe_fields<StudyConfig>(study_fields::output)},
      {"inputs.direction.", describe_fields<DirectionLaw>(study_fields::direction_law)},
      {"inputs.direction.", describe_fields<DirectionLaw>(study_fields::fixed_direction)},
      {"inputs.*.", describe_alternatives<Distribution, DistributionKeys>()},
      {"intensity_measure.", describe_fields<IntensityMeasure>(study_fields::measure_type)},
      {"intensity_measure.", describe_fields<IntensityMeasure>(study_fields::sa)},
      {"intensity_measure.", describe_fields<IntensityMeasure>(study_fields::scaling)},
      {"intensity_measure.", describe_fields<IntensityMeasure>(study_fields::cloud)},
      {"intensity_measure.",
       describe_fields<LevelList>(study_fields::level_list<domain::intensity_g>)},
      {"intensity_measure.",
       describe_fields<LevelList>(study_fields::level_list<domain::pgv_level>)},
      {"intensity_measure.second.",
       describe_fields<LevelList>(study_fields::level_list<domain::pulse_period>)},
      {"intensity_measure.",
       describe_fields<LevelRange>(study_fields::level_range<domain::intensity_g>)},
      {"intensity_measure.",
       describe_fields<LevelRange>(study_fields::level_range<domain::pgv_level>)},
      {"intensity_measure.second.",
       describe_fields<LevelRange>(study_fields::level_range<domain::pulse_period>)},
      {"limit_states[].", describe_fields<LimitState>(study_fields::limit_state_name)},
      {"limit_states[].", describe_fields<LimitState>(study_fields::limit_state_type)},
      {"limit_states[].", describe_fields<LimitState>(study_fields::overturned_exceeds)},
      {"limit_states[].", describe_fields<LimitState>(study_fields::max_rotation)},
      {"limit_states[].", describe_fields<LimitState>(study_fields::residual_slide)},
      {"limit_states[].", describe_fields<LimitState>(study_fields::post_earthquake_unstable)},
      {"design.adaptive.", describe_fields<AdaptiveDesign>(study_fields::adaptive_base)},
      {"design.adaptive.", describe_fields<AdaptiveDesign>(study_fields::adaptive)},
      {"scene.ground_motion.records[].",
       describe_fields<SuiteRecord>(study_fields::suite_record_files)},
      {"scene.ground_motion.records[].", describe_fields<SuiteRecord>(study_fields::suite_record)}};
}

}  // namespace blockfrag
