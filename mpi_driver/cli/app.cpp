#include "mpi_driver/cli/app.hpp"

#include <cmath>
#include <exception>
#include <functional>
#include <iostream>
#include <memory>
#include <string>

#include <CLI/CLI.hpp>

#include "blockfrag/version.hpp"
#include "engine/errors.hpp"
#include "mpi_driver/accuracy/accuracy_settings.hpp"
#include "mpi_driver/cli/accuracy_command.hpp"
#include "mpi_driver/cli/bench_command.hpp"
#include "mpi_driver/cli/exit_codes.hpp"
#include "mpi_driver/cli/export_command.hpp"
#include "mpi_driver/cli/risk_command.hpp"
#include "mpi_driver/cli/run_command.hpp"
#include "mpi_driver/cli/simulate_command.hpp"
#include "mpi_driver/cli/spectrum_command.hpp"
#include "mpi_driver/cli/statics_command.hpp"

namespace blockfrag {

namespace {

// A finite number > 0: CLI11's PositiveNumber lets "nan" and "inf" through.
CLI::Validator positive_finite_number(const std::string& name) {
  return CLI::Validator(
      [](const std::string& text) -> std::string {
        try {
          std::size_t used = 0;
          const double x = std::stod(text, &used);
          if (used == text.size() && std::isfinite(x) && x > 0) return {};
        } catch (const std::exception&) {
        }
        return "must be a positive number (got " + text + ")";
      },
      name);
}

std::string valid_setting(const std::string& text) {
  try {
    parse_solver_setting(text);
    return {};
  } catch (const InvalidInput& error) {
    return error.what();
  }
}

void add_simulate_command(CLI::App& app, std::function<int()>& command) {
  auto options = std::make_shared<SimulateOptions>();
  CLI::App* simulate = app.add_subcommand("simulate", "Simulate one scene and print its summary");
  simulate->add_option("scene", options->scene_path, "Scene file (JSON)")
      ->required()
      ->check(CLI::ExistingFile);
  simulate->add_flag("--summary-json", options->summary_json,
                     "Print the summary as exactly one JSON object on stdout, nothing else");
  auto* history = simulate
                      ->add_option("--history", options->history_path,
                                   "Also write the time history to this CSV file")
                      ->type_name("FILE.csv");
  simulate
      ->add_option("--history-interval", options->history_interval, "Time between history rows, s")
      ->capture_default_str()
      ->check(positive_finite_number("SECONDS"))
      ->needs(history);
  simulate->callback(
      [options, &command] { command = [options] { return run_simulate(*options, std::cout); }; });
}

// A finite number >= 0.
CLI::Validator non_negative_finite_number(const std::string& name) {
  return CLI::Validator(
      [](const std::string& text) -> std::string {
        try {
          std::size_t used = 0;
          const double x = std::stod(text, &used);
          if (used == text.size() && std::isfinite(x) && x >= 0) return {};
        } catch (const std::exception&) {
        }
        return "must be a number >= 0 (got " + text + ")";
      },
      name);
}

void add_statics_command(CLI::App& app, std::function<int()>& command) {
  auto options = std::make_shared<StaticsOptions>();
  auto coefficient = std::make_shared<double>(0.0);
  CLI::App* statics = app.add_subcommand(
      "statics",
      "The block at rest under its reservoir: loads, yield accelerations, safety factors");
  statics->add_option("scene", options->scene_path, "Scene file (JSON)")
      ->required()
      ->check(CLI::ExistingFile);
  auto* given = statics
                    ->add_option("--coefficient", *coefficient,
                                 "Seismic coefficient K: also the pseudo-static safety factors")
                    ->check(non_negative_finite_number("K"));
  statics->add_flag("--summary-json", options->summary_json,
                    "Print exactly one JSON object on stdout, nothing else");
  statics->callback([options, coefficient, given, &command] {
    if (given->count() > 0) options->coefficient = *coefficient;
    command = [options] { return run_statics(*options, std::cout); };
  });
}

void add_run_command(CLI::App& app, std::function<int()>& command,
                     const AtomicWriteHooks& checkpoint_hooks) {
  auto options = std::make_shared<RunOptions>();
  options->checkpoint_hooks = checkpoint_hooks;
  CLI::App* run = app.add_subcommand("run", "Run a batch study (under mpirun for several ranks)");
  run->add_option("study", options->study_path, "Study config (JSON)")
      ->required()
      ->check(CLI::ExistingFile);
  run->add_option("--output", options->output,
                  "Output HDF5 file (replaces the config's \"output\")");
  run->add_option("--samples-per-level", options->samples_per_level,
                  "Samples per intensity level (replaces the config's \"samples_per_level\")")
      ->check(CLI::PositiveNumber);
  run->add_option("--max-chunk", options->max_chunk,
                  "Largest number of samples a worker gets per request (default: adapted to the "
                  "measured speed; results never depend on it)")
      ->check(CLI::Range(1, 1 << 20));
  run->callback(
      [options, &command] { command = [options] { return run_study_command(*options); }; });
}

void add_accuracy_command(CLI::App& app, std::function<int()>& command) {
  auto options = std::make_shared<AccuracyOptions>();
  CLI::App* accuracy = app.add_subcommand("accuracy",
                                          "Work-precision study: every scene of a suite with every "
                                          "solver setting, against a reference");
  accuracy
      ->add_option("suite", options->suite_path,
                   "Scene suite (JSON), e.g. configs/accuracy_suite.json")
      ->required()
      ->check(CLI::ExistingFile);
  accuracy
      ->add_option("--setting", options->settings,
                   "Run only this setting (repeatable): rk4:DT, adaptive:TOL, gsl_rkf45:TOL or "
                   "gsl_rk8pd:TOL")
      ->type_name("METHOD:VALUE")
      ->check(CLI::Validator(valid_setting, "METHOD:VALUE"));
  accuracy->add_option("--output", options->output_path, "HDF5 file to write")
      ->capture_default_str();
  accuracy->add_option("--table", options->table_path, "Also write the markdown table to this file")
      ->type_name("FILE.md");
  accuracy
      ->add_option("--reference-tolerance", options->reference_tolerance,
                   "Tolerance of the reference (adaptive) and of its check (gsl_rk8pd)")
      ->capture_default_str()
      ->check(positive_finite_number("TOL"));
  accuracy
      ->add_option("--min-batch-ms", options->min_batch_ms,
                   "Each scene is repeated until a timed batch takes at least this long (at "
                   "most 10 s)")
      ->capture_default_str()
      ->check(positive_finite_number("MS"))
      ->check(CLI::Range(0.0, kMaxMinBatchMilliseconds));
  accuracy
      ->add_option(
          "--fragility-study", options->fragility_study,
          "Also compare this study's fragility curves per setting, and MC against LHS convergence")
      ->check(CLI::ExistingFile)
      ->type_name("STUDY.json");
  accuracy
      ->add_option("--replicates", options->replicates,
                   "Seeds per design and size (--fragility-study)")
      ->capture_default_str()
      ->check(CLI::Range(1, 10000));
  accuracy
      ->add_option("--design-sizes", options->design_sizes,
                   "Samples per level compared (--fragility-study)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  accuracy
      ->add_option("--reference-samples", options->reference_samples_per_level,
                   "Samples per level of the Latin hypercube reference (--fragility-study)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  accuracy->callback([options, &command] {
    command = [options] { return run_accuracy(*options, std::cout, std::cerr); };
  });
}

void add_bench_command(CLI::App& app, std::function<int()>& command) {
  auto options = std::make_shared<BenchOptions>();
  CLI::App* bench =
      app.add_subcommand("bench", "Time one scene: N runs after a warm-up, one JSON object");
  bench->add_option("scene", options->scene_path, "Scene file (JSON)")
      ->required()
      ->check(CLI::ExistingFile);
  bench->add_option("--repeat", options->repeat, "Timed runs (at most 1000000)")
      ->capture_default_str()
      ->check(CLI::Range(1L, kMaxBenchRepeats));
  bench->callback(
      [options, &command] { command = [options] { return run_bench(*options, std::cout); }; });
}

void add_export_command(CLI::App& app, std::function<int()>& command) {
  auto options = std::make_shared<ExportOptions>();
  CLI::App* export_ = app.add_subcommand(
      "export", "Write a study's fragility fits as a pelicun damage model or an OpenQuake model");
  export_->add_option("results", options->results, "The study's HDF5 output")->required();
  auto format = std::make_shared<std::string>();
  export_
      ->add_option("--format", *format,
                   "pelicun: fragility.csv and fragility.json in --output; openquake: an NRML "
                   "0.5 fragility model in --output")
      ->required()
      ->check(CLI::IsMember({"pelicun", "openquake"}));
  export_
      ->add_option("--output", options->output,
                   "pelicun: the folder (created if missing); openquake: the XML file")
      ->required()
      ->type_name("PATH");
  export_->add_option("--id", options->id,
                      "The component (pelicun) and taxonomy (OpenQuake) ID; default "
                      "BF.BLOCK.<config hash>");
  export_->add_flag("--fitted-only", options->fitted_only,
                    "Export the limit states that have a fit and name the others, instead of "
                    "refusing a limit state without a fit");
  export_->add_flag("--nested", options->nested,
                    "Export the fit of all limit states with one common beta (curves that do "
                    "not cross) instead of each state's own fit");
  export_->callback([options, format, &command] {
    options->format = *format == "openquake" ? ExportFormat::openquake : ExportFormat::pelicun;
    command = [options] { return run_export(*options, std::cout, std::cerr); };
  });
}

void add_risk_command(CLI::App& app, std::function<int()>& command) {
  auto options = std::make_shared<RiskOptions>();
  CLI::App* risk = app.add_subcommand(
      "risk",
      "Integrate a study's fragility against a site's hazard curve: each limit state's "
      "mean annual frequency");
  risk->add_option("results", options->results, "The study's HDF5 output");
  risk->add_option("--study", options->studies,
                   "A study output and its weight, the share of the year (repeatable; instead "
                   "of RESULTS, weights summing to 1)")
      ->type_name("FILE.h5:WEIGHT");
  risk->add_option("--hazard", options->hazard,
                   "The site's hazard curve: an OpenQuake hazard-curve CSV, a USGS hazard "
                   "service JSON, or a two-column CSV of im and annual frequency")
      ->required()
      ->type_name("FILE");
  risk->add_option("--imt", options->imt,
                   "The hazard curve's measure (PGA, PGV, SA(T) or SA0P2): a two-column table's, "
                   "or the curve to take from a USGS answer");
  risk->add_option("--site", options->site, "The row (site) of an OpenQuake file, from 0")
      ->capture_default_str()
      ->check(CLI::Range(std::size_t{0}, std::size_t{100'000'000}));
  risk->add_option("--output", options->output, "Also write everything as JSON")
      ->type_name("FILE.json");
  risk->add_option("--csv", options->csv, "Also write one row per limit state and method")
      ->type_name("FILE.csv");
  risk->callback([options, &command] {
    command = [options] { return run_risk(*options, std::cout, std::cerr); };
  });
}

void add_spectrum_command(CLI::App& app, std::function<int()>& command,
                          const AtomicWriteHooks& checkpoint_hooks) {
  auto options = std::make_shared<SpectrumOptions>();
  options->checkpoint_hooks = checkpoint_hooks;
  CLI::App* spectrum =
      app.add_subcommand("spectrum",
                         "Map an overturning spectrum and bisect its boundaries (under mpirun for "
                         "several ranks)");
  spectrum->add_option("spectrum", options->spectrum_path, "Spectrum config (JSON)")
      ->required()
      ->check(CLI::ExistingFile);
  spectrum->add_option("--output", options->output,
                       "Output HDF5 file (replaces the config's \"output\")");
  spectrum
      ->add_option("--max-chunk", options->max_chunk,
                   "Largest number of points a worker gets per request (default: adapted to the "
                   "measured speed; results never depend on it)")
      ->check(CLI::Range(1, 1 << 20));
  spectrum->callback(
      [options, &command] { command = [options] { return run_spectrum_command(*options); }; });
}

// Declares every subcommand on `app`; once one has been parsed, `command` runs it.
void add_subcommands(CLI::App& app, std::function<int()>& command,
                     const AtomicWriteHooks& checkpoint_hooks) {
  add_simulate_command(app, command);
  add_statics_command(app, command);
  add_run_command(app, command, checkpoint_hooks);
  add_accuracy_command(app, command);
  add_bench_command(app, command);
  add_export_command(app, command);
  add_risk_command(app, command);
  add_spectrum_command(app, command, checkpoint_hooks);
}

}  // namespace

int run_command_line(int argc, char** argv, const AtomicWriteHooks& checkpoint_hooks) {
  CLI::App app{"blockfrag: rigid-block rocking, sliding and overturning under ground pulses"};
  app.set_version_flag("--version",
                       std::string("blockfrag ") + kVersion + " (commit " + build_commit() + ")");
  app.require_subcommand(1);

  std::function<int()> command;
  add_subcommands(app, command, checkpoint_hooks);

  try {
    app.parse(argc, argv);
    return command();
  } catch (const CLI::ParseError& error) {
    // --help and --version arrive here too, with exit code 0.
    return app.exit(error) == 0 ? 0 : exit_code_bad_input;
  } catch (const InvalidInput& error) {
    std::cerr << error.what() << '\n';
    return exit_code_bad_input;
  } catch (const ContractViolation& error) {
    std::cerr << "blockfrag: internal error (a bug, please report it with the input): "
              << error.what() << '\n';
    return exit_code_internal_error;
  } catch (const std::exception& error) {
    std::cerr << "blockfrag: " << error.what() << '\n';
    return exit_code_file_failure;
  }
}

}  // namespace blockfrag
