#include "mpi_driver/config/polygon_json.hpp"

#include <string>

#include "engine/number_text.hpp"
#include "engine/scene/block_geometry.hpp"
#include "engine/scene/polygon_properties.hpp"

namespace blockfrag {

std::vector<std::array<double, 2>> read_polygon(const nlohmann::json& value,
                                                const JsonPointer& path, ConfigErrors& errors) {
  ArrayReader vertices(value, path, errors);
  if (!vertices.valid()) return {};
  if (static_cast<double>(vertices.size()) > domain::kMaxPolygonVertices) {
    errors.add(path, "has " + std::to_string(vertices.size()) + " vertices, more than " +
                         format_number(domain::kMaxPolygonVertices));
    return {};
  }
  const Range coordinate = Range::of(domain::polygon_coordinate);
  std::vector<std::array<double, 2>> out;
  bool complete = true;
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    ArrayReader point(vertices.raw(i), vertices.path_of(i), errors);
    if (!point.valid()) {
      complete = false;
      continue;
    }
    if (point.size() != 2) {
      errors.add(point.path(),
                 "must be a vertex [x, y] (got " + std::to_string(point.size()) + " numbers)");
      complete = false;
      continue;
    }
    const auto x = point.number(0, coordinate), y = point.number(1, coordinate);
    if (!x || !y) {
      complete = false;
      continue;
    }
    out.push_back({*x, *y});
  }
  // The shape's rules make sense only for a list of numbers.
  if (complete) {
    if (const auto defect = polygon_defect(out)) {
      errors.add(defect->vertex < 0 ? path : path / static_cast<std::size_t>(defect->vertex),
                 defect->rule);
    } else if (const double size = BlockGeometry(PolygonBlock{out, 1.0}).size();
               !domain::block_length.contains(size)) {
      errors.add(path, "its size (the farthest corner from the centre of mass, " +
                           format_number(size) + " m) " + domain::block_length.rule());
    }
  }
  return out;
}

nlohmann::json polygon_to_json(const PolygonBlock& polygon) {
  nlohmann::json vertices = nlohmann::json::array();
  for (const auto& v : polygon.vertices) vertices.push_back({v[0], v[1]});
  return {{"polygon", vertices}, {"mass", polygon.mass}};
}

}  // namespace blockfrag
