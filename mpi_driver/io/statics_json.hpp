// The block's statics (engine/water/block_statics.hpp) as one JSON object, the machine-readable
// output of `blockfrag statics`:
//   {"weight_N": W, "hydrostatic_force_N": [fx, fy], "uplift_force_N": U (up),
//    "uplift_horizontal_force_N": U_x, "added_mass_kg": M_a,
//    "yield_acceleration_g": {"slide_downstream": ..., "slide_upstream": ...,
//                             "rock_downstream": ..., "rock_upstream": ...},
//    and with a coefficient: "coefficient": K, "sliding_safety_factor": ...,
//    "overturning_safety_factor": ...}
// null stands for infinity (no acceleration that way starts the motion; nothing drives it). A dry
// scene gives the same keys, its water zero.
#pragma once

#include <optional>

#include <nlohmann/json.hpp>

#include "engine/water/block_statics.hpp"

namespace blockfrag {

nlohmann::json statics_to_json(const BlockStatics& statics, std::optional<double> coefficient,
                               std::optional<SafetyFactors> factors);

}  // namespace blockfrag
