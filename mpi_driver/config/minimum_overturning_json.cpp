#include "mpi_driver/config/minimum_overturning_json.hpp"

#include "mpi_driver/config/study_fields.hpp"

namespace blockfrag {

MinimumOverturningSettings read_minimum_overturning(ObjectReader reader) {
  MinimumOverturningSettings settings;
  read_fields<MinimumOverturningSettings>(reader, study_fields::minimum_overturning, settings);
  reader.finish();
  return settings;
}

nlohmann::json minimum_overturning_to_json(const MinimumOverturningSettings& settings) {
  nlohmann::json out = nlohmann::json::object();
  write_fields<MinimumOverturningSettings>(settings, study_fields::minimum_overturning, out);
  return out;
}

}  // namespace blockfrag
