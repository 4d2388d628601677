#include "mpi_driver/cli/accuracy_command.hpp"

#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>

#include "mpi_driver/accuracy/accuracy_fragility.hpp"
#include "mpi_driver/accuracy/accuracy_output.hpp"
#include "mpi_driver/accuracy/accuracy_settings.hpp"
#include "mpi_driver/accuracy/accuracy_study.hpp"
#include "mpi_driver/accuracy/accuracy_suite.hpp"
#include "mpi_driver/config/config_reader.hpp"
#include "mpi_driver/config/study_config.hpp"
#include "mpi_driver/io/atomic_file.hpp"

namespace blockfrag {

namespace {

// The settings whose fragility curves are compared when the command line names none: the paper's,
// the production default, and one looser and one tighter setting of each kind.
std::vector<SolverSetting> default_fragility_settings() {
  return {{Method::rk4, 2.5e-4},    {Method::adaptive, 1e-4},  {Method::adaptive, 1e-6},
          {Method::adaptive, 1e-8}, {Method::gsl_rkf45, 1e-8}, {Method::gsl_rk8pd, 1e-8}};
}

void write_fragility_sections(std::ostream& out, const AccuracyOptions& options,
                              const AccuracyStudyOptions& study,
                              const std::vector<SolverSetting>& requested, std::ostream& log) {
  const nlohmann::json document = read_json_file(*options.fragility_study);
  const StudyConfig config = parse_study_config(document, options.fragility_study->string());
  log << "accuracy: fragility of " << options.fragility_study->string() << std::endl;
  const auto rows =
      compare_fragility(config, requested.empty() ? default_fragility_settings() : requested,
                        {Method::adaptive, study.reference_tolerance});
  out << "\nFragility of " << options.fragility_study->filename().string() << " ("
      << config.total_samples() << " samples) with each setting against "
      << setting_label({Method::adaptive, study.reference_tolerance}) << ":\n\n";
  write_fragility_table(out, rows);
  log << "accuracy: design convergence" << std::endl;
  const std::vector<std::int64_t> sizes(options.design_sizes.begin(), options.design_sizes.end());
  const auto convergence =
      design_convergence(document, sizes, options.replicates, options.reference_samples_per_level);
  out << "\nMonte Carlo against Latin hypercube: " << options.replicates
      << " seeds per row, errors against one "
      << "Latin hypercube run of " << options.reference_samples_per_level
      << " samples per level:\n\n";
  write_design_convergence_table(out, convergence);
}

}  // namespace

int run_accuracy(const AccuracyOptions& options, std::ostream& out, std::ostream& log) {
  const AccuracySuite suite = read_accuracy_suite(options.suite_path);
  // A bad study config is refused before the long part starts.
  if (options.fragility_study) {
    parse_study_config(read_json_file(*options.fragility_study), options.fragility_study->string());
  }
  AccuracyStudyOptions study_options;
  std::vector<SolverSetting> requested;
  for (const auto& text : options.settings) requested.push_back(parse_solver_setting(text));
  if (!requested.empty()) study_options.settings = requested;
  study_options.reference_tolerance = options.reference_tolerance;
  study_options.min_batch_seconds = options.min_batch_ms * 1e-3;
  study_options.progress = [&log](const std::string& label) {
    log << "accuracy: " << label << std::endl;
  };

  const AccuracyStudy study = run_accuracy_study(suite, study_options);
  write_accuracy_hdf5(options.output_path, study, options.suite_path.filename().string());
  std::ostringstream table;
  write_accuracy_table(table, study);
  if (options.fragility_study)
    write_fragility_sections(table, options, study_options, requested, log);
  out << table.str();
  out.flush();
  if (options.table_path) write_file_atomically(*options.table_path, table.str());
  return 0;
}

}  // namespace blockfrag
