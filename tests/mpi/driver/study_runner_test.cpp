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
#include "mpi_driver/io/record_spool.hpp"
#include "mpi_driver/parallel/checkpoint.hpp"
#include "mpi_driver/study/study_sample.hpp"
#include "tests/support/mpi_environment.hpp"
#include "tests/support/temporary_folder.hpp"

namespace blockfrag {
namespace {

using testing::TemporaryFolder;

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
  settings.records = folder.path() / "tiny.h5.records";
  settings.checkpoint_interval_s = 1e9;
  return settings;
}

// Every record the run left in its spool, by sample.
std::vector<SampleRecord> spooled_records(const StudyConfig& config, const RunSettings& settings) {
  const RecordSpool spool(settings.records, config.hash, config.total_samples(),
                          RecordSpool::Mode::resume);
  std::vector<SampleRecord> records(static_cast<std::size_t>(config.total_samples()));
  spool.read(0, records);
  return records;
}

TEST(StudyRunner, EachRecordIsTheSamplesOwnEvaluation) {
  TemporaryFolder folder;
  const StudyConfig config = tiny_study();
  const RunSettings settings = settings_in(folder);
  const RunResult result = run_study_samples(MPI_COMM_WORLD, config, settings, fake_simulate);
  ASSERT_EQ(result.outcome, RunOutcome::completed);
  EXPECT_EQ(result.computed, 40);
  const std::vector<SampleRecord> records = spooled_records(config, settings);
  StudySampler sampler(config);
  int failed = 0;
  for (std::int64_t i = 0; i < 40; ++i) {
    const StudySample sample = sampler.draw(i);
    const SampleRecord expected = make_record(i, fake_simulate(sample.scene));
    EXPECT_TRUE(same_bits(records[static_cast<std::size_t>(i)], expected)) << i;
    failed += expected.status != 0;
  }
  EXPECT_GT(failed, 0);  // the failed status is exercised
}

TEST(StudyRunner, ResumeComputesExactlyTheMissingSamples) {
  TemporaryFolder folder;
  const StudyConfig config = tiny_study();
  const RunSettings settings = settings_in(folder);
  run_study_samples(MPI_COMM_WORLD, config, settings, fake_simulate);
  const std::vector<SampleRecord> full = spooled_records(config, settings);

  // A checkpoint naming samples 0-2, 17 and 39 done, with only their records in the spool.
  std::filesystem::remove(settings.records);
  {
    RecordSpool spool(settings.records, config.hash, 40, RecordSpool::Mode::fresh);
    for (const std::size_t i : {0, 1, 2, 17, 39}) spool.write({&full[i], 1});
  }
  CheckpointState partial;
  partial.config_hash = config.hash;
  partial.total_samples = 40;
  partial.done = {{0, 3}, {17, 1}, {39, 1}};
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
  const std::vector<SampleRecord> records = spooled_records(config, settings);
  for (std::size_t i = 0; i < 40; ++i) EXPECT_TRUE(same_bits(records[i], full[i])) << i;
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
  // The last checkpoint, written once all are done (the output is written from it if the first
  // try cannot be), holds every sample: one range of 40.
  const auto state = read_checkpoint(settings.checkpoint);
  ASSERT_TRUE(state.has_value());
  ASSERT_EQ(state->done.size(), 1u);
  EXPECT_EQ(state->done[0].first, 0);
  EXPECT_EQ(state->done[0].count, 40);
}

}  // namespace
}  // namespace blockfrag
