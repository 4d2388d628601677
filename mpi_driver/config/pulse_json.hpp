// The near-fault pulses' keys in a scene's "ground_motion" (engine/motion/near_fault_pulses.hpp),
// and back.
#pragma once

#include <optional>
#include <string_view>

#include <nlohmann/json.hpp>

#include "engine/scene/scene.hpp"
#include "mpi_driver/config/config_reader.hpp"

namespace blockfrag {

// The "type" names this file reads.
inline constexpr std::string_view makris_a_type = "makris_a", makris_b_type = "makris_b",
                                  makris_c_type = "makris_c", ricker_type = "ricker",
                                  mavroeidis_papageorgiou_type = "mavroeidis_papageorgiou";

// The pulse of that type read from the reader (errors recorded there); nullopt for another type.
std::optional<GroundMotion> read_near_fault_pulse(std::string_view type, ObjectReader& reader);

// Defaults filled in (t0), so the canonical scene names the same motion after any default changes.
nlohmann::json pulse_to_json(const MakrisPulseA& pulse);
nlohmann::json pulse_to_json(const MakrisPulseB& pulse);
nlohmann::json pulse_to_json(const MakrisPulseC& pulse);
nlohmann::json pulse_to_json(const RickerWavelet& pulse);
nlohmann::json pulse_to_json(const MavroeidisPapageorgiouPulse& pulse);

}  // namespace blockfrag
