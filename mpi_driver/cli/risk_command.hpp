// `blockfrag risk RESULTS.h5 --hazard FILE [--imt NAME] [--site N] [--output risk.json]
// [--csv risk.csv]`, or `--study A.h5:WEIGHT ...` for several studies weighted (pool levels by
// their share of the year): each limit state's mean annual frequency at the site of the hazard
// curve, from the fit and from the points, with bootstrap intervals (risk_assessment.hpp),
// printed and written as JSON and CSV (risk_report.hpp; docs/risk.md).
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace blockfrag {

struct RiskOptions {
  std::optional<std::filesystem::path> results;
  std::vector<std::string> studies;  // "FILE:WEIGHT"
  std::filesystem::path hazard;
  std::optional<std::string> imt;
  std::size_t site = 0;
  std::optional<std::filesystem::path> output;  // risk.json
  std::optional<std::filesystem::path> csv;
};

// Returns 0; the table goes to `out`, notes to `log`. Throws InvalidInput (exit code 2), before
// any computation, for a study output or hazard file that cannot be used, studies that do not
// match (measure, limit states), weights that are not shares of one, or outputs that cannot be
// written by the output rule (mpi_driver/io/output_target.hpp).
int run_risk(const RiskOptions& options, std::ostream& out, std::ostream& log);

}  // namespace blockfrag
