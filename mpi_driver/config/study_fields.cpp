#include "mpi_driver/config/study_fields.hpp"

#include <utility>
#include <variant>

#include "mpi_driver/config/distribution_json.hpp"

namespace blockfrag {

namespace {

template <class Law>
void add_law_fields(std::vector<FieldDescription>& fields) {
  for (FieldDescription& field : describe_fields<Law>(DistributionKeys<Law>::fields)) {
    fields.push_back(std::move(field));
  }
}

template <std::size_t... index>
std::vector<FieldDescription> law_fields(std::index_sequence<index...>) {
  std::vector<FieldDescription> fields;
  (add_law_fields<std::variant_alternative_t<index, Distribution>>(fields), ...);
  return fields;
}

}  // namespace

std::vector<KeyTable> study_key_tables() {
  return {
      {"", describe_fields<StudyConfig>(study_fields::run)},
      {"inputs.*.", law_fields(std::make_index_sequence<std::variant_size_v<Distribution>>{})},
      {"intensity_measure.", describe_fields<IntensityMeasure>(study_fields::measure_type)},
      {"intensity_measure.", describe_fields<IntensityMeasure>(study_fields::sa)},
      {"intensity_measure.", describe_fields<IntensityMeasure>(study_fields::scaling)},
      {"intensity_measure.", describe_fields<IntensityMeasure>(study_fields::cloud)},
      {"limit_states[].", describe_fields<LimitState>(study_fields::limit_state_type)},
      {"limit_states[].", describe_fields<LimitState>(study_fields::max_rotation)},
      {"limit_states[].", describe_fields<LimitState>(study_fields::residual_slide)},
      {"limit_states[].", describe_fields<LimitState>(study_fields::post_earthquake_unstable)},
      {"design.adaptive.", describe_fields<AdaptiveDesign>(study_fields::adaptive_base)},
      {"design.adaptive.", describe_fields<AdaptiveDesign>(study_fields::adaptive)},
      {"scene.ground_motion.records[].", describe_fields<SuiteRecord>(study_fields::suite_record)}};
}

}  // namespace blockfrag
