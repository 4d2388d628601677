// Where an adaptive study's next batch goes: the pair placed where the fitted curve is the design's
// p and 1 - p (the default and the D-optimal pair, found by maximising the probit's Fisher
// information numerically), the median's interval width from its standard error, the stopping
// rules, the bracketing batches when there is no fit yet and the bounds every level keeps.
#include "mpi_driver/study/adaptive_levels.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "engine/number_text.hpp"
#include "engine/scene/scene_validation.hpp"
#include "mpi_driver/study/study_sample.hpp"
#include "postproc/fragility/fragility_curve.hpp"

namespace blockfrag {
namespace {

double normal_cdf(double z) { return 0.5 * std::erfc(-z / std::sqrt(2.0)); }
double normal_pdf(double z) { return std::exp(-0.5 * z * z) / std::sqrt(2.0 * M_PI); }

// With n samples at each of the standardised levels -z and +z, the probit's information matrix
// for (location, scale) is diagonal with entries proportional to 2 w(z) and 2 z^2 w(z), w the
// binomial weight phi^2 / (Phi (1 - Phi)): its determinant is proportional to (z w(z))^2.
double information_determinant_root(double z) {
  const double p = normal_cdf(z);
  return z * normal_pdf(z) * normal_pdf(z) / (p * (1.0 - p));
}

AdaptiveDesign design_with(double target, std::int64_t budget) {
  AdaptiveDesign design;
  design.limit_state = "overturn";
  design.target_relative_width = target;
  design.max_samples = budget;
  return design;
}

// Bounds as a pulse study's: a thousandth of 0.2 up to `largest`.
LevelBounds bounds_up_to(double largest) { return {2e-4, largest, "the measure's largest level"}; }

// Counts that follow a lognormal curve exactly enough for its fit to exist.
FragilityCurve lognormal_counts(double median, double beta, std::int64_t per_level) {
  const std::vector<double> levels{0.25, 0.5, 1.0, 2.0, 4.0};
  std::vector<std::int64_t> trials, exceedances;
  for (const double level : levels) {
    trials.push_back(per_level);
    const double p = normal_cdf(std::log(level / median) / beta);
    exceedances.push_back(std::llround(p * static_cast<double>(per_level)));
  }
  return fragility_from_counts(levels, trials, exceedances);
}

TEST(AdaptiveLevels, TheRelativeWidthIsTheMediansLognormalInterval) {
  FragilityCurve curve = lognormal_counts(1.0, 0.5, 1000);
  ASSERT_EQ(curve.fit_status, "ok");
  curve.median = 2.0;
  curve.median_se = 0.1;
  EXPECT_NEAR(median_relative_width(curve), std::exp(1.96 * 0.05) - std::exp(-1.96 * 0.05), 1e-15);
  curve.fit_status = "separated";
  EXPECT_TRUE(std::isnan(median_relative_width(curve)));
}

// The maximum of (z w(z))^2 over z, by scanning.
double d_optimal_z() {
  double best_z = 0.0, best = 0.0;
  for (double z = 0.5; z < 2.0; z += 1e-5) {
    if (information_determinant_root(z) > best) {
      best = information_determinant_root(z);
      best_z = z;
    }
  }
  return best_z;
}

TEST(AdaptiveLevels, TheNextPairSitsWhereTheFitIsTheDesignsProbabilities) {
  const FragilityCurve curve = lognormal_counts(1.3, 0.6, 400);
  ASSERT_EQ(curve.fit_status, "ok");
  const auto fitted = [&](double im) {
    return normal_cdf(std::log(im / curve.median) / curve.beta);
  };
  AdaptiveDesign design = design_with(1e-6, 1'000'000);
  // The default is the D-optimal pair.
  const double d_optimal = 1.0 - normal_cdf(d_optimal_z());
  EXPECT_NEAR(design.pair_probability, d_optimal, 1e-3);
  for (const double p : {d_optimal, 0.3}) {
    design.pair_probability = p;
    const BatchDecision next =
        decide_next_batch(design, curve, curve.im, 2000, 800, bounds_up_to(10.0));
    ASSERT_FALSE(next.stop);
    ASSERT_EQ(next.next_levels.size(), 2u);
    EXPECT_NEAR(fitted(next.next_levels[0]), p, 1e-12);
    EXPECT_NEAR(fitted(next.next_levels[1]), 1.0 - p, 1e-12);
    EXPECT_EQ(next.relative_width, median_relative_width(curve));
  }
}

TEST(AdaptiveLevels, LevelsStayBelowTheMeasuresLargest) {
  const FragilityCurve curve = lognormal_counts(1.3, 0.6, 400);
  const BatchDecision next = decide_next_batch(design_with(1e-6, 1'000'000), curve, curve.im, 2000,
                                               800, bounds_up_to(1.5));
  ASSERT_FALSE(next.stop);
  EXPECT_LT(next.next_levels[0], 1.3);
  EXPECT_EQ(next.next_levels[1], 1.5);
}

TEST(AdaptiveLevels, StopsAtTheTargetBeforeLookingAtTheBudget) {
  const FragilityCurve curve = lognormal_counts(1.3, 0.6, 400);
  const double width = median_relative_width(curve);
  const BatchDecision reached = decide_next_batch(design_with(width * 1.01, 2000), curve, curve.im,
                                                  2000, 800, bounds_up_to(10.0));
  EXPECT_TRUE(reached.stop);
  EXPECT_EQ(reached.reason, "target reached");
  const BatchDecision spent = decide_next_batch(design_with(width * 0.99, 2799), curve, curve.im,
                                                2000, 800, bounds_up_to(10.0));
  EXPECT_TRUE(spent.stop);
  EXPECT_EQ(spent.reason, "budget spent");
  const BatchDecision fits = decide_next_batch(design_with(width * 0.99, 2800), curve, curve.im,
                                               2000, 800, bounds_up_to(10.0));
  EXPECT_FALSE(fits.stop);
}

TEST(AdaptiveLevels, WithoutExceedancesTheBatchLooksFurtherUp) {
  const std::vector<double> levels{0.2, 0.4};
  const FragilityCurve curve = fragility_from_counts(levels, {100, 100}, {0, 0});
  ASSERT_NE(curve.fit_status, "ok");
  const BatchDecision next =
      decide_next_batch(design_with(0.05, 10'000), curve, levels, 200, 200, bounds_up_to(5.0));
  ASSERT_FALSE(next.stop);
  EXPECT_TRUE(std::isnan(next.relative_width));
  EXPECT_DOUBLE_EQ(next.next_levels[0], 0.8);
  EXPECT_DOUBLE_EQ(next.next_levels[1], 1.6);
}

TEST(AdaptiveLevels, StopsWhenNothingExceedsAtTheLargestLevel) {
  const std::vector<double> levels{1.0, 2.5};
  const FragilityCurve curve = fragility_from_counts(levels, {100, 100}, {0, 0});
  const BatchDecision next =
      decide_next_batch(design_with(0.05, 10'000), curve, levels, 200, 200, bounds_up_to(2.5));
  EXPECT_TRUE(next.stop);
  EXPECT_EQ(next.reason, "no exceedance up to the measure's largest level");
  const BatchDecision below =
      decide_next_batch(design_with(0.05, 10'000), curve, {1.0, 2.0}, 200, 200, bounds_up_to(2.5));
  EXPECT_FALSE(below.stop);
  EXPECT_EQ(below.next_levels, (std::vector<double>{2.5, 2.5}));
}

TEST(AdaptiveLevels, WhenEverythingExceededTheBatchLooksFurtherDown) {
  const std::vector<double> levels{0.4, 0.8};
  const FragilityCurve curve = fragility_from_counts(levels, {100, 100}, {100, 100});
  ASSERT_NE(curve.fit_status, "ok");
  const BatchDecision next =
      decide_next_batch(design_with(0.05, 10'000), curve, levels, 200, 200, bounds_up_to(5.0));
  ASSERT_FALSE(next.stop);
  EXPECT_DOUBLE_EQ(next.next_levels[0], 0.1);
  EXPECT_DOUBLE_EQ(next.next_levels[1], 0.2);
}

TEST(AdaptiveLevels, SeparatedDataAreSplitBetweenTheirLevels) {
  const std::vector<double> levels{0.5, 2.0};
  const FragilityCurve curve = fragility_from_counts(levels, {100, 100}, {0, 100});
  ASSERT_NE(curve.fit_status, "ok");
  const BatchDecision next =
      decide_next_batch(design_with(0.05, 10'000), curve, levels, 200, 200, bounds_up_to(5.0));
  ASSERT_FALSE(next.stop);
  for (const double level : next.next_levels) {
    EXPECT_GT(level, 0.5);
    EXPECT_LT(level, 2.0);
  }
  EXPECT_NEAR(next.next_levels[0], std::pow(0.5, 2.0 / 3.0) * std::pow(2.0, 1.0 / 3.0), 1e-12);
  EXPECT_NEAR(next.next_levels[1], std::pow(0.5, 1.0 / 3.0) * std::pow(2.0, 2.0 / 3.0), 1e-12);
}

// A study's batches against a limit state with `exceeded(level)` of 10 samples exceeding at each
// level: the levels in the order they ran, and the decision that stopped it (or the last one).
struct AdaptiveDrive {
  std::vector<double> levels;
  BatchDecision last;
  int batches = 0;
};

AdaptiveDrive drive_batches(const AdaptiveDesign& design, std::vector<double> levels,
                            const std::function<std::int64_t(double)>& exceeded,
                            const LevelBounds& bounds, int max_batches) {
  AdaptiveDrive drive;
  drive.levels = std::move(levels);
  for (; drive.batches < max_batches; ++drive.batches) {
    std::vector<std::int64_t> trials, exceedances;
    for (const double level : drive.levels) {
      trials.push_back(10);
      exceedances.push_back(exceeded(level));
    }
    const FragilityCurve curve = fragility_from_counts(drive.levels, trials, exceedances);
    const auto samples = static_cast<std::int64_t>(10 * drive.levels.size());
    drive.last = decide_next_batch(design, curve, drive.levels, samples, 20, bounds);
    if (drive.last.stop) break;
    drive.levels.insert(drive.levels.end(), drive.last.next_levels.begin(),
                        drive.last.next_levels.end());
  }
  return drive;
}

// A limit state past at every level (a block released beyond it) looks down a factor 4 a batch,
// then stops at the bounds' smallest level instead of halving the levels until they underflow.
TEST(AdaptiveLevels, EveryLevelExceededStopsAtTheSmallestLevel) {
  const AdaptiveDrive drive = drive_batches(
      design_with(0.05, 1'000'000), {0.2, 0.4}, [](double) { return 10; }, bounds_up_to(5.0), 100);
  ASSERT_TRUE(drive.last.stop);
  EXPECT_EQ(drive.last.reason,
            "every level exceeded down to 2e-04, a thousandth of the study's smallest level");
  EXPECT_EQ(drive.batches, 5);  // batch 5 runs 0.0002, as 0.2 / 4^5 < 0.0002 <= 0.2 / 4^4
  for (const double level : drive.levels) EXPECT_GE(level, 2e-4);
  EXPECT_EQ(*std::min_element(drive.levels.begin(), drive.levels.end()), 2e-4);
}

// Nothing exceeds: the batches double up to the cap (a record's, below the measure's largest)
// and stop there, naming it.
TEST(AdaptiveLevels, NoExceedanceStopsAtTheCap) {
  const LevelBounds bounds{2e-4, 18.5, "18.5 g, the largest level a scale of 100 gives a.csv"};
  const AdaptiveDrive drive = drive_batches(
      design_with(0.05, 1'000'000), {0.2, 0.4}, [](double) { return 0; }, bounds, 100);
  ASSERT_TRUE(drive.last.stop);
  EXPECT_EQ(drive.last.reason,
            "no exceedance up to 18.5 g, the largest level a scale of 100 gives a.csv");
  EXPECT_EQ(drive.levels, (std::vector<double>{0.2, 0.4, 0.8, 1.6, 3.2, 6.4, 12.8, 18.5}));
}

TEST(AdaptiveLevels, AFittedPairStaysWithinTheBounds) {
  const FragilityCurve curve = lognormal_counts(1.3, 3.0, 400);
  ASSERT_EQ(curve.fit_status, "ok");
  const BatchDecision next = decide_next_batch(design_with(1e-6, 1'000'000), curve, curve.im, 2000,
                                               800, {0.05, 4.0, "the measure's largest level"});
  ASSERT_FALSE(next.stop);
  EXPECT_EQ(next.next_levels, (std::vector<double>{0.05, 4.0}));
}

// Rocking onset is a step: no sample rocks below it, every one above. The batches narrow the gap
// by thirds, never repeating a level, until it is within the target width.
TEST(AdaptiveLevels, SeparatedDataNarrowTheGapUntilTheTarget) {
  const double step = 0.52;
  const AdaptiveDrive drive = drive_batches(
      design_with(0.05, 1'000'000), {0.2, 0.4}, [&](double level) { return level < step ? 0 : 10; },
      bounds_up_to(1000.0), 100);
  ASSERT_TRUE(drive.last.stop);
  EXPECT_THAT(drive.last.reason, ::testing::StartsWith("separated data: the median lies between "));
  EXPECT_THAT(drive.last.reason, ::testing::EndsWith(", a gap within the target width"));
  EXPECT_LE(drive.batches, 8);
  std::vector<double> sorted = drive.levels;
  std::sort(sorted.begin(), sorted.end());
  EXPECT_EQ(std::adjacent_find(sorted.begin(), sorted.end()), sorted.end()) << "a level repeats";
  const double below = *(std::lower_bound(sorted.begin(), sorted.end(), step) - 1);
  const double above = *std::lower_bound(sorted.begin(), sorted.end(), step);
  EXPECT_LE((above - below) / std::sqrt(below * above), 0.05);
  EXPECT_EQ(drive.last.reason, "separated data: the median lies between " + format_number(below) +
                                   " and " + format_number(above) +
                                   ", a gap within the target width");
}

// One level between the separated ones where some samples exceeded: each side's gap is halved, so
// a batch whose levels told nothing is not placed again (the pair at x / sqrt(1.1) and
// x sqrt(1.1) was, batch after batch).
TEST(AdaptiveLevels, AMixedLevelAtTheSeparationHalvesEachSide) {
  const double x = 0.54275;
  std::vector<double> levels{0.5, x, 0.6};
  std::vector<std::int64_t> exceedances{0, 5, 10};
  const AdaptiveDesign design = design_with(0.01, 1'000'000);
  for (int batch = 0; batch < 3; ++batch) {
    const FragilityCurve curve =
        fragility_from_counts(levels, std::vector<std::int64_t>(levels.size(), 10), exceedances);
    ASSERT_EQ(curve.fit_status, "separated");
    const BatchDecision next = decide_next_batch(design, curve, levels, 30, 20, bounds_up_to(5.0));
    ASSERT_FALSE(next.stop);
    const double below = levels[levels.size() - 2], above = levels.back();
    const double low = batch == 0 ? 0.5 : below, high = batch == 0 ? 0.6 : above;
    EXPECT_NEAR(next.next_levels[0], std::sqrt(low * x), 1e-15);
    EXPECT_NEAR(next.next_levels[1], std::sqrt(x * high), 1e-15);
    levels.insert(levels.end(), next.next_levels.begin(), next.next_levels.end());
    exceedances.insert(exceedances.end(), {0, 10});
  }
}

TEST(AdaptiveLevels, AGapTooNarrowToSplitStops) {
  const std::vector<double> levels{1.0, std::nextafter(1.0, 2.0)};
  const FragilityCurve curve = fragility_from_counts(levels, {10, 10}, {0, 10});
  const BatchDecision next =
      decide_next_batch(design_with(1e-300, 10'000), curve, levels, 20, 20, bounds_up_to(5.0));
  EXPECT_TRUE(next.stop);
  EXPECT_EQ(next.reason,
            "separated data: the median lies between 1 and 1.0000000000000002, a gap too narrow to "
            "split");
}

TEST(AdaptiveLevels, ACurveWithoutTrendStopsAtTheCapSayingSo) {
  const std::vector<double> levels{1.0, 2.5};
  const FragilityCurve curve = fragility_from_counts(levels, {10, 10}, {10, 0});
  ASSERT_EQ(curve.fit_status, "no_trend");
  const BatchDecision next =
      decide_next_batch(design_with(0.05, 10'000), curve, levels, 20, 20, bounds_up_to(2.5));
  EXPECT_TRUE(next.stop);
  EXPECT_EQ(next.reason, "no fit (no_trend) up to the measure's largest level");
}

// The bounds of a study: a record's cap is the level it reaches with a scale of 100, the same rule
// that refuses a fixed level just above it; a pulse's is the measure's largest level.
TEST(AdaptiveLevels, TheBoundsAreTheStripeCapAndAThousandthOfTheSmallestLevel) {
  const std::filesystem::path folder =
      std::filesystem::path(BLOCKFRAG_SOURCE_DIR) / "tests/data/records";
  const auto record_study = [](const nlohmann::json& levels) {
    return nlohmann::json{{"scene",
                           {{"block", {{"half_width", 0.4}, {"half_height", 1.0}}},
                            {"contact", {{"friction", 0.7}, {"restitution", 0.5}}},
                            {"ground_motion", {{"type", "record"}, {"file", "cosine_pulse.txt"}}}}},
                          {"intensity_measure", {{"type", "pga"}, {"levels", levels}}},
                          {"samples_per_level", 2},
                          {"design", {{"adaptive", {{"max_samples", 100}}}}},
                          {"limit_states", {{{"name", "overturn"}, {"type", "overturning"}}}},
                          {"seed", 7}};
  };
  const std::string source = (folder / "study.json").string();
  const StudyConfig config = parse_study_config(record_study({0.2, 0.4}), source);
  const LevelBounds bounds = adaptive_level_bounds(config);
  EXPECT_DOUBLE_EQ(bounds.smallest, 2e-4);
  EXPECT_NEAR(bounds.largest, 40.0, 1e-9);  // cosine_pulse.txt peaks at 0.4 g
  EXPECT_THAT(bounds.largest_reason, ::testing::StartsWith(format_number(bounds.largest) + " g"));
  EXPECT_THAT(bounds.largest_reason,
              ::testing::HasSubstr("the largest level a scale of 100 gives cosine_pulse.txt (its "
                                   "PGA is "));
  EXPECT_NO_THROW(parse_study_config(record_study({0.2, bounds.largest}), source));
  EXPECT_THROW(parse_study_config(record_study({0.2, std::nextafter(bounds.largest, 1e3)}), source),
               ConfigError);

  nlohmann::json pulse_study = record_study({0.2, 0.4});
  pulse_study["scene"]["ground_motion"] = {
      {"type", "cosine_pulse"}, {"amplitude_g", 1.0}, {"period", 1.0}};
  const LevelBounds pulse_bounds = adaptive_level_bounds(parse_study_config(pulse_study, source));
  EXPECT_EQ(pulse_bounds.largest, 1000.0);
  EXPECT_EQ(pulse_bounds.largest_reason, "the measure's largest level");
}

// One level between separated ones where fewer (more) than half of the samples exceeded places the
// median above (below) it: the batch splits the gap on that side only, or looks further on when
// no level bounds it, and stops at the bounds saying so.
TEST(AdaptiveLevels, AMixedLevelPlacesTheMedianOnTheSideItsProportionSays) {
  const AdaptiveDesign design = design_with(0.01, 1'000'000);
  const std::vector<double> gap{0.5, 0.54, 0.6};
  const FragilityCurve few = fragility_from_counts(gap, {10, 10, 10}, {0, 2, 10});
  ASSERT_EQ(few.fit_status, "separated");
  const BatchDecision above = decide_next_batch(design, few, gap, 30, 20, bounds_up_to(5.0));
  ASSERT_FALSE(above.stop);
  EXPECT_NEAR(above.next_levels[0], std::cbrt(0.54 * 0.54 * 0.6), 1e-15);
  EXPECT_NEAR(above.next_levels[1], std::cbrt(0.54 * 0.6 * 0.6), 1e-15);

  const std::vector<double> top{12.8, 18.5};
  const FragilityCurve at_cap = fragility_from_counts(top, {10, 10}, {0, 1});
  ASSERT_EQ(at_cap.fit_status, "separated");
  const BatchDecision capped = decide_next_batch(design, at_cap, top, 20, 20, bounds_up_to(18.5));
  EXPECT_TRUE(capped.stop);
  EXPECT_EQ(capped.reason,
            "fewer than half of the samples exceeded at every level up to the measure's largest "
            "level");

  const std::vector<double> bottom{1.0, 2.0};
  const FragilityCurve most = fragility_from_counts(bottom, {10, 10}, {8, 10});
  ASSERT_EQ(most.fit_status, "separated");
  const BatchDecision below = decide_next_batch(design, most, bottom, 20, 20, bounds_up_to(5.0));
  ASSERT_FALSE(below.stop);
  EXPECT_EQ(below.next_levels, (std::vector<double>{0.25, 0.5}));
}

// A pulse given by its velocity reaches 100 m/s, the end of its domain, at a level of PGA its
// shape sets: a sample at the bounds' largest level is a valid scene, one a little past it is
// refused, as a sample at a fixed level would be.
TEST(AdaptiveLevels, APulsesCapIsTheEndOfItsAmplitudesDomain) {
  const nlohmann::json study{{"scene",
                              {{"block", {{"half_width", 10.0}, {"half_height", 1.0}}},
                               {"contact", {{"friction", 1e4}, {"restitution", 0.5}}},
                               {"ground_motion",
                                {{"type", "mavroeidis_papageorgiou"},
                                 {"velocity_amplitude", 0.5},
                                 {"period", 1.0},
                                 {"gamma", 2.0}}}}},
                             {"inputs", {{"direction", {{"distribution", "random_sign"}}}}},
                             {"intensity_measure", {{"type", "pga"}, {"levels", {0.2, 0.4}}}},
                             {"samples_per_level", 2},
                             {"design", {{"adaptive", {{"max_samples", 100}}}}},
                             {"limit_states", {{{"name", "overturn"}, {"type", "overturning"}}}},
                             {"seed", 7}};
  StudyConfig config = parse_study_config(study, "study.json");
  const LevelBounds bounds = adaptive_level_bounds(config);
  EXPECT_LT(bounds.largest, 1000.0);
  EXPECT_THAT(bounds.largest_reason,
              ::testing::HasSubstr("the largest level within the pulse's velocity_amplitude "
                                   "domain (at most 100 m/s; its PGA is "));
  config.intensity.levels = {bounds.largest, bounds.largest * (1.0 + 1e-9)};
  StudySampler sampler(config);
  for (std::int64_t index = 0; index < 2; ++index) {
    EXPECT_NO_THROW(validate_scene(sampler.draw(index).scene));
    EXPECT_THROW(validate_scene(sampler.draw(2 + index).scene), InvalidInput);
  }
}

}  // namespace
}  // namespace blockfrag
