#include "mpi_driver/cli/distributed_run.hpp"

#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>
#include <system_error>

#include "engine/errors.hpp"
#include "mpi_driver/cli/exit_codes.hpp"
#include "mpi_driver/config/study_hash.hpp"
#include "mpi_driver/io/atomic_file.hpp"
#include "mpi_driver/io/study_output.hpp"

namespace blockfrag {
namespace {

OutputVerdict judge_existing_output(const std::filesystem::path& path, std::uint64_t hash,
                                    const std::string& kind, std::string& message) {
  const std::string output = path.string();
  if (const auto problem = folder_write_problem(path)) {
    message = output + ": " + *problem;
    return OutputVerdict::refused;
  }
  std::error_code error;
  const auto status = std::filesystem::symlink_status(path, error);
  if (!std::filesystem::exists(status)) return OutputVerdict::run;
  const bool link = std::filesystem::is_symlink(status);
  if (!link && !std::filesystem::is_regular_file(status)) {
    message = output +
              ": refusing to replace something that is not a regular file; choose another --output";
    return OutputVerdict::refused;
  }
  const std::string found = output_config_hash(path);
  if (found == hash_to_hex(hash)) {
    message = kind + " already complete: " + output + " (config hash " + found + ")";
    return OutputVerdict::already_complete;
  }
  if (link) {
    message = output + ": is a symbolic link" +
              (found.empty() ? " that does not lead to a blockfrag " + kind + " output"
                             : " to another " + kind + "'s output (config hash " + found + ")") +
              "; blockfrag replaces only its own files: remove the link or choose another --output";
    return OutputVerdict::refused;
  }
  message =
      output + ": refusing to replace an existing file that is not this " + kind + "'s output" +
      (found.empty() ? " (not a blockfrag " + kind + " output)"
                     : " (config hash " + found + ", this config " + hash_to_hex(hash) + ")") +
      "; remove it or choose another --output";
  return OutputVerdict::refused;
}

bool launched_by_mpirun_or_srun() {
  for (const char* launched : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK"}) {
    if (std::getenv(launched)) return true;
  }
  return false;
}

// A run started without mpirun or srun is a singleton: it talks to no other process, yet Open
// MPI's defaults start a helper daemon and probe UCX's transports for it, about 0.4 s of waiting
// at every start (a 2-scene study took 0.5 to 0.65 s, 0.13 s without them). Such a run gets the
// messaging layer for one machine and no daemon, unless the user's environment says otherwise; a
// launched rank keeps whatever its launcher and the user chose.
void prefer_quick_singleton_start() {
  setenv("OMPI_MCA_ess_singleton_isolated", "1", 0);
  setenv("OMPI_MCA_pml", "ob1", 0);
}

// Open MPI gives every isolated singleton one session directory (job family 0), which each
// creates at its start and removes at its end: of two starting together, one can find it made
// between its look and its mkdir, and MPI_Init fails ("A call to mkdir was unable to create the
// desired directory ... File exists"; 3 of 200 runs started 8 at a time). Each singleton gets a
// session tree of its own, a fresh folder in the temporary directory, removed after MPI_Finalize;
// a session directory the user chose is kept.
std::filesystem::path own_singleton_session_folder() {
  if (std::getenv("OMPI_MCA_orte_tmpdir_base")) return {};
  const char* tmpdir = std::getenv("TMPDIR");
  std::string pattern = std::string(tmpdir && *tmpdir ? tmpdir : "/tmp") + "/blockfrag-mpi-XXXXXX";
  if (!mkdtemp(pattern.data())) return {};  // Open MPI's own default then
  setenv("OMPI_MCA_orte_tmpdir_base", pattern.c_str(), 1);
  return pattern;
}

}  // namespace

MpiSession::MpiSession() {
  int initialized = 0;
  MPI_Initialized(&initialized);
  if (!initialized) {
    if (!launched_by_mpirun_or_srun()) {
      prefer_quick_singleton_start();
      session_folder_ = own_singleton_session_folder();
    }
    MPI_Init(nullptr, nullptr);
    owner_ = true;
  }
}

MpiSession::~MpiSession() {
  if (!owner_) return;
  MPI_Finalize();
  if (!session_folder_.empty()) {
    std::error_code ignored;
    std::filesystem::remove_all(session_folder_, ignored);
  }
}

OutputClaim claim_output(MPI_Comm comm, const std::filesystem::path& output, std::uint64_t hash,
                         const std::string& kind,
                         const std::vector<std::filesystem::path>& own_files) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  OutputClaim claim;
  if (rank == 0) {
    claim.verdict = judge_existing_output(output, hash, kind, claim.message);
    if (claim.verdict == OutputVerdict::run) {
      claim.lock = std::make_unique<StudyLock>(output);
      if (claim.lock->busy()) {
        claim.message = output.string() + ": another run of this " + kind +
                        " is in progress (it holds " + claim.lock->path().string() +
                        "); wait for it to end, or stop it first";
        claim.verdict = OutputVerdict::refused;
      } else if (!claim.lock->held()) {
        claim.message = output.string() + ": the lock file " + claim.lock->path().string() + " " +
                        claim.lock->problem();
        claim.verdict = OutputVerdict::refused;
      } else {
        // Holding the lock, no other writer of these files runs: a killed one's leftovers can go.
        remove_stale_temporaries(output);
        for (const auto& file : own_files) remove_stale_temporaries(file);
      }
    }
  }
  int verdict = static_cast<int>(claim.verdict);
  MPI_Bcast(&verdict, 1, MPI_INT, 0, comm);
  claim.verdict = static_cast<OutputVerdict>(verdict);
  return claim;
}

int exit_code_for(const std::exception& error) {
  if (dynamic_cast<const InvalidInput*>(&error)) return exit_code_bad_input;
  if (dynamic_cast<const ContractViolation*>(&error)) return exit_code_internal_error;
  return exit_code_file_failure;
}

void abort_run(MPI_Comm comm, int rank, const std::exception& error) {
  const bool bug = dynamic_cast<const ContractViolation*>(&error) != nullptr;
  std::cerr << "blockfrag: rank " << rank << ": "
            << (bug ? "internal error (a bug, please report it with the input): " : "")
            << error.what() << '\n'
            << std::flush;
  MPI_Abort(comm, exit_code_for(error));
  std::abort();
}

int refuse_bad_input(MPI_Comm comm, int rank, const std::exception& error) {
  if (rank == 0) std::cerr << error.what() << '\n' << std::flush;
  MPI_Barrier(comm);
  return exit_code_bad_input;
}

int finish_on_rank0(MPI_Comm comm, const std::function<int()>& finish) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  int exit_code = exit_code_success;
  std::exception_ptr failure;
  if (rank == 0) {
    try {
      exit_code = finish();
    } catch (const std::exception& error) {
      failure = std::current_exception();
      exit_code = exit_code_for(error);
    }
  }
  MPI_Bcast(&exit_code, 1, MPI_INT, 0, comm);
  if (failure) std::rethrow_exception(failure);
  return exit_code;
}

}  // namespace blockfrag
