// What a study tells its user about the samples that did not give a verdict: how many failed (the
// engine gave up: a budget spent, no consistent contact) or were rejected (the sampled scene broke
// a rule), and why the first few did. A sample is a pure function of its index, so evaluating it
// again fails again the same way: the reasons need not travel with every record.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "mpi_driver/config/study_config.hpp"
#include "mpi_driver/study/sample_evaluation.hpp"
#include "mpi_driver/study/study_record.hpp"

namespace blockfrag {

struct FailureReport {
  std::int64_t failed = 0;
  std::int64_t rejected = 0;
  std::vector<std::string> first_reasons;  // "sample 123 (level 4): <why>"

  std::int64_t total() const { return failed + rejected; }
};

// The failures counted one record at a time (the output streams them from disk), in sample order.
class FailureTally {
 public:
  void add(const SampleRecord& record);
  // The counts, and the first `described` failures described by evaluating them again.
  FailureReport report(const StudyConfig& config, const SceneEvaluator& evaluate,
                       std::size_t described = 3) const;

 private:
  std::int64_t failed_ = 0;
  std::int64_t rejected_ = 0;
  std::vector<SampleRecord> first_;  // the first few failed or rejected records
};

// True when more samples failed or were rejected than the config allows.
bool too_many_failures(const StudyConfig& config, const FailureReport& report);

}  // namespace blockfrag
