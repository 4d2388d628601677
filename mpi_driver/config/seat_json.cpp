#include "mpi_driver/config/seat_json.hpp"

#include <string>
#include <utility>

#include "engine/number_text.hpp"
#include "engine/scene/block_geometry.hpp"
#include "engine/scene/parameter_domains.hpp"
#include "engine/scene/seat.hpp"
#include "engine/tolerances.hpp"
#include "mpi_driver/config/point_list_json.hpp"

namespace blockfrag {

std::vector<std::array<double, 2>> read_seat(const nlohmann::json& value, const JsonPointer& path,
                                             ConfigErrors& errors,
                                             const std::vector<std::array<double, 2>>* block) {
  PointList read = read_point_list(value, path, errors, domain::kMaxSeatPoints, "point", "points");
  // The fit makes sense only for a list of numbers and a valid block.
  if (read.complete && block) {
    const double tolerance = kContactHeight * BlockGeometry(PolygonBlock{*block, 1.0}).size();
    if (const auto defect = seat_defect(read.points, *block, tolerance)) {
      errors.add(defect->point < 0 ? path : path / static_cast<std::size_t>(defect->point),
                 defect->rule);
    }
  }
  return std::move(read.points);
}

}  // namespace blockfrag
