#include "mpi_driver/config/point_list_json.hpp"

#include "engine/number_text.hpp"
#include "engine/scene/parameter_domains.hpp"

namespace blockfrag {

PointList read_point_list(const nlohmann::json& value, const JsonPointer& path,
                          ConfigErrors& errors, double max_count, const std::string& noun,
                          const std::string& nouns) {
  PointList out;
  ArrayReader entries(value, path, errors);
  if (!entries.valid()) return out;
  if (static_cast<double>(entries.size()) > max_count) {
    errors.add(path, "has " + std::to_string(entries.size()) + " " + nouns + ", more than " +
                         format_number(max_count));
    return out;
  }
  const Range coordinate = Range::of(domain::polygon_coordinate);
  out.complete = true;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    ArrayReader point(entries.raw(i), entries.path_of(i), errors);
    if (!point.valid()) {
      out.complete = false;
      continue;
    }
    if (point.size() != 2) {
      errors.add(point.path(), "must be a " + noun + " [x, y] (got " +
                                   std::to_string(point.size()) + " numbers)");
      out.complete = false;
      continue;
    }
    const auto x = point.number(0, coordinate), y = point.number(1, coordinate);
    if (!x || !y) {
      out.complete = false;
      continue;
    }
    out.points.push_back({*x, *y});
  }
  return out;
}

}  // namespace blockfrag
