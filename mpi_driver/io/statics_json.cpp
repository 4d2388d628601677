#include "mpi_driver/io/statics_json.hpp"

#include <cmath>

namespace blockfrag {

namespace {

// JSON has no infinity: null stands for it.
nlohmann::json finite_or_null(double x) {
  return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr);
}

}  // namespace

nlohmann::json statics_to_json(const BlockStatics& statics, std::optional<double> coefficient,
                               std::optional<SafetyFactors> factors) {
  const YieldAccelerations& y = statics.yield;
  nlohmann::json out = {{"weight_N", statics.weight},
                        {"hydrostatic_force_N", {statics.hydrostatic_x, statics.hydrostatic_y}},
                        {"uplift_force_N", statics.uplift_y},
                        {"uplift_horizontal_force_N", statics.uplift_x},
                        {"added_mass_kg", statics.added_mass},
                        {"yield_acceleration_g",
                         {{"slide_downstream", finite_or_null(y.slide_downstream)},
                          {"slide_upstream", finite_or_null(y.slide_upstream)},
                          {"rock_downstream", finite_or_null(y.rock_downstream)},
                          {"rock_upstream", finite_or_null(y.rock_upstream)}}}};
  if (coefficient && factors) {
    out["coefficient"] = *coefficient;
    out["sliding_safety_factor"] = finite_or_null(factors->sliding);
    out["overturning_safety_factor"] = finite_or_null(factors->overturning);
  }
  return out;
}

}  // namespace blockfrag
