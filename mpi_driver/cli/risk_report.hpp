// `blockfrag risk`'s outputs: the printed table, risk.json (everything, for plot_risk.py and other
// tools) and risk.csv (one row per limit state and method). docs/risk.md documents every key and
// column.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "mpi_driver/cli/risk_assessment.hpp"
#include "mpi_driver/io/hazard_file.hpp"

namespace blockfrag {

struct RiskReport {
  std::string hazard_file;
  SiteHazard hazard;
  std::vector<StudyRisk> studies;
  std::vector<LimitStateRisk> combined;  // the studies weighted and summed
};

// How risk.json and risk.csv start, by which a rerun knows the files it replaces: the JSON's
// first key (keys are sorted) and the CSV's comment line.
inline constexpr const char* kRiskJsonStart = "{\n \"blockfrag_risk\": ";
inline constexpr const char* kRiskCsvStart = "# blockfrag risk ";

std::string risk_json(const RiskReport& report);
std::string risk_csv(const RiskReport& report);
void print_risk_table(const RiskReport& report, std::ostream& out);

}  // namespace blockfrag
