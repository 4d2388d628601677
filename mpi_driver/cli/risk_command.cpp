#include "mpi_driver/cli/risk_command.hpp"

#include <charconv>
#include <chrono>
#include <cmath>

#include "engine/errors.hpp"
#include "engine/number_text.hpp"
#include "mpi_driver/cli/risk_report.hpp"
#include "mpi_driver/config/input_file.hpp"
#include "mpi_driver/io/atomic_file.hpp"
#include "mpi_driver/io/output_target.hpp"

namespace blockfrag {
namespace {

// As export: reading a study's fits and counts takes a fraction of a second.
constexpr std::chrono::milliseconds kRiskReadLimit{10'000};
// Weights are shares of the year: they sum to 1, to the digits a user writes.
constexpr double kWeightSumTolerance = 1e-6;
constexpr std::size_t kMaxStudies = 100;

struct StudySpec {
  std::filesystem::path file;
  double weight = 1.0;
};

std::vector<StudySpec> study_specs(const RiskOptions& options) {
  if (options.results.has_value() == !options.studies.empty()) {
    throw InvalidInput(
        "risk: give one study output (RESULTS.h5) or several as --study "
        "FILE:WEIGHT, not both or neither");
  }
  if (options.results) return {{*options.results, 1.0}};
  if (options.studies.size() > kMaxStudies) {
    throw InvalidInput("--study: at most " + std::to_string(kMaxStudies) + " studies");
  }
  std::vector<StudySpec> specs;
  double sum = 0.0;
  for (const auto& text : options.studies) {
    const auto colon = text.rfind(':');
    double weight = 0.0;
    const char* end = text.data() + text.size();
    const bool parsed = colon != std::string::npos && colon > 0 &&
                        std::from_chars(text.data() + colon + 1, end, weight).ptr == end &&
                        colon + 1 < text.size();
    if (!parsed || !(std::isfinite(weight) && weight > 0.0 && weight <= 1.0)) {
      throw InvalidInput("--study " + printable_excerpt(text) +
                         ": not FILE:WEIGHT with a weight in (0, 1]");
    }
    specs.push_back({text.substr(0, colon), weight});
    sum += weight;
  }
  if (std::abs(sum - 1.0) > kWeightSumTolerance) {
    throw InvalidInput("--study: the weights sum to " + format_number(sum) +
                       ", not 1 (each is a share of the year)");
  }
  return specs;
}

// Every study of one measure and one list of limit states, as the first's.
void check_studies_match(const std::vector<WeightedStudy>& studies) {
  const auto& first = studies.front();
  for (std::size_t s = 1; s < studies.size(); ++s) {
    const auto& other = studies[s];
    if (other.study.fits.im_label != first.study.fits.im_label) {
      throw InvalidInput(other.file + ": its intensity measure is " + other.study.fits.im_label +
                         ", " + first.file + "'s " + first.study.fits.im_label +
                         ": weighted studies share one measure");
    }
    const auto names = [](const WeightedStudy& study) {
      std::vector<std::string> list;
      for (const auto& state : study.study.fits.states) list.push_back(state.name);
      return list;
    };
    if (names(other) != names(first)) {
      throw InvalidInput(other.file + ": its limit states are not " + first.file +
                         "'s (the same names, in the same order of severity)");
    }
  }
}

}  // namespace

int run_risk(const RiskOptions& options, std::ostream& out, std::ostream& log) {
  std::vector<WeightedStudy> studies;
  for (const auto& spec : study_specs(options)) {
    studies.push_back(
        {read_risk_study_isolated(spec.file, kRiskReadLimit), spec.file.string(), spec.weight});
  }
  check_studies_match(studies);
  const FragilityFits& fits = studies.front().study.fits;
  HazardRequest request;
  request.study = study_imt(studies.front().file, fits.im_name, fits.im_period_s, fits.im_damping);
  request.imt = options.imt;
  request.site = options.site;
  RiskReport report;
  report.hazard_file = options.hazard.string();
  report.hazard = read_hazard_file(options.hazard, request);
  std::vector<OutputTarget> targets;
  if (options.output) {
    targets.push_back({*options.output, "--output", "a blockfrag risk JSON",
                       [](const auto& path) { return file_starts_with(path, kRiskJsonStart); }});
  }
  if (options.csv) {
    targets.push_back({*options.csv, "--csv", "a blockfrag risk CSV",
                       [](const auto& path) { return file_starts_with(path, kRiskCsvStart); }});
  }
  std::vector<CommandInput> inputs{{options.hazard, "the hazard file"}};
  for (const auto& study : studies) inputs.push_back({study.file, "a study output"});
  check_output_targets(targets, inputs);

  for (const auto& study : studies)
    report.studies.push_back(assess_study(study, report.hazard.curve));
  report.combined = combine_studies(report.studies);
  print_risk_table(report, out);
  out.flush();
  if (options.output) write_file_atomically(*options.output, risk_json(report));
  if (options.csv) write_file_atomically(*options.csv, risk_csv(report));
  for (const auto& study : report.studies) {
    for (const auto& state : study.states) {
      if (!state.fit)
        log << "note: " << study.file << ": " << state.name << " has no fit (" << state.fit_status
            << "): its risk is from the points only\n";
    }
  }
  log.flush();
  return 0;
}

}  // namespace blockfrag
