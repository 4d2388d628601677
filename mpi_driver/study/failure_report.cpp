#include "mpi_driver/study/failure_report.hpp"

#include "engine/errors.hpp"
#include "mpi_driver/study/study_sample.hpp"

namespace blockfrag {

namespace {

// More than any report describes.
constexpr std::size_t kKeptFailures = 16;

}  // namespace

void FailureTally::add(const SampleRecord& record) {
  const auto status = static_cast<SampleStatus>(record.status);
  if (status == SampleStatus::ok) return;
  (status == SampleStatus::failed ? failed_ : rejected_) += 1;
  if (first_.size() < kKeptFailures) first_.push_back(record);
}

FailureReport FailureTally::report(const StudyConfig& config, const SceneEvaluator& evaluate,
                                   std::size_t described) const {
  FailureReport report{failed_, rejected_, {}};
  StudySampler sampler(config);
  for (const SampleRecord& record : first_) {
    if (report.first_reasons.size() >= described) break;
    const auto status = static_cast<SampleStatus>(record.status);
    const StudySample sample = sampler.draw(record.index);
    std::string why;
    try {
      why = evaluate(sample.scene).status_reason;
    } catch (const InvalidInput& refused) {
      why = refused.what();
    }
    report.first_reasons.push_back(
        "sample " + std::to_string(record.index) + " (level " + std::to_string(sample.level) +
        ", " + (status == SampleStatus::failed ? "failed" : "rejected") + "): " + why);
  }
  return report;
}

bool too_many_failures(const StudyConfig& config, const FailureReport& report) {
  const auto total = static_cast<double>(config.total_samples());
  return static_cast<double>(report.total()) > config.allowed_failed_fraction * total;
}

}  // namespace blockfrag
