#include "mpi_driver/config/adaptive_design.hpp"

#include "mpi_driver/config/study_fields.hpp"

namespace blockfrag {

AdaptiveDesign read_adaptive_design(ObjectReader reader) {
  AdaptiveDesign design;
  read_fields<AdaptiveDesign>(reader, study_fields::adaptive_base, design);
  read_fields<AdaptiveDesign>(reader, study_fields::adaptive, design);
  reader.finish();
  return design;
}

nlohmann::json adaptive_design_to_json(const AdaptiveDesign& design) {
  nlohmann::json adaptive = nlohmann::json::object();
  write_fields<AdaptiveDesign>(design, study_fields::adaptive_base, adaptive);
  write_fields<AdaptiveDesign>(design, study_fields::adaptive, adaptive);
  return {{"adaptive", adaptive}};
}

}  // namespace blockfrag
