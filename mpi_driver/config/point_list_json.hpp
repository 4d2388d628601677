// A JSON list of points [[x, y], ...], as a polygon's vertices and a seat's points are written.
#pragma once

#include <array>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "mpi_driver/config/config_reader.hpp"

namespace blockfrag {

struct PointList {
  std::vector<std::array<double, 2>> points;  // those read (check errors before using them)
  bool complete = false;                      // every entry a point of two valid coordinates
};

// Reads at most `max_count` points, each coordinate in the polygon coordinates' domain, recording
// every error at its path; `noun` and `nouns` name an entry in the messages ("vertex",
// "vertices").
PointList read_point_list(const nlohmann::json& value, const JsonPointer& path,
                          ConfigErrors& errors, double max_count, const std::string& noun,
                          const std::string& nouns);

}  // namespace blockfrag
