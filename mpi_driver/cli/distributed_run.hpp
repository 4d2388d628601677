// What the distributed commands (`run`, `spectrum`) share: MPI's lifetime, the claim on the output
// before any work (its verdict, the lock, a killed run's leftovers), the exit code of an error, and
// the ends of a run (an error inside it aborts every rank; rank 0 finishes alone and every rank
// learns the exit code).
#pragma once

#include <mpi.h>

#include <cstdint>
#include <exception>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "mpi_driver/parallel/study_lock.hpp"

namespace blockfrag {

// MPI_Init in the constructor, MPI_Finalize in the destructor, so every return and every exception
// leaves MPI finalised.
class MpiSession {
 public:
  MpiSession();
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

 private:
  bool owner_ = false;
  std::filesystem::path session_folder_;  // a singleton's own Open MPI session tree, if made
};

enum class OutputVerdict : int { run = 0, already_complete = 1, refused = 2 };

struct OutputClaim {
  OutputVerdict verdict = OutputVerdict::run;
  std::string message;              // rank 0: why it is refused, or the "already complete" line
  std::unique_ptr<StudyLock> lock;  // rank 0, held when the verdict is run
};

// Collective over comm. Rank 0 looks at the output before any work: a folder it can write in, no
// link at its name (unless the link leads to this run's finished output, hash `hash`), and no file
// there that belongs to anything but this run; a finished output with this hash means there is
// nothing to do. Then it takes the lock and, holding it, removes the temporary files a killed
// writer of the output or of `own_files` left. `kind` names the output in messages ("study",
// "spectrum"). Every rank learns the verdict.
OutputClaim claim_output(MPI_Comm comm, const std::filesystem::path& output, std::uint64_t hash,
                         const std::string& kind,
                         const std::vector<std::filesystem::path>& own_files);

// The exit code for an error of this kind (mpi_driver/cli/exit_codes.hpp).
int exit_code_for(const std::exception& error);

// Any error inside the distributed run leaves other ranks waiting on messages: abort them all,
// with the exit code of the error's kind.
[[noreturn]] void abort_run(MPI_Comm comm, int rank, const std::exception& error);

// Collective over comm: bad input found on every rank before any work. Rank 0 reports it on
// stderr, then all ranks return exit code 2 together: mpirun aborts the job at the first
// non-zero exit, which could otherwise kill rank 0 before its message is out.
int refuse_bad_input(MPI_Comm comm, int rank, const std::exception& error);

// Collective: rank 0 runs `finish` (writing the output) alone; whatever happens there, every rank
// learns its exit code (a rank left waiting on the broadcast would hang the job), then rank 0
// rethrows its error, to be reported the usual way.
int finish_on_rank0(MPI_Comm comm, const std::function<int()>& finish);

}  // namespace blockfrag
