// A site's hazard curve read from the file a hazard tool writes (docs/risk.md, "Hazard files"):
//  - OpenQuake's hazard-curve CSV (`oq export hcurves`; gem/oq-engine
//    openquake/calculators/export/hazard.py, export_hcurves_by_imt_csv; the manual's "Outputs
//    from Classical PSHA"): a `#` line of metadata with investigation_time and imt, a header
//    `[custom_site_id,]lon,lat,depth,poe-<iml>,...`, one row per site of probabilities of
//    exceedance in the investigation time T, so lambda = -ln(1 - poe) / T;
//  - the USGS hazard web service's JSON (usgs/nshmp-haz-ws, HazardService): `response[]`, each
//    with `metadata.imt` and `metadata.xvalues` and `data[]` of `{component, yvalues}`, the
//    component "Total" holding annual frequencies of exceedance;
//  - a plain table: lines `im,annual frequency`, '#' comments and one header line allowed, the
//    intensity in the study's unit and its measure given by --imt.
// Nothing is trusted: the file is read only if regular and at most 64 MB, every number is checked
// (intensities finite, > 0 and increasing; probabilities in [0, 1]; rates finite and >= 0, both
// non-increasing), and a refusal names the file and the line (CSV) or JSON path.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>

#include "mpi_driver/io/hazard_imt.hpp"
#include "postproc/risk/hazard_curve.hpp"

namespace blockfrag {

struct HazardRequest {
  HazardImt study;                 // the measure the curve must be of
  std::optional<std::string> imt;  // --imt: the file's measure (a plain table has no other)
  std::size_t site = 0;            // --site: the row of an OpenQuake file, from 0
};

struct SiteHazard {
  HazardCurve curve;   // intensities in the study's unit, annual rates of exceedance
  std::string format;  // "openquake", "usgs", "table"
  HazardImt imt;
  std::string site;  // where, as the file says: "lon 11.1, lat 46.1", "" for a table
  std::optional<double> investigation_time;  // OpenQuake's T, years
  // OpenQuake's leading levels with poe = 1 (an unbounded rate): left out, the curve starting at
  // the first level with poe < 1.
  std::size_t levels_at_poe_one = 0;
  // Levels after the first whose rate is 0: left out, the curve ending at that first 0.
  std::size_t levels_after_zero = 0;
};

// Throws InvalidInput naming the file and the line or JSON path for a file that breaks its
// format, whose measure is not the study's (naming both), or without two usable levels.
SiteHazard read_hazard_file(const std::filesystem::path& path, const HazardRequest& request);

}  // namespace blockfrag
