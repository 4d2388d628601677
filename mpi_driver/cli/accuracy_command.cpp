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
#include "mpi_driver/io/hdf5_file.hpp"
#include "mpi_driver/io/output_target.hpp"

namespace blockfrag {

namespace {

// The settings whose fragility curves are compared when the command line names none: the paper's,
// the production default, and one looser and one tighter setting of each kind.
std::vector<SolverSetting> default_fragility_settings() {
  return {{Method::rk4, 2.5e-4},    {Method::adaptive, 1e-4},  {Method::adaptive, 1e-6},
          {Method::adaptive, 1e-8}, {Method::gsl_rkf45, 1e-8}, {Method::gsl_rk8pd, 1e-8}};
}

// An earlier accuracy study's output: an HDF5 file with the reference's method at its root.
bool is_accuracy_output(const std::filesystem::path& path) {
  if (!file_starts_with(path, "\x89HDF\r\n\x1a\n")) return false;
  try {
    read_root_string_attribute(path, "reference_method");
    return true;
  } catch (const Hdf5Error&) {
    return false;
  }
}

// An earlier accuracy study's table (write_accuracy_table's first line).
bool is_accuracy_table(const std::filesystem::path& path) {
  return file_starts_with(path, "Reference: ", " scenes. Largest |check - reference|: ");
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
  // A bad study config, and an output that must not be replaced, are refused before the long part
  // starts.
  if (options.fragility_study) {
    parse_study_config(read_json_file(*options.fragility_study), options.fragility_study->string());
  }
  std::vector<OutputTarget> targets = {
      {options.output_path, "--output", "an accuracy study's HDF5 output", is_accuracy_output}};
  if (options.table_path) {
    targets.push_back(
        {*options.table_path, "--table", "an accuracy study's table", is_accuracy_table});
  }
  std::vector<CommandInput> inputs = {{options.suite_path, "the suite"}};
  if (options.fragility_study) inputs.push_back({*options.fragility_study, "the fragility study"});
  check_output_targets(targets, inputs);
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
