#include "mpi_driver/config/seat_json.hpp"

#include <cstddef>
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
  // A seat's simulation watches the clearance of every seat point and block vertex, one guard each.
  const std::size_t watched = read.points.size() + (block ? block->size() : 0);
  if (read.complete && block && watched > static_cast<std::size_t>(kMaxSeatClearances)) {
    errors.add(path, "has " + std::to_string(read.points.size()) + " points; with the block's " +
                         std::to_string(block->size()) + " vertices they number " +
                         std::to_string(watched) + ", more than the " +
                         std::to_string(kMaxSeatClearances) + " a seat's simulation watches");
  }
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
