#include "mpi_driver/io/hazard_file.hpp"

#include <charconv>
#include <cmath>
#include <utility>

#include "engine/errors.hpp"
#include "engine/number_text.hpp"
#include "mpi_driver/config/input_file.hpp"
#include "mpi_driver/io/hazard_formats.hpp"

namespace blockfrag {
namespace {

// An OpenQuake export of every site of a national model is tens of MB; a site's curve from the
// USGS service a few kB.
constexpr std::size_t kMaxHazardFileBytes = std::size_t{64} << 20;

// OpenQuake's CSV has "poe-" in its header (its first or second line); a USGS answer is JSON.
enum class HazardFormat { openquake, usgs, table };

HazardFormat format_of(std::string_view text) {
  const auto start = text.find_first_not_of(" \t\r\n");
  if (start != std::string_view::npos && text[start] == '{') return HazardFormat::usgs;
  const auto lines = split_lines(text.substr(0, std::min<std::size_t>(text.size(), 1 << 20)));
  for (std::size_t i = 0; i < lines.size() && i < 2; ++i) {
    if (lines[i].find("poe-") != std::string_view::npos) return HazardFormat::openquake;
  }
  return HazardFormat::table;
}

}  // namespace

std::vector<std::string_view> split_lines(std::string_view text) {
  std::vector<std::string_view> lines;
  std::size_t start = 0;
  while (start < text.size()) {
    const auto end = std::min(text.find('\n', start), text.size());
    auto line = text.substr(start, end - start);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    lines.push_back(line);
    start = end + 1;
  }
  return lines;
}

std::vector<std::string_view> split_fields(std::string_view line) {
  std::vector<std::string_view> fields;
  std::size_t start = 0;
  while (true) {
    const auto end = std::min(line.find(',', start), line.size());
    fields.push_back(line.substr(start, end - start));
    if (end == line.size()) return fields;
    start = end + 1;
  }
}

bool read_field_number(std::string_view field, double& value) {
  const auto first = field.find_first_not_of(" \t");
  if (first == std::string_view::npos) return false;
  field = field.substr(first, field.find_last_not_of(" \t") - first + 1);
  const char* end = field.data() + field.size();
  const auto result = std::from_chars(field.data(), end, value);
  return result.ec == std::errc() && result.ptr == end && std::isfinite(value);
}

void refuse_imt(const std::string& file, const std::string& what, const HazardImt& file_imt,
                const HazardImt& study) {
  throw InvalidInput(file + ": " + what + " " + file_imt.name() +
                     ", the study's intensity measure is " + study.name() +
                     (study.kind == HazardImt::Kind::sa ? " (5 % damped)" : "") +
                     ": a fragility is integrated against the hazard of its own measure");
}

SiteHazard finish_hazard(const std::string& file, RawHazard raw, const LevelName& where,
                         double unit) {
  SiteHazard hazard;
  std::size_t first = 0;
  while (first < raw.rate.size() && std::isinf(raw.rate[first])) ++first;
  hazard.levels_at_poe_one = first;
  std::size_t last = first;
  while (last + 1 < raw.rate.size() && raw.rate[last] > 0.0) ++last;
  hazard.levels_after_zero = raw.rate.size() - 1 - last;
  if (first >= raw.rate.size() || last == first) {
    throw InvalidInput(file + ": the curve has fewer than two levels with a finite rate above 0 " +
                       "(levels with poe = 1 have an unbounded rate; after a rate of 0 the " +
                       "curve has ended)");
  }
  for (std::size_t i = first; i < raw.rate.size(); ++i) {
    if (i > first && raw.rate[i] > raw.rate[i - 1]) {
      throw InvalidInput(file + ": " + where(i) + ": the rate of exceedance " +
                         format_number(raw.rate[i]) + " is above the previous level's " +
                         format_number(raw.rate[i - 1]) + " (a hazard curve never rises)");
    }
    if (i > last) continue;
    hazard.curve.im.push_back(raw.im[i] * unit);
    hazard.curve.annual_rate.push_back(raw.rate[i]);
  }
  return hazard;
}

SiteHazard read_hazard_file(const std::filesystem::path& path, const HazardRequest& request) {
  const std::string file = path.string();
  const std::string text = read_input_file(path, {kMaxHazardFileBytes});
  switch (format_of(text)) {
    case HazardFormat::openquake: return read_openquake_curve(file, text, request);
    case HazardFormat::usgs: return read_usgs_curve(file, text, request);
    case HazardFormat::table: return read_table_curve(file, text, request);
  }
  throw ContractViolation("read_hazard_file: unknown format");
}

}  // namespace blockfrag
