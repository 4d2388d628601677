// The blockfrag command line: the subcommands and their options, and the one place where exceptions
// become messages and exit codes. app.cpp is the one file of the driver that includes CLI11, a
// large header-only library that costs each file including it seconds of compile time.
//
// Exit codes:
//   0  success
//   1  any other error (a file that cannot be read or written, ...)
//   2  a bad scene or config (every message on stderr names the file, the JSON path and the rule)
//      or a bad command line
//   3  the simulation failed (its status is "failed"; the summary is still printed)
//   4  a study was interrupted (SIGTERM, SIGINT) after writing its checkpoint: rerun the same
//   command
#pragma once

#include "mpi_driver/io/atomic_file.hpp"

namespace blockfrag {

// `checkpoint_hooks` reach every checkpoint write of `run` and `spectrum`: the executable passes
// none; a test's own executable (tests/support/paused_checkpoints_main.cpp) passes a pause, to land
// a kill inside a write.
int run_command_line(int argc, char** argv, const AtomicWriteHooks& checkpoint_hooks = {});

}  // namespace blockfrag
