#include "mpi_driver/config/study_crest_check.hpp"

#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "engine/number_text.hpp"
#include "mpi_driver/config/dam_json.hpp"

namespace blockfrag {
namespace {

// One motion some samples run, as a scene: a study scales its amplitude, which does not change the
// crest's grid, so one scene stands for all of its samples.
struct CrestCase {
  Scene scene;
  std::string what;  // "the record a.AT2", "the period 0.3 s"
};

Scene with_pulse_period(Scene scene, double period) {
  if (auto* cosine = std::get_if<CosinePulse>(&scene.ground_motion)) cosine->period = period;
  if (auto* sine = std::get_if<SinePulse>(&scene.ground_motion)) sine->period = period;
  return scene;
}

// The motions between them every sample runs. A drawn period's crest grows or shrinks with the
// period across its range (the pulse's nodes against the ringing's), so its two ends bound it.
std::vector<CrestCase> crest_cases(const StudyConfig& config) {
  const Scene& base = config.base_scene;
  std::vector<CrestCase> cases;
  if (config.suite && std::holds_alternative<NoMotion>(base.ground_motion)) {
    for (const SuiteRecord& record : config.suite->records) {
      Scene scene = base;
      scene.ground_motion = RecordedMotion{record.file, 1.0, record.record};
      cases.push_back({std::move(scene), "the record " + record.file});
    }
    return cases;
  }
  std::vector<double> periods = config.intensity.periods;
  for (const StudyInputSpec& spec : config.inputs) {
    if (spec.input != StudyInput::period) continue;
    const auto [low, high] = support_of(spec.distribution);
    periods.push_back(low);
    periods.push_back(high);
  }
  for (const double period : periods) {
    cases.push_back(
        {with_pulse_period(base, period), "the period " + format_number(period) + " s"});
  }
  return cases;
}

}  // namespace

void check_study_crest(const StudyConfig& config, ConfigErrors& errors) {
  if (!config.base_scene.dam) return;
  const std::vector<CrestCase> cases = crest_cases(config);
  if (cases.empty()) return;
  std::string first;
  for (const CrestCase& crest : cases) {
    const auto problem = crest_history_problem(crest.scene);
    if (!problem) return;  // these samples run
    if (first.empty()) first = crest.what + ": " + *problem;
  }
  const std::size_t others = cases.size() - 1;
  std::string likewise;
  if (others == 1) likewise = ", and likewise for the other motion the samples run";
  if (others > 1) {
    likewise =
        ", and likewise for the " + std::to_string(others) + " other motions the samples run";
  }
  errors.add(JsonPointer("/scene/dam"),
             "no sample could run (each would be rejected): with " + first + likewise);
}

}  // namespace blockfrag
