// The scene's "seat" (engine/scene/seat.hpp): the ground under the block as a polyline.
#pragma once

#include <array>
#include <vector>

#include <nlohmann/json.hpp>

#include "mpi_driver/config/config_reader.hpp"

namespace blockfrag {

// [[x, y], ...], left to right, at least 2 points, at most kMaxSeatClearances
// (engine/tolerances.hpp) with the block's vertices, in the frame of the block's vertices. Every
// error is recorded at its path: a bad coordinate at /seat/2/1, a point out of order or inside the
// block at /seat/2, a rule of the whole seat (a block vertex below it, its weight not carried) at
// /seat. `block`: the block's vertices (engine/scene/seat.hpp, scene_block_vertices), or none when
// the block itself has errors (the fit is then not checked). Returns the points read (check errors
// before using them).
std::vector<std::array<double, 2>> read_seat(const nlohmann::json& value, const JsonPointer& path,
                                             ConfigErrors& errors,
                                             const std::vector<std::array<double, 2>>* block);

}  // namespace blockfrag
