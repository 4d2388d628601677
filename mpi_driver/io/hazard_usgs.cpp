// The USGS hazard web service's answer (usgs/nshmp-haz-ws, HazardService.java: Result, Response,
// ResponseData, Curve; GET .../hazard/{edition}/{region}/{lon}/{lat}/{imt}/{vs30}):
//   {"status": "success", "date": ..., "url": ...,
//    "response": [{"metadata": {"edition": {...}, "region": {...}, "latitude": 40.75,
//                               "longitude": -111.9, "imt": {"value": "PGA", ...}, "vs30": {...},
//                               "xlabel": "Ground Motion (g)",
//                               "ylabel": "Annual Frequency of Exceedence",
//                               "xvalues": [0.0025, ...]},
//                  "data": [{"component": "Total", "yvalues": [0.41, ...]}, ...]}, ...]}
// one response per measure asked for ("any" asks for all); the service's enums are objects whose
// "value" is the name (meta/Util.java, EnumSerializer), a plain string is read as well.
#include <cmath>
#include <string>
#include <utility>

#include <nlohmann/json.hpp>

#include "engine/errors.hpp"
#include "mpi_driver/config/input_file.hpp"
#include "mpi_driver/io/hazard_formats.hpp"

namespace blockfrag {
namespace {

using Json = nlohmann::json;

constexpr std::size_t kMaxResponses = 1000;

class UsgsReader {
 public:
  explicit UsgsReader(const std::string& file) : file_(file) {}

  InvalidInput error(const std::string& path, const std::string& what) const {
    return InvalidInput(file_ + ": " + path + ": " + what + " (the USGS hazard service's JSON)");
  }

  const Json& member(const Json& object, const std::string& path, const std::string& key) const {
    if (!object.is_object()) throw error(path, "is not an object");
    const auto found = object.find(key);
    if (found == object.end()) throw error(path, "has no \"" + key + "\"");
    return *found;
  }

  // metadata.imt: a name, or the service's enum object with the name as "value".
  HazardImt imt(const Json& metadata, const std::string& path) const {
    const Json& field = member(metadata, path, "imt");
    const Json* name = &field;
    if (field.is_object() && field.contains("value")) name = &field.at("value");
    const auto parsed =
        name->is_string() ? parse_hazard_imt(name->get<std::string>()) : std::optional<HazardImt>{};
    if (!parsed) {
      throw error(path + "/imt",
                  "is not PGA, PGV or SA<T> (\"" + printable_excerpt(name->dump()) + "\")");
    }
    return *parsed;
  }

  std::vector<double> numbers(const Json& array, const std::string& path) const {
    if (!array.is_array() || array.size() < 2 || array.size() > kMaxHazardLevels) {
      throw error(path, "is not an array of 2 to " + std::to_string(kMaxHazardLevels) + " numbers");
    }
    std::vector<double> values;
    for (std::size_t k = 0; k < array.size(); ++k) {
      if (!array[k].is_number() || !std::isfinite(array[k].get<double>())) {
        throw error(path + "/" + std::to_string(k), "is not a finite number");
      }
      values.push_back(array[k].get<double>());
    }
    return values;
  }

 private:
  const std::string& file_;
};

// The index in response[] of the curve of `wanted`; refuses naming the measures it has.
std::size_t response_of(const UsgsReader& reader, const Json& responses, const HazardImt& wanted) {
  std::string offered;
  for (std::size_t i = 0; i < responses.size(); ++i) {
    const std::string path = "/response/" + std::to_string(i);
    const HazardImt imt =
        reader.imt(reader.member(responses[i], path, "metadata"), path + "/metadata");
    if (same_imt(imt, wanted)) return i;
    offered += (offered.empty() ? "" : ", ") + imt.name();
  }
  throw reader.error("/response", "has no curve of " + wanted.name() + " (it has " + offered + ")");
}

// The parsed answer's response[] array, after its status.
Json parse_answer(const std::string& file, std::string_view text) {
  try {
    return Json::parse(text);
  } catch (const Json::parse_error& error) {
    throw InvalidInput(file + ": not JSON (byte " + std::to_string(error.byte) +
                       "): a USGS hazard service answer is");
  }
}

const Json& responses_of(const UsgsReader& reader, const Json& root) {
  if (root.contains("status") &&
      (!root["status"].is_string() || root["status"].get<std::string>() != "success")) {
    throw reader.error("/status", "is " + printable_excerpt(root["status"].dump()) +
                                      ", not \"success\": the service did not answer with curves");
  }
  const Json& responses = reader.member(root, "", "response");
  if (!responses.is_array() || responses.empty() || responses.size() > kMaxResponses) {
    throw reader.error("/response",
                       "is not an array of 1 to " + std::to_string(kMaxResponses) + " responses");
  }
  return responses;
}

// The measure to take: --imt's (which must be the study's), or the study's.
HazardImt wanted_imt(const std::string& file, const HazardRequest& request) {
  if (!request.imt) return request.study;
  const auto asked = parse_hazard_imt(*request.imt);
  if (!asked) {
    throw InvalidInput("--imt " + printable_excerpt(*request.imt) +
                       ": not PGA, PGV, SA(T) or SA<T> (SA0P2)");
  }
  if (!same_imt(*asked, request.study)) refuse_imt(file, "--imt names", *asked, request.study);
  return *asked;
}

// The response's xvalues into raw.im and its Total component's yvalues into raw.rate; returns the
// Total component's JSON path.
std::string read_curve(const UsgsReader& reader, const Json& response, const std::string& path,
                       RawHazard& raw) {
  const Json& metadata = reader.member(response, path, "metadata");
  raw.im = reader.numbers(reader.member(metadata, path + "/metadata", "xvalues"),
                          path + "/metadata/xvalues");
  for (std::size_t k = 0; k < raw.im.size(); ++k) {
    if (!(raw.im[k] > 0.0) || (k > 0 && !(raw.im[k] > raw.im[k - 1]))) {
      throw reader.error(path + "/metadata/xvalues/" + std::to_string(k),
                         "is not > 0 and above the value before");
    }
  }
  const Json& data = reader.member(response, path, "data");
  for (std::size_t d = 0; data.is_array() && d < data.size(); ++d) {
    if (!data[d].is_object() || data[d].value("component", Json()) != "Total") continue;
    const std::string total = path + "/data/" + std::to_string(d);
    raw.rate = reader.numbers(reader.member(data[d], total, "yvalues"), total + "/yvalues");
    if (raw.rate.size() != raw.im.size()) {
      throw reader.error(total + "/yvalues", "holds " + std::to_string(raw.rate.size()) +
                                                 " values for " + std::to_string(raw.im.size()) +
                                                 " xvalues");
    }
    for (std::size_t k = 0; k < raw.rate.size(); ++k) {
      if (raw.rate[k] < 0.0) {
        throw reader.error(total + "/yvalues/" + std::to_string(k), "is negative");
      }
    }
    return total;
  }
  throw reader.error(path + "/data", "has no component \"Total\"");
}

}  // namespace

SiteHazard read_usgs_curve(const std::string& file, std::string_view text,
                           const HazardRequest& request) {
  const Json root = parse_answer(file, text);
  const UsgsReader reader(file);
  const Json& responses = responses_of(reader, root);
  const HazardImt wanted = wanted_imt(file, request);
  const std::size_t i = response_of(reader, responses, wanted);
  const std::string path = "/response/" + std::to_string(i);
  RawHazard raw;
  const std::string total = read_curve(reader, responses[i], path, raw);
  const auto where = [&](std::size_t k) { return total + "/yvalues/" + std::to_string(k); };
  SiteHazard hazard = finish_hazard(file, std::move(raw), where, hazard_unit_to_study(wanted));
  hazard.format = "usgs";
  hazard.imt = wanted;
  const Json& metadata = responses[i]["metadata"];
  if (metadata.contains("longitude") && metadata.contains("latitude") &&
      metadata["longitude"].is_number() && metadata["latitude"].is_number()) {
    hazard.site = "lon " + metadata["longitude"].dump() + ", lat " + metadata["latitude"].dump();
  }
  return hazard;
}

}  // namespace blockfrag
