#include "mpi_driver/study/failure_report.hpp"

#include "engine/errors.hpp"
#include "mpi_driver/study/study_sample.hpp"

namespace blockfrag {

FailureReport report_failures(const StudyConfig& config, const std::vector<SampleRecord>& records,
                              const SceneEvaluator& evaluate, std::size_t described) {
  FailureReport report;
  StudySampler sampler(config);
  for (const SampleRecord& record : records) {
    const auto status = static_cast<SampleStatus>(record.status);
    if (status == SampleStatus::ok) continue;
    (status == SampleStatus::failed ? report.failed : report.rejected) += 1;
    if (report.first_reasons.size() >= described) continue;
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
