// The work-precision study's pieces: the suite file parses and covers what it claims (each scene
// does what its category says, checked against Shenton's onset criteria and the modes the engine
// reports), the error metrics and quantiles on hand-made cases, and the reference against
// Newmark's closed forms, Housner's free-rocking period and its check (gsl_rk8pd).
#include "mpi_driver/accuracy/accuracy_suite.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "engine/simulate.hpp"
#include "mpi_driver/accuracy/accuracy_fragility.hpp"
#include "mpi_driver/accuracy/accuracy_metrics.hpp"
#include "mpi_driver/accuracy/accuracy_settings.hpp"
#include "mpi_driver/accuracy/accuracy_study.hpp"
#include "mpi_driver/config/config_reader.hpp"
#include "mpi_driver/config/study_config.hpp"
#include "postproc/fragility/sample_quantile.hpp"

namespace blockfrag {
namespace {

using nlohmann::json;
using ::testing::HasSubstr;

const std::filesystem::path suite_path =
    std::filesystem::path(BLOCKFRAG_SOURCE_DIR) / "configs/accuracy_suite.json";
constexpr double infinity = std::numeric_limits<double>::infinity();

bool has_mode(const Summary& summary, ModeKind mode) {
  for (const auto& change : summary.modes) {
    if (change.mode == mode) return true;
  }
  return false;
}

const SuiteScene& scene_named(const AccuracySuite& suite, const std::string& name) {
  for (const auto& entry : suite.scenes) {
    if (entry.name == name) return entry;
  }
  throw std::out_of_range("no scene " + name);
}

TEST(AccuracySuite, TheSuiteFileCoversEveryCategoryWithAtLeastThirtyScenes) {
  const AccuracySuite suite = read_accuracy_suite(suite_path);
  EXPECT_GE(suite.scenes.size(), 30u);
  std::set<std::string> categories;
  bool slender = false, stocky = false, small = false, large = false;
  for (const auto& entry : suite.scenes) {
    categories.insert(entry.category);
    const double a = entry.scene.block.half_width, b = entry.scene.block.half_height;
    slender = slender || a / b <= 0.1;
    stocky = stocky || a / b >= 0.8;
    small = small || b <= 0.1;
    large = large || b >= 4.0;
    // The study sets the solver: a suite scene carries the defaults.
    EXPECT_EQ(entry.scene.solver.method, SolverSettings{}.method) << entry.name;
  }
  EXPECT_EQ(categories.size(), accuracy_categories.size());
  EXPECT_TRUE(slender && stocky && small && large);
}

// Every scene of the suite at the production default does what its category says. This also keeps
// the suite runnable: it is the only test that simulates all of it.
TEST(AccuracySuite, EachSceneDoesWhatItsCategorySays) {
  const AccuracySuite suite = read_accuracy_suite(suite_path);
  for (const auto& entry : suite.scenes) {
    SCOPED_TRACE(entry.name);
    const Summary summary = simulate(entry.scene);
    ASSERT_EQ(summary.status, Status::ok) << summary.status_reason;
    const double beta = entry.scene.block.half_width / entry.scene.block.half_height;
    const double mu = entry.scene.contact.friction;
    if (entry.category == "rocking") {
      EXPECT_FALSE(summary.overturned);
      EXPECT_TRUE(summary.rock_start_time.has_value());
      EXPECT_FALSE(summary.slide_start_time.has_value());
    } else if (entry.category == "sliding") {
      EXPECT_LT(mu, beta);  // Shenton: a block with mu <= a/b never starts to rock
      EXPECT_TRUE(summary.slide_start_time.has_value());
      EXPECT_FALSE(summary.rock_start_time.has_value());
      EXPECT_EQ(summary.max_abs_theta, 0.0);
    } else if (entry.category == "slide_rock") {
      EXPECT_GT(mu, beta);
      EXPECT_TRUE(has_mode(summary, ModeKind::slide_rock));
    } else if (entry.category == "flight_bouncing") {
      EXPECT_GT(entry.scene.contact.restitution, 0.0);
      EXPECT_TRUE(has_mode(summary, ModeKind::flight));
    } else if (entry.category == "overturning") {
      EXPECT_TRUE(summary.overturned);
    } else if (entry.category == "near_threshold") {
      // Pairs named *_below and *_above straddle the overturning amplitude.
      const bool above = entry.name.ends_with("_above");
      EXPECT_TRUE(above || entry.name.ends_with("_below"));
      EXPECT_EQ(summary.overturned, above);
    }
  }
}

TEST(AccuracySuite, RefusesASolverDuplicateNamesAndUnknownCategories) {
  const json scene = json::parse(R"({"block": {"half_width": 0.5, "half_height": 1.0},
      "contact": {"friction": 0.6, "restitution": 0.6}, "ground_motion": {"type": "none"}, "duration": 1.0})");
  json with_solver = scene;
  with_solver["solver"] = {{"method", "rk4"}};
  const json document = {{"scenes",
                          {{{"name", "a"}, {"category", "rocking"}, {"scene", scene}},
                           {{"name", "a"}, {"category", "rocking"}, {"scene", with_solver}},
                           {{"name", "b"}, {"category", "wobbling"}, {"scene", scene}}}}};
  try {
    accuracy_suite_from_json(document, "suite.json");
    FAIL() << "no ConfigError";
  } catch (const ConfigError& error) {
    const std::string text = error.what();
    EXPECT_THAT(text, HasSubstr("suite.json: /scenes/1/scene/solver: must be absent"));
    EXPECT_THAT(text, HasSubstr("/scenes/1/name: must be unique"));
    EXPECT_THAT(text, HasSubstr("/scenes/2/category: must be one of"));
  }
  EXPECT_THROW(accuracy_suite_from_json(json{{"scenes", json::array()}}, "empty.json"),
               ConfigError);
}

TEST(AccuracySettings, ParsesMethodAndValueAndRefusesNonsense) {
  EXPECT_EQ(parse_solver_setting("rk4:0.00025"), (SolverSetting{Method::rk4, 0.00025}));
  EXPECT_EQ(parse_solver_setting("gsl_rk8pd:1e-10"), (SolverSetting{Method::gsl_rk8pd, 1e-10}));
  for (const char* bad : {"rk4", "euler:1e-3", "adaptive:", "adaptive:-1e-8", "adaptive:nan",
                          "adaptive:0.5", "rk4:1e-3x"}) {
    EXPECT_THROW(parse_solver_setting(bad), InvalidInput) << bad;
  }
  const auto full = full_accuracy_settings();
  EXPECT_EQ(full.size(), 37u);
  EXPECT_NE(std::find(full.begin(), full.end(), SolverSetting{Method::rk4, 2.5e-4}), full.end());
  EXPECT_NE(std::find(full.begin(), full.end(), default_setting()), full.end());
  const SolverSettings applied = with_setting(SolverSettings{}, {Method::rk4, 1e-4});
  EXPECT_EQ(applied.method, Method::rk4);
  EXPECT_EQ(applied.dt, 1e-4);
}

Summary synthetic(double max_theta, double final_theta, double slide, std::optional<double> impact,
                  bool over) {
  Summary s;
  s.max_abs_theta = max_theta;
  s.final_theta = final_theta;
  s.final_slide = slide;
  s.first_impact_time = impact;
  s.overturned = over;
  return s;
}

TEST(AccuracyMetrics, ErrorsAreAbsoluteDifferencesWithMissingImpactsInfinite) {
  const Summary reference = synthetic(0.30, -0.10, 0.25, 1.5, false);
  const OutputErrors e = output_errors(reference, synthetic(0.31, 0.05, 0.20, 1.25, false));
  EXPECT_NEAR(e.max_abs_theta, 0.01, 1e-15);
  EXPECT_NEAR(e.final_theta, 0.15, 1e-15);
  EXPECT_NEAR(e.final_slide, 0.05, 1e-15);
  EXPECT_EQ(e.first_impact_time, 0.25);
  EXPECT_FALSE(e.wrong_verdict);

  EXPECT_EQ(
      output_errors(reference, synthetic(0.3, -0.1, 0.25, std::nullopt, false)).first_impact_time,
      infinity);
  EXPECT_EQ(output_errors(synthetic(0.3, 0, 0, std::nullopt, false),
                          synthetic(0.3, 0, 0, std::nullopt, false))
                .first_impact_time,
            0.0);
  EXPECT_TRUE(output_errors(reference, synthetic(0.3, -0.1, 0.25, 1.5, true)).wrong_verdict);

  Summary failed = reference;
  failed.status = Status::failed;
  const OutputErrors f = output_errors(reference, failed);
  EXPECT_TRUE(f.failed);
  EXPECT_TRUE(f.wrong_verdict);
  EXPECT_EQ(f.max_abs_theta, infinity);
}

TEST(AccuracyMetrics, QuantilesInterpolateLikeNumpy) {
  // numpy.sample_quantile([4, 1, 3, 2], q) for q = 0.5, 0.95, 0, 1.
  EXPECT_DOUBLE_EQ(sample_quantile({4, 1, 3, 2}, 0.5), 2.5);
  EXPECT_DOUBLE_EQ(sample_quantile({4, 1, 3, 2}, 0.95), 3.85);
  EXPECT_DOUBLE_EQ(sample_quantile({4, 1, 3, 2}, 0.0), 1.0);
  EXPECT_DOUBLE_EQ(sample_quantile({4, 1, 3, 2}, 1.0), 4.0);
  EXPECT_EQ(sample_quantile({1, infinity, 2}, 1.0), infinity);
  EXPECT_TRUE(std::isnan(sample_quantile({}, 0.5)));
}

TEST(AccuracyMetrics, StatisticsOverScenes) {
  const Summary reference = synthetic(0.3, 0.0, 0.0, std::nullopt, false);
  const std::vector<OutputErrors> errors = {
      output_errors(reference, synthetic(0.3 + 1e-3, 0, 0, std::nullopt, false)),
      output_errors(reference, synthetic(0.3 + 4e-3, 0, 0, std::nullopt, true)),
      output_errors(reference, synthetic(0.3 + 2e-3, 0, 0, std::nullopt, false)),
      output_errors(reference, synthetic(0.3, 0, 0, std::nullopt, false))};
  const SettingStatistics s =
      setting_statistics(errors, {1.0, 2.0, 3.0, 4.0}, {10, 20, 30, 40}, {1, 2, 3, 4});
  EXPECT_NEAR(s.max_error.max_abs_theta, 4e-3, 1e-15);
  EXPECT_NEAR(s.median_error.max_abs_theta, 1.5e-3, 1e-15);
  EXPECT_EQ(s.scenes_over_target, 3);  // 1e-3, 4e-3, 2e-3 exceed 1e-6 rad; 0 does not
  EXPECT_EQ(s.wrong_verdicts, 1);
  EXPECT_DOUBLE_EQ(s.wrong_verdict_rate, 0.25);
  EXPECT_EQ(s.failures, 0);
  EXPECT_DOUBLE_EQ(s.median_seconds, 2.5);
  EXPECT_DOUBLE_EQ(s.p95_seconds, 3.85);
  EXPECT_DOUBLE_EQ(s.median_rhs_evaluations, 25.0);
  EXPECT_DOUBLE_EQ(s.mean_rhs_evaluations, 25.0);
}

// Housner's free rocking from rest at theta0 reaches theta = 0 after a quarter of the exact period
// of docs/references.md:
//   t = Int_0^theta0 dtheta / (p sqrt(2 [cos(alpha - theta0) - cos(alpha - theta)])).
// With theta = theta0 (1 - s^2) the integrand is smooth on [0, 1], and Simpson's rule converges
// fast.
double free_rocking_quarter_period(const Scene& scene) {
  const double a = scene.block.half_width, b = scene.block.half_height;
  const double alpha = std::atan(a / b), p = std::sqrt(3 * scene.g / (4 * std::hypot(a, b)));
  const double theta0 = std::abs(scene.initial.theta);
  const auto integrand = [&](double s) {
    if (s == 0.0) return 2 * theta0 / (p * std::sqrt(2 * std::sin(alpha - theta0) * theta0));
    const double theta = theta0 * (1 - s * s);
    return 2 * theta0 * s /
           (p * std::sqrt(2 * (std::cos(alpha - theta0) - std::cos(alpha - theta))));
  };
  const int n = 20000;
  const double h = 1.0 / n;
  double sum = integrand(0.0) + integrand(1.0);
  for (int i = 1; i < n; ++i) sum += (i % 2 ? 4 : 2) * integrand(i * h);
  return sum * h / 3;
}

// The reference of Newmark's scenes matches the closed forms of docs/references.md to six digits,
// the free-rocking one the exact quarter period, and the check method (gsl_rk8pd) agrees with it.
TEST(AccuracyStudy, ReferenceMatchesClosedFormsAndItsCheck) {
  const AccuracySuite full = read_accuracy_suite(suite_path);
  AccuracySuite suite;
  for (const char* name : {"slide_rectangular", "slide_half_sine", "rock_free_release"}) {
    suite.scenes.push_back(scene_named(full, name));
  }
  AccuracyStudyOptions options;
  options.settings = {{Method::rk4, 1e-3}, {Method::adaptive, 1e-4}};
  options.min_batch_seconds = 0.0;
  const AccuracyStudy study = run_accuracy_study(suite, options);
  ASSERT_EQ(study.reference.size(), 3u);
  EXPECT_NEAR(study.reference[0].final_slide, 0.408750, 1e-6);
  EXPECT_NEAR(study.reference[1].final_slide, 1.123778, 1e-6);
  EXPECT_EQ(study.check_statistics.wrong_verdicts, 0);
  EXPECT_EQ(study.check_statistics.failures, 0);
  EXPECT_LT(study.check_statistics.max_error.max_abs_theta, 1e-9);
  EXPECT_LT(study.check_statistics.max_error.final_slide, 1e-9);
  // GSL's steppers locate events on a cubic Hermite interpolant over their long steps: rk8pd's
  // event times are good to about 1e-8 s only (the quarter period below shows the reference is the
  // accurate one).
  EXPECT_LT(study.check_statistics.max_error.first_impact_time, 1e-7);
  ASSERT_TRUE(study.reference[2].first_impact_time.has_value());
  EXPECT_NEAR(*study.reference[2].first_impact_time,
              free_rocking_quarter_period(suite.scenes[2].scene), 1e-10);

  ASSERT_EQ(study.settings.size(), 2u);
  for (const auto& result : study.settings) {
    ASSERT_EQ(result.errors.size(), 3u);
    for (std::size_t i = 0; i < 3; ++i) {
      // The errors are those of each run against its reference.
      EXPECT_EQ(result.errors[i].max_abs_theta,
                std::abs(result.runs[i].summary.max_abs_theta - study.reference[i].max_abs_theta));
      EXPECT_GE(result.runs[i].repeats, 1);
      EXPECT_GT(result.runs[i].seconds, 0.0);
    }
  }
  // A reference compared with itself has no error.
  std::vector<TimedRun> itself;
  for (const auto& summary : study.reference) itself.push_back({summary, 1.0, 1});
  const SettingResult same = evaluate_setting({Method::adaptive, 1e-12}, itself, study.reference);
  EXPECT_EQ(same.statistics.max_error.max_abs_theta, 0.0);
  EXPECT_EQ(same.statistics.max_error.first_impact_time, 0.0);
}

// The fragility comparison of a setting with itself finds no difference, and one with a coarse
// setting counts the samples whose verdict changed consistently with the curves: a level's
// probability can move by at most (changed verdicts at that level) / trials.
TEST(AccuracyFragility, ASettingAgainstItselfChangesNothing) {
  nlohmann::json document =
      read_json_file(std::filesystem::path(BLOCKFRAG_SOURCE_DIR) / "configs/example_study.json");
  document["samples_per_level"] = 4;
  const StudyConfig config = parse_study_config(document, "example_study.json");
  const SolverSetting reference{Method::adaptive, 1e-10};
  const auto rows = compare_fragility(config, {reference, {Method::adaptive, 1e-3}}, reference);
  ASSERT_EQ(rows.size(), 2 * config.limit_states.size());
  for (std::size_t i = 0; i < config.limit_states.size(); ++i) {
    const FragilityDifference& same = rows[i];
    EXPECT_EQ(same.limit_state, config.limit_states[i].name);
    EXPECT_EQ(same.verdicts_changed, 0);
    EXPECT_EQ(same.max_probability_difference, 0.0);
    EXPECT_GT(same.max_sampling_half_width, 0.0);
    EXPECT_TRUE(std::isnan(same.median) ? std::isnan(same.reference_median)
                                        : same.median == same.reference_median);
    const FragilityDifference& coarse = rows[config.limit_states.size() + i];
    EXPECT_LE(coarse.max_probability_difference,
              static_cast<double>(coarse.verdicts_changed) / 4 + 1e-12);
  }
  const auto convergence = design_convergence(document, {2, 4}, 2, 8);
  ASSERT_EQ(convergence.size(), 4u);
  EXPECT_EQ(convergence[0].design, "monte_carlo");
  EXPECT_EQ(convergence[3].design, "latin_hypercube");
  EXPECT_EQ(convergence[3].samples_per_level, 4);
}

}  // namespace
}  // namespace blockfrag
