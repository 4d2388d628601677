// A simulation's Summary as one JSON object, the machine-readable output of `blockfrag simulate`.
#pragma once

#include <nlohmann/json.hpp>

#include "engine/summary.hpp"

namespace blockfrag {

// Keys: status ("ok"/"failed"), status_reason (null when ok), overturned, overturn_time, fell,
// fell_time (off a seat's end: never on the flat ground),
// max_abs_theta, final_theta, final_slide, max_abs_slide, rock_start_time, slide_start_time,
// first_impact_time (each time null when it never happened), impacts, modes ([[time, "mode"],
// ...]), end_time, steps, rhs_evaluations, events, max_impact_energy_gain, max_contact_violation,
// max_penetration, painleve_events; with a reservoir, post_earthquake_sliding_safety_factor and
// post_earthquake_overturning_safety_factor (null when the block does not stand at rest at the end,
// or when nothing drives it: infinite).
// dump() writes each double as the shortest text that reads back to the same bits.
nlohmann::json summary_to_json(const Summary& summary);

}  // namespace blockfrag
