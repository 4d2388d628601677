// A study's "limit_states": each one's "name", its "type" and the threshold's key the type selects
// (study_fields.hpp's tables), and "overturned_exceeds" for every type but overturning.
#pragma once

#include <nlohmann/json.hpp>

#include "mpi_driver/config/config_reader.hpp"
#include "mpi_driver/config/study_config.hpp"

namespace blockfrag {

// Reads the array into config.limit_states; a post-earthquake limit state needs the base scene's
// reservoir (checked when the scene is valid). An empty array is refused at `root`'s key.
void read_limit_states(ArrayReader array, ObjectReader& root, StudyConfig& config,
                       bool scene_valid);
nlohmann::json limit_state_to_json(const LimitState& state);

}  // namespace blockfrag
