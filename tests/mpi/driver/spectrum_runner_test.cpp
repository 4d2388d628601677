// The spectrum runner on one rank (a singleton MPI process, no mpirun), with a stand-in evaluator
// whose overturning region is known exactly (a narrow band the map steps over, an onset, a safe
// island, a second onset per frequency): every crossing is found and bisected to the tolerance on
// the right side, and the minimum refined down to the narrow band; a rerun over the finished files
// computes nothing; a run stopped by an error in the middle of the bisection or of the minimum's
// refinement resumes from its files and ends with the same brackets and segments, bit for bit,
// computing nothing twice; a bisection state, minimum refinement or map checkpoint of another
// spectrum is refused as another spectrum spec's.
// Labelled mpi: Open MPI's allocations at MPI_Init would count as leaks under the sanitizer's leak
// check.
#include "mpi_driver/parallel/spectrum_runner.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "mpi_driver/io/record_spool.hpp"
#include "mpi_driver/parallel/bisection_state.hpp"
#include "mpi_driver/parallel/checkpoint.hpp"
#include "tests/support/mpi_environment.hpp"
#include "tests/support/temporary_folder.hpp"

namespace blockfrag {
namespace {

using testing::TemporaryFolder;

SpectrumConfig small_spectrum(double restitution = 0.6) {
  nlohmann::json document = nlohmann::json::parse(R"({
    "block": {"half_width": 0.5, "half_height": 1.0},
    "contact": {"friction": 0.6, "restitution": 0.6},
    "pulse": {"type": "cosine_pulse"},
    "frequency_ratio": {"from": 0.5, "to": 2, "count": 4},
    "amplitude_ratio": {"from": 1, "to": 6, "count": 11},
    "bisection": {"tolerance": 1e-9},
    "minimum_overturning": {"resolution": 0.01}})");
  document["contact"]["restitution"] = restitution;
  return parse_spectrum_config(document, "small.json");
}

// The stand-in's overturning region at frequency ratio f: [0.8 + f, 0.85 + f), a band between two
// of the map's amplitudes (1, 1.5, ..., 6), [1 + f, 2 + f) and [2.5 + f, inf), with no impact above
// 4 + f and three below; everything else stands, its max |theta| / alpha 1 - 2 sqrt(d) at a
// distance d from the band (at least 0).
double band_start(double f) { return 0.8 + f; }
double band_end(double f) { return 0.85 + f; }
double onset(double f) { return 1.0 + f; }
double island_start(double f) { return 2.0 + f; }
double second_onset(double f) { return 2.5 + f; }

SceneEvaluator stand_in(const SpectrumConfig& config, int* calls = nullptr, int fail_after = -1) {
  return [&config, calls, fail_after](const Scene& scene) {
    if (calls && fail_after >= 0 && *calls >= fail_after) throw std::runtime_error("stopped");
    if (calls) ++*calls;
    const auto& pulse = std::get<CosinePulse>(scene.ground_motion);
    const double f = 2 * std::numbers::pi / (pulse.period * config.p());
    const double a = pulse.amplitude_g / config.tan_alpha();
    Summary summary;
    summary.overturned = (a >= band_start(f) && a < band_end(f)) ||
                         (a >= onset(f) && a < island_start(f)) || a >= second_onset(f);
    summary.impacts = summary.overturned && a < 4 + f ? 3 : 0;
    summary.settled = true;
    const double distance = std::min(std::abs(a - band_start(f)), std::abs(a - band_end(f)));
    summary.max_abs_theta =
        summary.overturned ? 1.5 : config.alpha() * std::max(0.0, 1.0 - 2.0 * std::sqrt(distance));
    return summary;
  };
}

struct RunFiles {
  RunSettings settings;
  SpectrumFiles files;
};

RunFiles files_in(const TemporaryFolder& folder) {
  RunFiles run;
  const auto output = folder.path() / "small.h5";
  run.settings.checkpoint = checkpoint_path_for(output);
  run.settings.records = record_spool_path_for(output);
  run.settings.checkpoint_interval_s = 0.0;  // a checkpoint after every sample
  run.files = SpectrumFiles::for_output(output);
  return run;
}

template <typename T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

TEST(SpectrumRunner, FindsEveryCrossingToTheTolerance) {
  TemporaryFolder folder;
  const SpectrumConfig config = small_spectrum();
  const RunFiles run = files_in(folder);
  int calls = 0;
  const SpectrumRunResult result =
      run_spectrum(MPI_COMM_WORLD, config, run.settings, run.files, stand_in(config, &calls));
  EXPECT_EQ(result.outcome, RunOutcome::completed);
  EXPECT_EQ(result.map.computed, 44);
  EXPECT_EQ(calls, 44 + result.midpoints + result.minimum_midpoints);
  ASSERT_EQ(result.brackets.size(), 12u);  // three crossings at each of 4 frequencies
  for (std::size_t k = 0; k < result.brackets.size(); ++k) {
    const SpectrumBracket& b = result.brackets[k];
    const double f = config.frequency_ratio[static_cast<std::size_t>(b.frequency_index)];
    const double expected[] = {onset(f), island_start(f), second_onset(f)};
    EXPECT_EQ(b.frequency_index, static_cast<std::int64_t>(k / 3));
    EXPECT_EQ(b.direction(), k % 3 == 1 ? -1 : +1);
    EXPECT_EQ(b.state, static_cast<std::int64_t>(BracketState::converged));
    // The true crossing lies in the final bracket, which is within the tolerance.
    EXPECT_LE(b.low, expected[k % 3] * (1 + 1e-15));
    EXPECT_GE(b.high, expected[k % 3] * (1 - 1e-15));
    EXPECT_LE(b.high - b.low, 1e-9 * b.high);
  }
  // Each frequency's minimum is the band's lower edge, bracketed to the default 1e-3 (the band is
  // wider than the probes' resolution, 0.01 of its amplitude).
  const std::vector<FrequencyMinimum> minima = frequency_minima(result.minimum);
  ASSERT_EQ(minima.size(), 4u);
  for (std::size_t i = 0; i < minima.size(); ++i) {
    const double start = band_start(config.frequency_ratio[i]);
    EXPECT_EQ(minima[i].state, static_cast<std::int64_t>(MinimumState::found)) << i;
    EXPECT_LT(minima[i].low, start) << i;
    EXPECT_GE(minima[i].high, start) << i;
    EXPECT_LE(minima[i].high - minima[i].low, 1e-3 * minima[i].high) << i;
    EXPECT_EQ(minima[i].midpoints, result.minimum.midpoints[i]);
  }
  EXPECT_GT(result.minimum_rounds, 0);

  // The map's records are on disk, every point's; its checkpoint says all are done.
  const auto checkpoint = read_checkpoint(run.settings.checkpoint);
  ASSERT_TRUE(checkpoint.has_value());
  EXPECT_EQ(checkpoint->done.size(), 1u);
  EXPECT_EQ(checkpoint->done[0].count, 44);

  // Over its finished files, a rerun computes nothing and ends with the same brackets.
  int again = 0;
  const SpectrumRunResult rerun =
      run_spectrum(MPI_COMM_WORLD, config, run.settings, run.files, stand_in(config, &again));
  EXPECT_EQ(again, 0);
  EXPECT_EQ(rerun.rounds, 0);
  EXPECT_EQ(rerun.minimum_rounds, 0);
  EXPECT_TRUE(same_bits(rerun.brackets, result.brackets));
  EXPECT_TRUE(same_bits(rerun.minimum.segments, result.minimum.segments));
}

TEST(SpectrumRunner, ResumesAStoppedBisectionOrRefinementWithTheSameResults) {
  const SpectrumConfig config = small_spectrum();
  SpectrumRunResult straight;
  int straight_calls = 0;
  {
    TemporaryFolder folder;
    const RunFiles run = files_in(folder);
    straight = run_spectrum(MPI_COMM_WORLD, config, run.settings, run.files,
                            stand_in(config, &straight_calls));
  }
  const int refinement_start = 44 + static_cast<int>(straight.midpoints);
  for (const int stop_at : {30, 44 + 12 * 5 + 7, refinement_start + 5, straight_calls - 3}) {
    TemporaryFolder folder;
    const RunFiles run = files_in(folder);
    int calls = 0;
    EXPECT_THROW(run_spectrum(MPI_COMM_WORLD, config, run.settings, run.files,
                              stand_in(config, &calls, stop_at)),
                 std::runtime_error);
    int resumed_calls = 0;
    const SpectrumRunResult resumed = run_spectrum(MPI_COMM_WORLD, config, run.settings, run.files,
                                                   stand_in(config, &resumed_calls));
    EXPECT_TRUE(same_bits(resumed.brackets, straight.brackets)) << "stopped after " << stop_at;
    EXPECT_TRUE(same_bits(resumed.minimum.segments, straight.minimum.segments))
        << "stopped after " << stop_at;
    EXPECT_EQ(resumed.minimum.midpoints, straight.minimum.midpoints);
    // With a checkpoint after every sample, nothing is lost or computed twice.
    EXPECT_EQ(calls, stop_at);
    EXPECT_EQ(calls + resumed_calls, straight_calls) << "stopped after " << stop_at;
  }
}

TEST(SpectrumRunner, RefusesTheBisectionStateOfAnotherSpectrum) {
  TemporaryFolder folder;
  const RunFiles run = files_in(folder);
  const SpectrumConfig other = small_spectrum(0.5);
  run_spectrum(MPI_COMM_WORLD, other, run.settings, run.files, stand_in(other));
  // The map's files go (as a finished run's command removes them); the bisection state stays.
  std::filesystem::remove(run.settings.checkpoint);
  std::filesystem::remove(run.settings.records);
  const SpectrumConfig config = small_spectrum();
  try {
    run_spectrum(MPI_COMM_WORLD, config, run.settings, run.files, stand_in(config));
    FAIL() << "accepted another spectrum's bisection state";
  } catch (const StudyMismatchError& error) {
    EXPECT_NE(std::string(error.what()).find("belongs to a different spectrum spec"),
              std::string::npos)
        << error.what();
  }
}

TEST(SpectrumRunner, RefusesTheMinimumRefinementOfAnotherSpectrum) {
  TemporaryFolder folder;
  const RunFiles run = files_in(folder);
  const SpectrumConfig other = small_spectrum(0.5);
  run_spectrum(MPI_COMM_WORLD, other, run.settings, run.files, stand_in(other));
  std::filesystem::remove(run.settings.checkpoint);
  std::filesystem::remove(run.settings.records);
  std::filesystem::remove(run.files.bisection);
  ASSERT_TRUE(std::filesystem::exists(run.files.minimum));
  const SpectrumConfig config = small_spectrum();
  try {
    run_spectrum(MPI_COMM_WORLD, config, run.settings, run.files, stand_in(config));
    FAIL() << "accepted another spectrum's minimum refinement";
  } catch (const StudyMismatchError& error) {
    EXPECT_NE(std::string(error.what())
                  .find("the minimum refinement " + run.files.minimum.string() +
                        " belongs to a different spectrum spec"),
              std::string::npos)
        << error.what();
  }
}

// The map's checkpoint of another spectrum (stopped in its map) is another spectrum spec's, not a
// study's.
TEST(SpectrumRunner, RefusesTheMapCheckpointOfAnotherSpectrumSpec) {
  TemporaryFolder folder;
  const RunFiles run = files_in(folder);
  const SpectrumConfig other = small_spectrum(0.5);
  int calls = 0;
  EXPECT_THROW(
      run_spectrum(MPI_COMM_WORLD, other, run.settings, run.files, stand_in(other, &calls, 10)),
      std::runtime_error);
  ASSERT_TRUE(std::filesystem::exists(run.settings.checkpoint));
  const SpectrumConfig config = small_spectrum();
  try {
    run_spectrum(MPI_COMM_WORLD, config, run.settings, run.files, stand_in(config));
    FAIL() << "accepted another spectrum's map checkpoint";
  } catch (const StudyMismatchError& error) {
    const std::string what = error.what();
    EXPECT_NE(what.find("belongs to a different spectrum spec (checkpoint spec hash"),
              std::string::npos)
        << what;
    EXPECT_NE(what.find("run the original spec to finish it"), std::string::npos) << what;
    EXPECT_EQ(what.find("study config"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace blockfrag
