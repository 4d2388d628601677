// The study run loop on one rank (a singleton MPI process, no mpirun), with a stand-in evaluator:
// each record is the sample's own evaluation, a resume from a partial checkpoint computes exactly
// the missing samples and gives the same records, a checkpoint of another config is refused, and
// checkpoints are written at the interval. Labelled mpi: Open MPI's allocations at MPI_Init would
// count as leaks under the sanitizer's leak check.
#include "mpi_driver/parallel/study_runner.hpp"

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "mpi_driver/config/study_config.hpp"
#include "mpi_driver/parallel/checkpoint.hpp"
#include "mpi_driver/study/study_sample.hpp"

namespace blockfrag {
namespace {

// MPI for the whole executable (a singleton: no mpirun needed).
class MpiEnvironment : public ::testing::Environment {
 public:
  void SetUp() override { MPI_Init(nullptr, nullptr); }
  void TearDown() override { MPI_Finalize(); }
};
[[maybe_unused]] auto* const mpi_environment =
    ::testing::AddGlobalTestEnvironment(new MpiEnvironment);

class TemporaryFolder {
 public:
  TemporaryFolder() {
    char pattern[] = "/tmp/blockfrag_study_runner_test_XXXXXX";
    path_ = ::mkdtemp(pattern);
  }
  ~TemporaryFolder() { std::filesystem::remove_all(path_); }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

bool same_bits(const SampleRecord& a, const SampleRecord& b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

StudyConfig tiny_study(std::uint64_t seed = 5) {
  nlohmann::json document = nlohmann::json::parse(R"({
    "scene": {"block": {"half_width": 0.5, "half_height": 1.0}, "contact": {"friction": 0.7, "restitution": 0.7},
              "ground_motion": {"type": "cosine_pulse", "amplitude_g": 1.0, "period": 1.0}, "duration": 2.0},
    "inputs": {"friction": {"distribution": "uniform", "min": 0.55, "max": 0.9},
               "direction": {"distribution": "random_sign"}},
    "intensity_measure": {"levels": [0.3, 0.6, 0.9, 1.2]},
    "samples_per_level": 10, "design": "monte_carlo",
    "limit_states": [{"name": "overturn", "type": "overturning"}], "seed": 5})");
  document["seed"] = seed;
  return parse_study_config(document, "tiny.json");
}

// A stand-in engine: a summary that is a plain function of the scene, so the test knows each
// sample's record without the physics; scenes with friction above 0.85 "fail".
Summary fake_simulate(const Scene& scene) {
  Summary summary;
  const auto& pulse = std::get<CosinePulse>(scene.ground_motion);
  summary.max_abs_theta = scene.contact.friction * pulse.amplitude_g;
  summary.overturned = pulse.amplitude_g > 1.0;
  if (summary.overturned) summary.overturn_time = pulse.period;
  summary.steps = static_cast<long>(scene.contact.friction * 1e6);
  if (scene.contact.friction > 0.85) summary.status = Status::failed;
  return summary;
}

RunSettings settings_in(const TemporaryFolder& folder) {
  RunSettings settings;
  settings.checkpoint = folder.path() / "tiny.h5.checkpoint";
  settings.checkpoint_interval_s = 1e9;
  return settings;
}

TEST(StudyRunner, EachRecordIsTheSamplesOwnEvaluation) {
  TemporaryFolder folder;
  const StudyConfig config = tiny_study();
  const RunResult result =
      run_study_samples(MPI_COMM_WORLD, config, settings_in(folder), fake_simulate);
  ASSERT_EQ(result.outcome, RunOutcome::completed);
  ASSERT_EQ(result.records.size(), 40u);
  EXPECT_EQ(result.computed, 40);
  StudySampler sampler(config);
  int failed = 0;
  for (std::int64_t i = 0; i < 40; ++i) {
    const StudySample sample = sampler.draw(i);
    const SampleRecord expected = make_record(i, fake_simulate(sample.scene));
    EXPECT_TRUE(same_bits(result.records[static_cast<std::size_t>(i)], expected)) << i;
    failed += expected.status != 0;
  }
  EXPECT_GT(failed, 0);  // the failed status is exercised
}

TEST(StudyRunner, ResumeComputesExactlyTheMissingSamples) {
  TemporaryFolder folder;
  const StudyConfig config = tiny_study();
  const RunSettings settings = settings_in(folder);
  const RunResult full = run_study_samples(MPI_COMM_WORLD, config, settings, fake_simulate);

  CheckpointState partial;
  partial.config_hash = config.hash;
  partial.total_samples = 40;
  for (const std::int64_t i : {0, 1, 2, 17, 39})
    partial.done.push_back(full.records[static_cast<std::size_t>(i)]);
  write_checkpoint(settings.checkpoint, partial);

  std::set<double> evaluated_friction;
  int calls = 0;
  const RunResult resumed =
      run_study_samples(MPI_COMM_WORLD, config, settings, [&](const Scene& scene) {
        ++calls;
        evaluated_friction.insert(scene.contact.friction);
        return fake_simulate(scene);
      });
  EXPECT_EQ(resumed.restored, 5);
  EXPECT_EQ(resumed.computed, 35);
  EXPECT_EQ(calls, 35);
  StudySampler sampler(config);
  for (const std::int64_t i : {0, 1, 2, 17, 39}) {
    EXPECT_EQ(evaluated_friction.count(sampler.draw(i).scene.contact.friction), 0u)
        << "recomputed " << i;
  }
  for (std::size_t i = 0; i < 40; ++i)
    EXPECT_TRUE(same_bits(resumed.records[i], full.records[i])) << i;
}

TEST(StudyRunner, ACheckpointOfAnotherConfigIsRefused) {
  TemporaryFolder folder;
  const RunSettings settings = settings_in(folder);
  CheckpointState other;
  other.config_hash = tiny_study(6).hash;
  other.total_samples = 40;
  write_checkpoint(settings.checkpoint, other);
  try {
    run_study_samples(MPI_COMM_WORLD, tiny_study(5), settings, fake_simulate);
    FAIL() << "no refusal";
  } catch (const StudyMismatchError& error) {
    EXPECT_NE(std::string(error.what()).find("different study config"), std::string::npos)
        << error.what();
  }
}

TEST(StudyRunner, WritesCheckpointsAtTheInterval) {
  TemporaryFolder folder;
  RunSettings settings = settings_in(folder);
  settings.checkpoint_interval_s = 0.0;  // after every sample
  const RunResult result = run_study_samples(MPI_COMM_WORLD, tiny_study(), settings, fake_simulate);
  EXPECT_GE(result.checkpoints, 39);
  // The last periodic checkpoint holds every sample but the last one (none is written once all are
  // done).
  const auto state = read_checkpoint(settings.checkpoint, tiny_study().total_samples());
  ASSERT_TRUE(state.has_value());
  EXPECT_EQ(state->done.size(), 39u);
}

}  // namespace
}  // namespace blockfrag
