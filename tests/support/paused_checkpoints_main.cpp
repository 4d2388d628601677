// blockfrag with every checkpoint write held between its complete temporary file and the rename,
// so that a test can land a kill inside a write (tests/mpi/kill_resume_test.sh):
//
//   blockfrag_paused_checkpoints SECONDS COMMAND [ARGUMENTS...]
//
// runs `blockfrag COMMAND ARGUMENTS...` with that pause. The shipped executable has no such pause:
// only this test executable passes one to run_command_line.
#include <cmath>
#include <cstdlib>
#include <iostream>

#include "mpi_driver/cli/app.hpp"
#include "mpi_driver/cli/exit_codes.hpp"

int main(int argc, char** argv) {
  char* end = nullptr;
  const double pause_s = argc > 1 ? std::strtod(argv[1], &end) : -1.0;
  if (argc < 3 || end == argv[1] || *end != '\0' || !std::isfinite(pause_s) || pause_s < 0.0) {
    std::cerr << "usage: blockfrag_paused_checkpoints SECONDS COMMAND [ARGUMENTS...]\n";
    return blockfrag::exit_code_bad_input;
  }
  blockfrag::AtomicWriteHooks hooks;
  hooks.pause_before_rename_s = pause_s;
  // argv[1] gives way to the program name: CLI11 reads argv[0] as the name, the rest as arguments.
  argv[1] = argv[0];
  return blockfrag::run_command_line(argc - 1, argv + 1, hooks);
}
