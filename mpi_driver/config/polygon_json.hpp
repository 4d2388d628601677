// The block's "polygon" (a polygon block, engine/scene/polygon_properties.hpp), and back.
#pragma once

#include <vector>

#include <nlohmann/json.hpp>

#include "engine/scene/scene.hpp"
#include "mpi_driver/config/config_reader.hpp"

namespace blockfrag {

// [[x, y], ...], counter-clockwise, at least 3 vertices. Every error is recorded at its path: a bad
// coordinate at /block/polygon/2/1, a straight corner or a lone lowest vertex at /block/polygon/2,
// a rule of the whole polygon (crossing itself, clockwise, centre of mass outside the base) at
// /block/polygon. Returns the vertices read (check errors before using them).
std::vector<std::array<double, 2>> read_polygon(const nlohmann::json& value,
                                                const JsonPointer& path, ConfigErrors& errors);
nlohmann::json polygon_to_json(const PolygonBlock& polygon);

}  // namespace blockfrag
