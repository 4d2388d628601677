#include "mpi_driver/cli/app.hpp"

#include <exception>
#include <functional>
#include <iostream>

#include <CLI/CLI.hpp>

#include "engine/errors.hpp"
#include "mpi_driver/cli/accuracy_command.hpp"
#include "mpi_driver/cli/bench_command.hpp"
#include "mpi_driver/cli/exit_codes.hpp"
#include "mpi_driver/cli/export_command.hpp"
#include "mpi_driver/cli/run_command.hpp"
#include "mpi_driver/cli/simulate_command.hpp"
#include "mpi_driver/cli/spectrum_command.hpp"

namespace blockfrag {

int run_command_line(int argc, char** argv) {
  CLI::App app{"blockfrag: rigid-block rocking, sliding and overturning under ground pulses"};
  app.set_version_flag("--version", std::string("blockfrag ") + BLOCKFRAG_VERSION);
  app.require_subcommand(1);

  std::function<int()> command;
  add_simulate_command(app, command);
  add_run_command(app, command);
  add_accuracy_command(app, command);
  add_bench_command(app, command);
  add_export_command(app, command);
  add_spectrum_command(app, command);

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
