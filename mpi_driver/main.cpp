// The blockfrag executable. It stays thin: each subcommand lives in its own file and declares itself
// with one add_*_command call below; only this function turns exceptions into messages and exit codes.
//
// Exit codes:
//   0  success
//   1  any other error (a file that cannot be read or written, ...)
//   2  a bad scene or config (every message on stderr names the file, the JSON path and the rule)
//      or a bad command line
//   3  the simulation failed (its status is "failed"; the summary is still printed)
//   4  a study was interrupted (SIGTERM, SIGINT) after writing its checkpoint: rerun the same command
#include <exception>
#include <functional>
#include <iostream>

#include <CLI/CLI.hpp>

#include "mpi_driver/cli/accuracy_command.hpp"
#include "mpi_driver/cli/bench_command.hpp"
#include "mpi_driver/config/config_reader.hpp"
#include "mpi_driver/cli/run_command.hpp"
#include "mpi_driver/cli/simulate_command.hpp"

namespace {

constexpr int exit_code_other_error = 1;
constexpr int exit_code_bad_input = 2;

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"blockfrag: rigid-block rocking, sliding and overturning under ground pulses"};
  app.set_version_flag("--version", std::string("blockfrag ") + BLOCKFRAG_VERSION);
  app.require_subcommand(1);

  std::function<int()> command;
  blockfrag::add_simulate_command(app, command);
  blockfrag::add_run_command(app, command);
  blockfrag::add_accuracy_command(app, command);
  blockfrag::add_bench_command(app, command);

  try {
    app.parse(argc, argv);
    return command();
  } catch (const CLI::ParseError& error) {
    // --help and --version arrive here too, with exit code 0.
    return app.exit(error) == 0 ? 0 : exit_code_bad_input;
  } catch (const blockfrag::ConfigError& error) {
    std::cerr << error.what() << '\n';
    return exit_code_bad_input;
  } catch (const std::exception& error) {
    std::cerr << "blockfrag: " << error.what() << '\n';
    return exit_code_other_error;
  }
}
