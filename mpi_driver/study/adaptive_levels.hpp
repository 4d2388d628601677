// Where an adaptive study's next batch goes, from the fit of the batches so far: two levels of
// samples_per_level samples each, where the fitted lognormal is the design's pair_probability p
// and 1 - p, at median exp(-+z beta) with Phi(z) = 1 - p. The default p = 0.128 is the D-optimal
// pair, which makes the probit's median and beta together most precise per sample; a p nearer
// 0.5 favours the median alone, as long as the data are lognormal near it. Without a fit the batch
// brackets the median: past the largest level when nothing exceeded, below the smallest when
// everything did, in the gap where the data place it otherwise; no such level repeats one that
// told nothing (all or none of its samples exceeded), and where the data allow none the study
// stops with the reason. Every level lies within the study's level bounds. A pure function of the
// fit: the batches depend only on earlier batches' results, so any rank count and any restart
// place them alike.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "mpi_driver/config/study_config.hpp"
#include "postproc/fragility/fragility_curve.hpp"

namespace blockfrag {

// What each batch found, for the output's /adaptive group.
struct AdaptiveHistory {
  std::vector<std::int64_t> level_batch;  // the batch that added each level (0: the study's own)
  std::vector<std::int64_t> samples;      // after each batch: samples in all
  std::vector<double> median, beta, relative_width;  // the fit after each batch (NaN: none)
  std::string stop_reason;
};

struct BatchDecision {
  bool stop = false;
  std::string reason;               // why it stops: the target reached, the budget spent, ...
  std::vector<double> next_levels;  // when it goes on: two levels, in the measure's unit
  double relative_width;            // of the median's asymptotic 95 % interval; NaN without a fit
};

// The levels a batch may place. The largest is the stripe cap fixed levels obey (a record scaled by
// at most 100, the measure's domain). The smallest is a thousandth of the study's smallest level:
// a limit state every sample exceeds even there is one no intensity explains, and the study stops.
struct LevelBounds {
  double smallest;
  double largest;
  std::string largest_reason;  // what sets the largest (StripeCap::reason)
};
LevelBounds adaptive_level_bounds(const StudyConfig& config);

// The median's 95 % interval (high - low) / median from its standard error: with s the standard
// error of ln median, exp(1.96 s) - exp(-1.96 s).
double median_relative_width(const FragilityCurve& curve);

// After a batch: `curve` is the adaptive limit state's fit over every sample so far (samples in
// all) at `levels`, the levels so far (not empty), `budget` the design's max_samples and
// `batch_samples` what one more batch costs.
BatchDecision decide_next_batch(const AdaptiveDesign& design, const FragilityCurve& curve,
                                const std::vector<double>& levels, std::int64_t samples,
                                std::int64_t batch_samples, const LevelBounds& bounds);

}  // namespace blockfrag
