// A study on a dam crest whose every sample the engine would reject for its crest history (more
// than 2,000,000 nodes, one per dam period / 100 over the run) is refused at /scene/dam before any
// work; one where some samples run is accepted (those that cannot are rejected one by one). Node
// counts by hand: a settling run follows the crest to the motion's end plus 60 s, at steps of at
// most the dam's period / 100.
#include "mpi_driver/config/study_crest_check.hpp"

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "mpi_driver/config/config_reader.hpp"
#include "mpi_driver/config/study_config.hpp"
#include "tests/support/temporary_folder.hpp"

namespace blockfrag {
namespace {

using nlohmann::json;
using ::testing::ElementsAre;
using ::testing::HasSubstr;
using testing::TemporaryFolder;

// A settling study on a dam of period 0.01 s: 10,000 nodes a second of run, so a run of more than
// 200 s is refused. The base scene's 1 s pulse runs 61 s.
json dam_study() {
  return json::parse(R"({
    "scene": {
      "block": {"half_width": 0.5, "half_height": 1.0},
      "contact": {"friction": 0.7, "restitution": 0.7},
      "ground_motion": {"type": "cosine_pulse", "amplitude_g": 1.0, "period": 1.0},
      "dam": {"period": 0.01}},
    "intensity_measure": {"levels": [0.5, 1.0]},
    "samples_per_level": 4,
    "limit_states": [{"name": "overturn", "type": "overturning"}],
    "seed": 1})");
}

std::vector<std::string> messages_of(const json& document, const std::string& source) {
  try {
    parse_study_config(document, source);
  } catch (const ConfigError& error) {
    return error.messages();
  }
  return {};
}

TEST(StudyCrestCheck, APeriodRangeNoSampleCanRunIsRefusedAtTheDam) {
  json study = dam_study();
  EXPECT_THAT(messages_of(study, "study.json"), ElementsAre());
  // 200 to 300 s pulses: at least 260 s of run, 2,600,000 nodes and more.
  study["inputs"]["period"] = {{"distribution", "uniform"}, {"min", 200.0}, {"max", 300.0}};
  EXPECT_THAT(
      messages_of(study, "study.json"),
      ElementsAre("study.json: /scene/dam: no sample could run (each would be rejected): "
                  "with the period 200 s: the dam's period (0.01 s) is too short for the "
                  "run (260 s): the crest motion would need 2600003 nodes (one per period "
                  "/ 100), more than 2000000; give a longer period, or a duration or "
                  "max_duration that ends the run sooner, and likewise for the other motion "
                  "the samples run"));
  // From 100 s, 1,600,003 nodes: those samples run.
  study["inputs"]["period"]["min"] = 100.0;
  EXPECT_THAT(messages_of(study, "study.json"), ElementsAre());
}

TEST(StudyCrestCheck, ASurfaceWhosePeriodsAllNeedTooManyNodesIsRefused) {
  json study = dam_study();
  study["intensity_measure"]["second"] = {{"type", "pulse_period"}, {"levels", {250.0, 300.0}}};
  EXPECT_THAT(messages_of(study, "study.json"),
              ElementsAre(HasSubstr("study.json: /scene/dam: no sample could run")));
  study["intensity_measure"]["second"]["levels"] = {1.0, 300.0};
  EXPECT_THAT(messages_of(study, "study.json"), ElementsAre());
}

// A record suite's base scene has no motion (the scene reader's 60 s run fits); its records do not.
TEST(StudyCrestCheck, ASuiteOfRecordsTooLongForTheDamIsRefused) {
  const TemporaryFolder folder;
  // 300 s and 10 s records (three samples each, two-column).
  std::ofstream(folder.path() / "long.txt") << "0 0\n0.5 0.1\n300 0\n";
  std::ofstream(folder.path() / "short.txt") << "0 0\n0.5 0.1\n10 0\n";
  const std::string source = (folder.path() / "study.json").string();
  json study = dam_study();
  study["scene"]["ground_motion"] = {{"type", "record_suite"}, {"records", {"long.txt"}}};
  study["intensity_measure"] = {{"type", "pga"}, {"levels", {0.5, 1.0}}};
  EXPECT_THAT(messages_of(study, source),
              ElementsAre(HasSubstr("/scene/dam: no sample could run (each would be rejected): "
                                    "with the record long.txt: the dam's period (0.01 s) is too "
                                    "short for the run (360 s)")));
  study["scene"]["ground_motion"]["records"] = {"long.txt", "short.txt"};
  EXPECT_THAT(messages_of(study, source), ElementsAre());
}

}  // namespace
}  // namespace blockfrag
