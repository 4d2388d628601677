// The names of the files a run keeps beside its output: no output, and none of another output's
// files, can ever have one of them, so a run reads, replaces or removes only its own.
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "mpi_driver/config/output_name.hpp"
#include "mpi_driver/io/record_spool.hpp"
#include "mpi_driver/parallel/bisection_state.hpp"
#include "mpi_driver/parallel/checkpoint.hpp"
#include "mpi_driver/parallel/spectrum_runner.hpp"

namespace blockfrag {
namespace {

std::vector<std::filesystem::path> side_files_of(const std::filesystem::path& output) {
  const SpectrumFiles spectrum = SpectrumFiles::for_output(output);
  auto lock = output;
  lock += ".lock";
  return {checkpoint_path_for(output),
          record_spool_path_for(output),
          spectrum.bisection,
          spectrum.minimum,
          spectrum.round_checkpoint,
          spectrum.round_records,
          lock};
}

TEST(SideFileNames, NoOutputMayHaveTheNameOfAnOutputsFile) {
  for (const auto& file : side_files_of("results/X.h5")) {
    EXPECT_TRUE(output_name_problem(file.string())) << file;
  }
  EXPECT_TRUE(output_name_problem("X.h5.tmp.Ab12Cd"));  // a temporary file's name
  EXPECT_FALSE(output_name_problem("X.h5"));
  EXPECT_FALSE(output_name_problem("X.h5.round"));
  EXPECT_FALSE(output_name_problem("notes.checkpoints"));
}

TEST(SideFileNames, ASpectrumsRoundFilesAreNotAnotherOutputsFiles) {
  // A study whose output is X.h5.round kept X.h5.round.checkpoint and X.h5.round.records, which a
  // spectrum X.h5 once took for its round's files.
  std::set<std::filesystem::path> study;
  for (const auto& file : side_files_of("X.h5.round")) study.insert(file);
  for (const auto& file : side_files_of("X.h5")) EXPECT_EQ(study.count(file), 0u) << file;
}

TEST(SideFileNames, NoEndingEndsWithAnother) {
  for (const auto longer : kSideFileEndings) {
    for (const auto shorter : kSideFileEndings) {
      if (longer == shorter) continue;
      EXPECT_FALSE(longer.ends_with(shorter)) << longer << " " << shorter;
    }
  }
}

}  // namespace
}  // namespace blockfrag
