// A plain hazard table: one level a line, `im,annual frequency of exceedance`, the intensity in
// the study's unit (g or m/s); lines starting with '#' and blank lines are skipped, and the first
// other line may be a header (text, not two numbers). The table does not say its measure: --imt
// does.
#include <string>
#include <utility>

#include "engine/errors.hpp"
#include "mpi_driver/config/input_file.hpp"
#include "mpi_driver/io/hazard_formats.hpp"

namespace blockfrag {
SiteHazard read_table_curve(const std::string& file, std::string_view text,
                            const HazardRequest& request) {
  if (!request.imt) {
    throw InvalidInput(file +
                       ": a two-column hazard table does not name its intensity measure: "
                       "give it with --imt (the study's is " +
                       request.study.name() + ")");
  }
  const auto imt = parse_hazard_imt(*request.imt);
  if (!imt) {
    throw InvalidInput("--imt " + printable_excerpt(*request.imt) +
                       ": not PGA, PGV, SA(T) or SA<T> (SA0P2)");
  }
  if (!same_imt(*imt, request.study)) refuse_imt(file, "--imt names", *imt, request.study);
  const auto lines = split_lines(text);
  RawHazard raw;
  std::vector<std::size_t> line_of;
  bool header_allowed = true;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const std::string_view line = lines[i];
    if (line.find_first_not_of(" \t") == std::string_view::npos || line.front() == '#') continue;
    const auto fields = split_fields(line);
    double im = 0.0, rate = 0.0;
    const bool numbers = fields.size() == 2 && read_field_number(fields[0], im) &&
                         read_field_number(fields[1], rate);
    const std::string where = file + ": line " + std::to_string(i + 1);
    if (!numbers && header_allowed) {
      header_allowed = false;
      continue;
    }
    header_allowed = false;
    if (!numbers) {
      throw InvalidInput(where + ": \"" + printable_excerpt(line) +
                         "\" is not two numbers, im,annual frequency");
    }
    if (!(im > 0.0) || (!raw.im.empty() && !(im > raw.im.back()))) {
      throw InvalidInput(where + ": the intensity " + std::string(fields[0]) +
                         " is not > 0 and above the line before's");
    }
    if (rate < 0.0) throw InvalidInput(where + ": the annual frequency is negative");
    if (raw.im.size() == kMaxHazardLevels) {
      throw InvalidInput(where + ": more than " + std::to_string(kMaxHazardLevels) + " levels");
    }
    raw.im.push_back(im);
    raw.rate.push_back(rate);
    line_of.push_back(i + 1);
  }
  const auto where = [&](std::size_t k) { return "line " + std::to_string(line_of[k]); };
  SiteHazard hazard = finish_hazard(file, std::move(raw), where, 1.0);
  hazard.format = "table";
  hazard.imt = *imt;
  return hazard;
}

}  // namespace blockfrag
