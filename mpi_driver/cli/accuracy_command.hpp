// `blockfrag accuracy SUITE.json [--setting METHOD:VALUE ...] [--output FILE.h5] [--table FILE.md]
//  [--reference-tolerance TOL] [--min-batch-ms MS]`: the work-precision study of accuracy_study.hpp
// over a scene suite (configs/accuracy_suite.json), written to HDF5 and printed as a markdown
// table. Without --setting every setting of full_accuracy_settings() runs (minutes); with it, only
// those. With --fragility-study STUDY.json it also compares that study's fragility curves computed
// with each setting (--setting, or a short default list) against the reference, next to their
// sampling error, and the convergence of Monte Carlo and Latin hypercube designs
// (accuracy_fragility.hpp).
#pragma once

#include <filesystem>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace blockfrag {

// A timed batch lasts at most this long: with every setting and scene of the full study, 10 s a
// batch is already days of timing.
inline constexpr double kMaxMinBatchMilliseconds = 1e4;

struct AccuracyOptions {
  std::filesystem::path suite_path;
  std::vector<std::string> settings;  // METHOD:VALUE; empty: the full study
  std::filesystem::path output_path = "accuracy.h5";
  std::optional<std::filesystem::path> table_path;
  double reference_tolerance = 1e-14;
  double min_batch_ms = 2.0;
  std::optional<std::filesystem::path> fragility_study;
  int replicates = 20;                                // seeds per design and size
  std::vector<long> design_sizes = {10, 20, 40, 80};  // samples per level
  long reference_samples_per_level = 320;
};

// Runs the study; the table goes to `out`, progress lines to `log`. Returns 0. Throws ConfigError
// for a bad suite, InvalidInput for a bad setting, Hdf5Error or FileError on output.
int run_accuracy(const AccuracyOptions& options, std::ostream& out, std::ostream& log);

}  // namespace blockfrag
