// The scene's "dam": the block stands on a gravity dam's crest (engine/motion/dam_crest.hpp), and
// back.
#pragma once

#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "engine/scene/scene.hpp"
#include "mpi_driver/config/config_reader.hpp"

namespace blockfrag {

// {"period": s} or {"height": m, "elastic_modulus": Pa}, with "damping" (0.05),
// "participation" (1) and Fenves & Chopra's "reservoir_period_ratio" (1), "reservoir_damping" (0),
// "foundation_period_ratio" (1), "foundation_damping" (0), written back only when not their
// defaults. An absent "dam" is no dam; errors are recorded at their paths.
std::optional<DamCrest> read_dam(ObjectReader reader);
nlohmann::json dam_to_json(const DamCrest& dam);

// Why the scene's run cannot follow its dam's crest, if it cannot: the crest history it needs has
// more than kMaxCrestNodes nodes (engine/tolerances.hpp: a dam period far shorter than the
// run), which the engine would refuse only once the run starts. For a valid scene.
std::optional<std::string> crest_history_problem(const Scene& scene);

}  // namespace blockfrag
