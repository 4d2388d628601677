// The blockfrag executable's exit codes, one place for all commands (documented in the README).
#pragma once

namespace blockfrag {

inline constexpr int exit_code_success = 0;
inline constexpr int exit_code_file_failure = 1;       // a file that cannot be read or written
inline constexpr int exit_code_bad_input = 2;          // a bad scene, study, record or command line
inline constexpr int exit_code_simulation_failed = 3;  // a scene's simulation failed
inline constexpr int exit_code_interrupted = 4;        // a study stopped by SIGTERM or SIGINT
inline constexpr int exit_code_internal_error = 5;     // a broken internal contract: a bug

}  // namespace blockfrag
