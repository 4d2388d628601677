// OpenQuake's hazard-curve CSV, as `oq export hcurves` writes it (gem/oq-engine
// openquake/calculators/export/hazard.py, export_hcurves_by_imt_csv; the manual's "Outputs from
// Classical PSHA" shows one):
//   #,,,,,"generated_by='OpenQuake engine 3.18.0', ..., kind='mean', investigation_time=1.0,
//   imt='PGA'" lon,lat,depth,poe-0.1000000,poe-0.4000000,poe-0.6000000
//   0.00000,0.00000,-0.10000,4.553860E-01,5.754042E-02,6.354511E-03
// with an optional custom_site_id column first (OpenQuake 3.16 on).
#include <cmath>
#include <string>

#include "engine/errors.hpp"
#include "engine/number_text.hpp"
#include "mpi_driver/config/input_file.hpp"
#include "mpi_driver/io/hazard_formats.hpp"

namespace blockfrag {
namespace {

// The value of `key=` in the metadata line: quoted ('...' or "...") or up to the next ',' or '"'.
std::optional<std::string> metadata_value(std::string_view line, std::string_view key) {
  std::size_t at = 0;
  while ((at = line.find(key, at)) != std::string_view::npos) {
    const bool starts = at == 0 || line[at - 1] == ' ' || line[at - 1] == ',' ||
                        line[at - 1] == '"' || line[at - 1] == '#';
    const std::size_t value = at + key.size();
    if (!starts || value >= line.size() || line[value] != '=') {
      at += key.size();
      continue;
    }
    const std::string_view rest = line.substr(value + 1);
    if (!rest.empty() && (rest.front() == '\'' || rest.front() == '"')) {
      const auto close = rest.find(rest.front(), 1);
      if (close == std::string_view::npos) return std::nullopt;
      return std::string(rest.substr(1, close - 1));
    }
    return std::string(rest.substr(0, std::min(rest.find_first_of(",\""), rest.size())));
  }
  return std::nullopt;
}

struct OpenQuakeHeader {
  std::size_t first_level = 0;  // the column of the first poe-<iml>
  bool custom_site_id = false;
  std::vector<double> iml;
};

OpenQuakeHeader read_openquake_header(const std::string& file, std::string_view line) {
  const auto fields = split_fields(line);
  const auto at = [&](std::size_t i) { return i < fields.size() ? fields[i] : std::string_view{}; };
  OpenQuakeHeader header;
  header.custom_site_id = at(0) == "custom_site_id";
  std::size_t column = header.custom_site_id ? 1 : 0;
  if (at(column) != "lon" || at(column + 1) != "lat") {
    throw InvalidInput(file + ": line 2: the header starts \"" + printable_excerpt(line) +
                       "\", not [custom_site_id,]lon,lat[,depth],poe-<iml>,... (an OpenQuake "
                       "hazard-curve CSV)");
  }
  column += at(column + 2) == "depth" ? 3 : 2;
  header.first_level = column;
  if (fields.size() - column > kMaxHazardLevels) {
    throw InvalidInput(file + ": line 2: more than " + std::to_string(kMaxHazardLevels) +
                       " levels");
  }
  for (std::size_t i = column; i < fields.size(); ++i) {
    double iml = 0.0;
    const std::string_view name = fields[i];
    if (name.substr(0, 4) != "poe-" || !read_field_number(name.substr(4), iml) || !(iml > 0.0) ||
        (!header.iml.empty() && !(iml > header.iml.back()))) {
      throw InvalidInput(file + ": line 2, column " + std::to_string(i + 1) + ": \"" +
                         printable_excerpt(name) +
                         "\" is not poe-<level> with levels > 0 and increasing");
    }
    header.iml.push_back(iml);
  }
  if (header.iml.size() < 2) {
    throw InvalidInput(file + ": line 2: fewer than two poe-<level> columns");
  }
  return header;
}

// A row's probabilities as annual rates, -ln(1 - poe) / T (+inf for poe = 1).
RawHazard read_openquake_row(const std::string& file, std::string_view line,
                             std::size_t line_number, const OpenQuakeHeader& header, double years) {
  const auto fields = split_fields(line);
  const std::string where = file + ": line " + std::to_string(line_number);
  if (fields.size() != header.first_level + header.iml.size()) {
    throw InvalidInput(where + ": " + std::to_string(fields.size()) + " fields, the header has " +
                       std::to_string(header.first_level + header.iml.size()));
  }
  double coordinate = 0.0;
  for (std::size_t i = header.custom_site_id ? 1 : 0; i < header.first_level; ++i) {
    if (!read_field_number(fields[i], coordinate)) {
      throw InvalidInput(where + ", column " + std::to_string(i + 1) + ": \"" +
                         printable_excerpt(fields[i]) + "\" is not a number");
    }
  }
  RawHazard raw{header.iml, {}};
  for (std::size_t k = 0; k < header.iml.size(); ++k) {
    const std::size_t column = header.first_level + k;
    double poe = 0.0;
    if (!read_field_number(fields[column], poe) || poe < 0.0 || poe > 1.0) {
      throw InvalidInput(where + ", column " + std::to_string(column + 1) + ": \"" +
                         printable_excerpt(fields[column]) +
                         "\" is not a probability of exceedance in [0, 1]");
    }
    raw.rate.push_back(poe == 1.0 ? HUGE_VAL : -std::log1p(-poe) / years);
  }
  return raw;
}

}  // namespace

SiteHazard read_openquake_curve(const std::string& file, std::string_view text,
                                const HazardRequest& request) {
  const auto lines = split_lines(text);
  if (lines.size() < 2 || lines[0].empty() || lines[0].front() != '#') {
    throw InvalidInput(file +
                       ": line 1: not OpenQuake's metadata line (a '#' line with "
                       "investigation_time and imt)");
  }
  const auto time_text = metadata_value(lines[0], "investigation_time");
  double years = 0.0;
  if (!time_text || !read_field_number(*time_text, years) || !(years > 0.0)) {
    throw InvalidInput(file + ": line 1: no investigation_time=<years> > 0 in the metadata");
  }
  const auto imt_text = metadata_value(lines[0], "imt");
  const auto imt = imt_text ? parse_hazard_imt(*imt_text) : std::nullopt;
  if (!imt) {
    throw InvalidInput(file + ": line 1: no imt='PGA', 'PGV' or 'SA(<period>)' in the metadata" +
                       (imt_text ? " (got \"" + printable_excerpt(*imt_text) + "\")" : ""));
  }
  if (request.imt) {
    const auto asked = parse_hazard_imt(*request.imt);
    if (!asked || !same_imt(*asked, *imt)) {
      throw InvalidInput(file + ": --imt " + printable_excerpt(*request.imt) +
                         " but the file's curves are of " + imt->name());
    }
  }
  if (!same_imt(*imt, request.study)) refuse_imt(file, "its curves are of", *imt, request.study);
  const OpenQuakeHeader header = read_openquake_header(file, lines[1]);
  std::vector<std::size_t> rows;
  for (std::size_t i = 2; i < lines.size(); ++i) {
    if (!lines[i].empty()) rows.push_back(i);
  }
  if (request.site >= rows.size()) {
    throw InvalidInput(file + ": --site " + std::to_string(request.site) + " but the file has " +
                       std::to_string(rows.size()) + " site" + (rows.size() == 1 ? "" : "s") +
                       " (rows), numbered from 0");
  }
  RawHazard chosen;
  for (std::size_t r = 0; r < rows.size(); ++r) {
    RawHazard raw = read_openquake_row(file, lines[rows[r]], rows[r] + 1, header, years);
    if (r == request.site) chosen = std::move(raw);
  }
  const std::size_t line_number = rows[request.site] + 1;
  const auto where = [&](std::size_t k) {
    return "line " + std::to_string(line_number) + ", column poe-" + format_number(header.iml[k]);
  };
  SiteHazard hazard = finish_hazard(file, std::move(chosen), where, hazard_unit_to_study(*imt));
  hazard.format = "openquake";
  hazard.imt = *imt;
  hazard.investigation_time = years;
  const auto fields = split_fields(lines[rows[request.site]]);
  const std::size_t lon = header.custom_site_id ? 1 : 0;
  hazard.site = "lon " + std::string(fields[lon]) + ", lat " + std::string(fields[lon + 1]);
  if (header.custom_site_id) {
    hazard.site = printable_excerpt(fields[0], 20) + " (" + hazard.site + ")";
  }
  return hazard;
}

}  // namespace blockfrag
