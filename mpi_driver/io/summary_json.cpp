#include "mpi_driver/io/summary_json.hpp"

#include <cmath>
#include <optional>

namespace blockfrag {

namespace {

nlohmann::json optional_time(const std::optional<double>& time) {
  return time ? nlohmann::json(*time) : nlohmann::json(nullptr);
}

// JSON has no infinity: null stands for it, as for no value.
nlohmann::json finite_or_null(const std::optional<double>& value) {
  return value && std::isfinite(*value) ? nlohmann::json(*value) : nlohmann::json(nullptr);
}

}  // namespace

nlohmann::json summary_to_json(const Summary& summary) {
  nlohmann::json modes = nlohmann::json::array();
  for (const auto& change : summary.modes) modes.push_back({change.time, mode_name(change.mode)});
  const bool ok = summary.status == Status::ok;
  nlohmann::json out = {
      {"status", ok ? "ok" : "failed"},
      {"status_reason", ok ? nlohmann::json(nullptr) : nlohmann::json(summary.status_reason)},
      {"model", model_name(summary.model)},
      {"effects", model_effects(summary.model)},
      {"overturned", summary.overturned},
      {"overturn_time", optional_time(summary.overturn_time)},
      {"fell", summary.fell},
      {"fell_time", optional_time(summary.fell_time)},
      {"max_abs_theta", summary.max_abs_theta},
      {"final_theta", summary.final_theta},
      {"final_slide", summary.final_slide},
      {"max_abs_slide", summary.max_abs_slide},
      {"rock_start_time", optional_time(summary.rock_start_time)},
      {"slide_start_time", optional_time(summary.slide_start_time)},
      {"first_impact_time", optional_time(summary.first_impact_time)},
      {"impacts", summary.impacts},
      {"modes", std::move(modes)},
      {"end_time", summary.end_time},
      {"settled", summary.settled},
      {"settle_time", optional_time(summary.settle_time)},
      {"steps", summary.steps},
      {"rhs_evaluations", summary.rhs_evaluations},
      {"events", summary.events},
      {"max_impact_energy_gain", summary.max_impact_energy_gain},
      {"max_contact_violation", summary.max_contact_violation},
      {"max_penetration", summary.max_penetration},
      {"painleve_events", summary.painleve_events}};
  if (summary.post_earthquake) {
    out["post_earthquake_sliding_safety_factor"] =
        finite_or_null(summary.post_earthquake->sliding_safety_factor);
    out["post_earthquake_overturning_safety_factor"] =
        finite_or_null(summary.post_earthquake->overturning_safety_factor);
  }
  return out;
}

}  // namespace blockfrag
