#include "mpi_driver/study/adaptive_levels.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include <gsl/gsl_cdf.h>

#include "engine/errors.hpp"
#include "engine/number_text.hpp"
#include "mpi_driver/config/stripe_scale.hpp"
#include "postproc/fragility/fragility_curve.hpp"

namespace blockfrag {
namespace {

// The bounds' smallest level, as a fraction of the study's smallest.
constexpr double kSmallestLevelFraction = 1e-3;

// Two levels around x, a factor `spread` apart.
std::vector<double> pair_around(double x, double spread) {
  return {x / std::sqrt(spread), x * std::sqrt(spread)};
}

// (high - low) / sqrt(low high), as the median's interval is measured against the median; infinite
// when an end is unknown (0 or infinite).
double relative_gap(double low, double high) {
  if (!(low > 0.0) || !std::isfinite(high)) return std::numeric_limits<double>::infinity();
  return (high - low) / std::sqrt(low * high);
}

void stop_with(BatchDecision& decision, std::string reason) {
  decision.stop = true;
  decision.reason = std::move(reason);
  decision.next_levels.clear();
}

// What the data say without a fit, for a stop reason at an end of the bounds: `side` is "fewer"
// going up, "more" going down.
std::string without_fit(const FragilityCurve& curve, const std::string& side) {
  if (curve.fit_status == "no_exceedances") return "no exceedance";
  if (curve.fit_status == "all_exceedances") return "every level exceeded";
  if (curve.fit_status == "separated" || curve.fit_status == "single_level")
    return side + " than half of the samples exceeded at every level";
  return "no fit (" + curve.fit_status + ")";
}

// The nearest level with trials on either side of x (0 and infinity where there is none), and the
// proportion of x's samples that exceeded, over every batch that ran it.
struct AroundLevel {
  double below = 0.0, above = std::numeric_limits<double>::infinity();
  double proportion = 0.0;
};
AroundLevel around_level(const FragilityCurve& curve, double x) {
  AroundLevel around;
  std::int64_t trials = 0, exceedances = 0;
  for (std::size_t k = 0; k < curve.im.size(); ++k) {
    if (curve.trials[k] == 0) continue;
    if (curve.im[k] < x) around.below = std::max(around.below, curve.im[k]);
    if (curve.im[k] > x) around.above = std::min(around.above, curve.im[k]);
    if (curve.im[k] == x) {
      trials += curve.trials[k];
      exceedances += curve.exceedances[k];
    }
  }
  around.proportion = static_cast<double>(exceedances) / static_cast<double>(trials);
  return around;
}

// Where the data place the median without a fit: in (below, above), 0 and infinity where no level
// bounds it; `at` > 0 when it is at that level, where half of the samples exceeded.
struct MedianBracket {
  double below, above, at = 0.0;
};

// The level nearest x (the fit gives its bracket's ends as exp(ln level), which need not be the
// level to the last bit); 0 and infinity stay.
double level_at(const FragilityCurve& curve, double x) {
  if (!(x > 0.0) || !std::isfinite(x)) return x;
  double nearest = x, distance = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < curve.im.size(); ++k) {
    if (curve.trials[k] == 0 || std::abs(std::log(curve.im[k] / x)) >= distance) continue;
    distance = std::abs(std::log(curve.im[k] / x));
    nearest = curve.im[k];
  }
  return nearest;
}

// The fit's bracket, except that one level x between separated ones (every level below without
// an exceedance, every one above all exceedances) gives the side of x the median lies on.
MedianBracket median_bracket(const FragilityCurve& curve) {
  const double low = level_at(curve, curve.median_low), high = level_at(curve, curve.median_high);
  if (low != high) return {low, high};
  const AroundLevel around = around_level(curve, low);
  if (around.proportion < 0.5) return {low, around.above};
  if (around.proportion > 0.5) return {around.below, low};
  return {around.below, around.above, low};
}

// A gap between levels: two levels split it in thirds (of its logarithm), or, with the median at a
// level x inside it, halve it on each side of x (doubling or halving x where no level bounds
// that side yet), each strictly inside, so none repeats a level that told nothing. A gap within
// the target width locates the median as closely as a fit's interval would; one too narrow to
// split in doubles ends the study too.
void split_gap(const AdaptiveDesign& design, MedianBracket bracket, const LevelBounds& bounds,
               BatchDecision& decision) {
  std::vector<double> next;
  const double x = bracket.at;
  if (x > 0.0) {
    if (bracket.below == 0.0 && x <= bounds.smallest) bracket.below = x;  // nothing can go below
    if (!std::isfinite(bracket.above) && x >= bounds.largest) bracket.above = x;
    next = {bracket.below == x    ? x
            : bracket.below > 0.0 ? std::sqrt(bracket.below * x)
                                  : x / 2.0,
            bracket.above == x             ? x
            : std::isfinite(bracket.above) ? std::sqrt(x * bracket.above)
                                           : 2.0 * x};
    for (double& level : next) level = std::clamp(level, bounds.smallest, bounds.largest);
  } else {
    const double low = std::log(bracket.below), high = std::log(bracket.above);
    next = {std::exp((2.0 * low + high) / 3.0), std::exp((low + 2.0 * high) / 3.0)};
  }
  const std::string gap = "separated data: the median lies between " +
                          format_number(bracket.below) + " and " + format_number(bracket.above);
  if (relative_gap(bracket.below, bracket.above) <= design.target_relative_width) {
    stop_with(decision, gap + ", a gap within the target width");
    return;
  }
  const auto inside = [&](double level, double low, double high) {
    return low < level && level < high;
  };
  const bool split =
      x > 0.0 ? (bracket.below == x || inside(next[0], bracket.below, x)) &&
                    (bracket.above == x || inside(next[1], x, bracket.above))
              : inside(next[0], bracket.below, next[1]) && inside(next[1], next[0], bracket.above);
  if (!split) {
    stop_with(decision, gap + ", a gap too narrow to split");
    return;
  }
  decision.next_levels = next;
}

// Without a fit the batch brackets the median: further up when it lies above every level, further
// down when below, inside the gap between levels otherwise.
void bracket_median(const AdaptiveDesign& design, const FragilityCurve& curve,
                    const std::vector<double>& levels, const LevelBounds& bounds,
                    BatchDecision& decision) {
  const auto [lowest, highest] = std::minmax_element(levels.begin(), levels.end());
  const MedianBracket bracket = median_bracket(curve);
  if (bracket.at == 0.0 && !std::isfinite(bracket.above)) {
    if (*highest >= bounds.largest) {
      stop_with(decision, without_fit(curve, "fewer") + " up to " + bounds.largest_reason);
      return;
    }
    decision.next_levels = {std::min(2.0 * *highest, bounds.largest),
                            std::min(4.0 * *highest, bounds.largest)};
    return;
  }
  if (bracket.at == 0.0 && !(bracket.below > 0.0)) {
    if (*lowest <= bounds.smallest) {
      stop_with(decision, without_fit(curve, "more") + " down to " +
                              format_number(bounds.smallest) +
                              ", a thousandth of the study's smallest level");
      return;
    }
    decision.next_levels = {std::max(*lowest / 4.0, bounds.smallest),
                            std::max(*lowest / 2.0, bounds.smallest)};
    return;
  }
  split_gap(design, bracket, bounds, decision);
}

}  // namespace

LevelBounds adaptive_level_bounds(const StudyConfig& config) {
  StripeCap cap = stripe_cap(config);
  const double smallest = std::max(kSmallestLevelFraction * config.intensity.levels.front(),
                                   std::numeric_limits<double>::min());
  return {smallest, cap.level, std::move(cap.reason)};
}

double median_relative_width(const FragilityCurve& curve) {
  if (curve.fit_status != "ok" || !std::isfinite(curve.median_se))
    return std::numeric_limits<double>::quiet_NaN();
  const double s = curve.median_se / curve.median;
  return std::exp(1.96 * s) - std::exp(-1.96 * s);
}

BatchDecision decide_next_batch(const AdaptiveDesign& design, const FragilityCurve& curve,
                                const std::vector<double>& levels, std::int64_t samples,
                                std::int64_t batch_samples, const LevelBounds& bounds) {
  if (levels.empty()) throw ContractViolation("an adaptive batch needs the levels so far");
  BatchDecision decision;
  decision.relative_width = median_relative_width(curve);
  if (decision.relative_width <= design.target_relative_width) {
    stop_with(decision, "target reached");
    return decision;
  }
  if (samples + batch_samples > design.max_samples) {
    stop_with(decision, "budget spent");
    return decision;
  }
  if (curve.fit_status == "ok") {
    const double z = gsl_cdf_ugaussian_Qinv(design.pair_probability);
    decision.next_levels = pair_around(curve.median, std::exp(2.0 * z * curve.beta));
    for (double& level : decision.next_levels)
      level = std::clamp(level, bounds.smallest, bounds.largest);
    return decision;
  }
  bracket_median(design, curve, levels, bounds, decision);
  return decision;
}

}  // namespace blockfrag
