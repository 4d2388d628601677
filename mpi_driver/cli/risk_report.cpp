#include "mpi_driver/cli/risk_report.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

#include <nlohmann/json.hpp>

#include "engine/number_text.hpp"
#include "mpi_driver/config/input_file.hpp"

namespace blockfrag {
namespace {

using Json = nlohmann::json;

// JSON has no NaN: a number that does not exist is null.
Json json_number(double value) { return std::isfinite(value) ? Json(value) : Json(nullptr); }

Json probabilities(double lambda, double low, double high) {
  Json list = Json::array();
  for (const double years : kRiskYears) {
    list.push_back({{"years", years},
                    {"probability", json_number(probability_in_years(lambda, years))},
                    {"low", json_number(probability_in_years(low, years))},
                    {"high", json_number(probability_in_years(high, years))}});
  }
  return list;
}

Json estimate_json(const std::optional<RiskEstimate>& estimate) {
  if (!estimate) return nullptr;
  const RiskIntegral& integral = estimate->integral;
  std::size_t resamples = 0;
  for (const double lambda : estimate->resample_lambda) resamples += std::isfinite(lambda);
  return {{"lambda", json_number(integral.lambda)},
          {"lambda_low", json_number(estimate->lambda_low)},
          {"lambda_high", json_number(estimate->lambda_high)},
          {"interval_resamples", resamples},
          {"interval_note", estimate->interval_note},
          {"probability_in_years",
           probabilities(integral.lambda, estimate->lambda_low, estimate->lambda_high)},
          {"lambda_below_levels", json_number(integral.lambda_below_levels)},
          {"lambda_above_levels", json_number(integral.lambda_above_levels)},
          {"share_beyond_levels", json_number(integral.share_beyond_levels())},
          {"lambda_beyond_hazard", json_number(integral.lambda_beyond_hazard)},
          {"bin_lambda", integral.bin_lambda}};
}

Json state_json(const LimitStateRisk& state) {
  return {{"name", state.name},
          {"median", json_number(state.median)},
          {"beta", json_number(state.beta)},
          {"fit_status", state.fit_status},
          {"levels", state.levels},
          {"probability", state.probability},
          {"fit", estimate_json(state.fit)},
          {"points", estimate_json(state.points)}};
}

Json hazard_json(const RiskReport& report) {
  const SiteHazard& hazard = report.hazard;
  return {{"file", report.hazard_file},
          {"format", hazard.format},
          {"imt", hazard.imt.name()},
          {"site", hazard.site},
          {"investigation_time_years",
           hazard.investigation_time ? Json(*hazard.investigation_time) : Json(nullptr)},
          {"levels_at_poe_one", hazard.levels_at_poe_one},
          {"levels_after_zero", hazard.levels_after_zero},
          {"im", hazard.curve.im},
          {"annual_rate", hazard.curve.annual_rate}};
}

std::string csv_number(double value) { return std::isfinite(value) ? format_number(value) : ""; }

void csv_row(std::ostream& out, const std::string& scope, const LimitStateRisk& state,
             const char* method, const std::optional<RiskEstimate>& estimate) {
  if (!estimate) return;
  {
    const RiskEstimate& e = *estimate;
    const RiskIntegral& integral = e.integral;
    out << scope << ',' << state.name << ',' << method << ',' << csv_number(integral.lambda) << ','
        << csv_number(e.lambda_low) << ',' << csv_number(e.lambda_high);
    for (const double years : kRiskYears) {
      out << ',' << csv_number(probability_in_years(integral.lambda, years));
    }
    out << ',' << csv_number(integral.lambda_below_levels) << ','
        << csv_number(integral.lambda_above_levels) << ','
        << csv_number(integral.share_beyond_levels()) << ','
        << csv_number(integral.lambda_beyond_hazard) << ',' << csv_number(state.median) << ','
        << csv_number(state.beta) << '\n';
  }
}

void csv_rows(std::ostream& out, const std::string& scope, const LimitStateRisk& state) {
  csv_row(out, scope, state, "fit", state.fit);
  csv_row(out, scope, state, "points", state.points);
}

// "1.23e-04", or "-" for a number that does not exist.
std::string short_number(double value, const char* format = "%.3g") {
  if (!std::isfinite(value)) return "-";
  char text[32];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

std::string estimate_cell(const std::optional<RiskEstimate>& estimate) {
  if (!estimate) return "-";
  const auto& e = *estimate;
  std::string cell = short_number(e.integral.lambda, "%.3e");
  if (std::isfinite(e.lambda_low)) {
    cell += " [" + short_number(e.lambda_low, "%.3e") + ", " + short_number(e.lambda_high, "%.3e") +
            "]";
  }
  cell += "  P50 " + short_number(probability_in_years(e.integral.lambda, 50.0));
  cell += "  beyond levels " + short_number(100 * e.integral.share_beyond_levels(), "%.1f") + " %";
  return cell;
}

}  // namespace

std::string risk_json(const RiskReport& report) {
  Json studies = Json::array();
  for (const auto& study : report.studies) {
    Json states = Json::array();
    for (const auto& state : study.states) states.push_back(state_json(state));
    studies.push_back({{"file", study.file},
                       {"weight", study.weight},
                       {"config_hash", study.config_hash},
                       {"im_label", study.im_label},
                       {"im_units", study.im_units},
                       {"cloud", study.cloud},
                       {"limit_states", states}});
  }
  Json combined = Json::array();
  for (const auto& state : report.combined) combined.push_back(state_json(state));
  const Json root = {{"blockfrag_risk", 1},
                     {"years", kRiskYears},
                     {"hazard", hazard_json(report)},
                     {"studies", studies},
                     {"limit_states", combined}};
  return root.dump(1) + "\n";
}

std::string risk_csv(const RiskReport& report) {
  std::ostringstream out;
  out << kRiskCsvStart << "(hazard " << printable_excerpt(report.hazard_file, 200) << ", "
      << report.hazard.imt.name()
      << "; lambda per year; scope combined: the studies weighted; studyK: the K-th --study, from "
         "0)\n";
  out << "scope,limit_state,method,lambda,lambda_low,lambda_high,p_1yr,p_50yr,p_100yr,"
         "lambda_below_levels,lambda_above_levels,share_beyond_levels,lambda_beyond_hazard,"
         "median,beta\n";
  for (const auto& state : report.combined) csv_rows(out, "combined", state);
  if (report.studies.size() > 1) {
    for (std::size_t s = 0; s < report.studies.size(); ++s) {
      for (const auto& state : report.studies[s].states) {
        csv_rows(out, "study" + std::to_string(s), state);
      }
    }
  }
  return out.str();
}

void print_risk_table(const RiskReport& report, std::ostream& out) {
  const SiteHazard& hazard = report.hazard;
  out << "risk from " << report.hazard_file << " (" << hazard.format << ", " << hazard.imt.name();
  if (!hazard.site.empty()) out << ", " << hazard.site;
  out << "): the curve from " << format_number(hazard.curve.im.front()) << " to "
      << format_number(hazard.curve.im.back()) << ' ' << report.studies.front().im_units;
  if (hazard.levels_at_poe_one > 0) {
    out << " (its " << hazard.levels_at_poe_one << " lower levels have poe = 1)";
  }
  out << '\n';
  for (const auto& study : report.studies) {
    out << "  study " << study.file << " (weight " << format_number(study.weight) << ")\n";
  }
  out << "mean annual frequency per year [95 % bootstrap interval], probability in 50 years, share "
         "from intensities beyond the study's levels:\n";
  for (const auto& state : report.combined) {
    out << "  " << state.name << '\n';
    out << "    fit     " << estimate_cell(state.fit) << '\n';
    out << "    points  " << estimate_cell(state.points) << '\n';
  }
}

}  // namespace blockfrag
