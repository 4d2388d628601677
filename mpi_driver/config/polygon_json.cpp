#include "mpi_driver/config/polygon_json.hpp"

#include <string>
#include <utility>

#include "engine/number_text.hpp"
#include "engine/scene/block_geometry.hpp"
#include "engine/scene/polygon_properties.hpp"
#include "mpi_driver/config/point_list_json.hpp"

namespace blockfrag {

std::vector<std::array<double, 2>> read_polygon(const nlohmann::json& value,
                                                const JsonPointer& path, ConfigErrors& errors) {
  PointList read =
      read_point_list(value, path, errors, domain::kMaxPolygonVertices, "vertex", "vertices");
  // The shape's rules make sense only for a list of numbers.
  if (read.complete) {
    if (const auto defect = polygon_defect(read.points)) {
      errors.add(defect->vertex < 0 ? path : path / static_cast<std::size_t>(defect->vertex),
                 defect->rule);
    } else if (const double size = BlockGeometry(PolygonBlock{read.points, 1.0}).size();
               !domain::block_length.contains(size)) {
      errors.add(path, "its size (the farthest corner from the centre of mass, " +
                           format_number(size) + " m) " + domain::block_length.rule());
    }
  }
  return std::move(read.points);
}

nlohmann::json polygon_to_json(const PolygonBlock& polygon) {
  nlohmann::json vertices = nlohmann::json::array();
  for (const auto& v : polygon.vertices) vertices.push_back({v[0], v[1]});
  return {{"polygon", vertices}, {"mass", polygon.mass}};
}

}  // namespace blockfrag
