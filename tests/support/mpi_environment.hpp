// MPI for a whole test executable (a singleton process: no mpirun needed). An inline variable, so
// the environment is registered once however many of the executable's files include this: MPI
// may be initialised only once.
#pragma once

#include <mpi.h>

#include <gtest/gtest.h>

namespace blockfrag::testing {

class MpiEnvironment : public ::testing::Environment {
 public:
  void SetUp() override { MPI_Init(nullptr, nullptr); }
  void TearDown() override { MPI_Finalize(); }
};

[[maybe_unused]] inline auto* const mpi_environment =
    ::testing::AddGlobalTestEnvironment(new MpiEnvironment);

}  // namespace blockfrag::testing
