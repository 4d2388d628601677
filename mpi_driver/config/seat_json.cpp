#include "mpi_driver/config/seat_json.hpp"

#include <string>

#include "engine/number_text.hpp"
#include "engine/scene/block_geometry.hpp"
#include "engine/scene/parameter_domains.hpp"
#include "engine/scene/seat.hpp"
#include "engine/tolerances.hpp"

namespace blockfrag {

std::vector<std::array<double, 2>> read_seat(const nlohmann::json& value, const JsonPointer& path,
                                             ConfigErrors& errors,
                                             const std::vector<std::array<double, 2>>* block) {
  ArrayReader points(value, path, errors);
  if (!points.valid()) return {};
  if (static_cast<double>(points.size()) > domain::kMaxSeatPoints) {
    errors.add(path, "has " + std::to_string(points.size()) + " points, more than " +
                         format_number(domain::kMaxSeatPoints));
    return {};
  }
  const Range coordinate = Range::of(domain::polygon_coordinate);
  std::vector<std::array<double, 2>> out;
  bool complete = true;
  for (std::size_t i = 0; i < points.size(); ++i) {
    ArrayReader point(points.raw(i), points.path_of(i), errors);
    if (!point.valid()) {
      complete = false;
      continue;
    }
    if (point.size() != 2) {
      errors.add(point.path(),
                 "must be a point [x, y] (got " + std::to_string(point.size()) + " numbers)");
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
  // The fit makes sense only for a list of numbers and a valid block.
  if (complete && block) {
    const double tolerance = kContactHeight * BlockGeometry(PolygonBlock{*block, 1.0}).size();
    if (const auto defect = seat_defect(out, *block, tolerance)) {
      errors.add(defect->point < 0 ? path : path / static_cast<std::size_t>(defect->point),
                 defect->rule);
    }
  }
  return out;
}

}  // namespace blockfrag
