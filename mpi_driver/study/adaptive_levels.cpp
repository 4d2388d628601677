#include "mpi_driver/study/adaptive_levels.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <tuple>
#include <utility>

#include <gsl/gsl_cdf.h>

#include "engine/errors.hpp"
#include "engine/number_text.hpp"
#include "postproc/fragility/fragility_curve.hpp"

namespace blockfrag {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The bounds' smallest level, as a fraction of the study's smallest.
constexpr double kSmallestLevelFraction = 1e-3;

// Two levels around x, a factor `spread` apart.
std::vector<double> pair_around(double x, double spread) {
  return {x / std::sqrt(spread), x * std::sqrt(spread)};
}

// (high - low) / sqrt(low high), as the median's interval is measured against the median; infinite
// when an end is unknown (0 or infinite).
double relative_gap(double low, double high) {
  if (!(low > 0.0) || !std::isfinite(high)) return kInfinity;
  return (high - low) / std::sqrt(low * high);
}

void stop_with(BatchDecision& decision, std::string reason) {
  decision.stop = true;
  decision.reason = std::move(reason);
  decision.next_levels.clear();
}

// What the data say without a fit, for a stop reason at an end of the bounds.
std::string without_fit(const FragilityCurve& curve) {
  if (curve.fit_status == "no_exceedances") return "no exceedance";
  if (curve.fit_status == "all_exceedances") return "every level exceeded";
  return "no fit (" + curve.fit_status + ")";
}

// The nearest level with trials on either side of x (0 and infinity where there is none).
std::pair<double, double> neighbours(const FragilityCurve& curve, double x) {
  double below = 0.0, above = kInfinity;
  for (std::size_t k = 0; k < curve.im.size(); ++k) {
    if (curve.trials[k] == 0) continue;
    if (curve.im[k] < x) below = std::max(below, curve.im[k]);
    if (curve.im[k] > x) above = std::min(above, curve.im[k]);
  }
  return {below, above};
}

// Separated data (every level up to `low` without an exceedance, every one from `high` on all
// exceedances) or one level x = low = high where some exceeded between such levels: the median
// lies in the gap. Two levels split the gap in thirds (of its logarithm), or halve it on each side
// of x (doubling or halving x where no level bounds that side yet), each strictly inside, so none
// repeats a level that told nothing. A gap within the target width locates the median as closely
// as a fit's interval would; one too narrow to split in doubles ends the study too.
void split_separation(const AdaptiveDesign& design, const FragilityCurve& curve,
                      const LevelBounds& bounds, BatchDecision& decision) {
  const double low = curve.median_low, high = curve.median_high;
  double below = low, above = high;
  std::vector<double> next;
  if (low < high) {
    next = {std::exp((2.0 * std::log(low) + std::log(high)) / 3.0),
            std::exp((std::log(low) + 2.0 * std::log(high)) / 3.0)};
  } else {
    std::tie(below, above) = neighbours(curve, low);
    if (below == 0.0 && low <= bounds.smallest) below = low;  // nothing can go below
    if (above == kInfinity && low >= bounds.largest) above = low;
    next = {below == low  ? low
            : below > 0.0 ? std::sqrt(below * low)
                          : low / 2.0,
            above == low           ? low
            : std::isfinite(above) ? std::sqrt(low * above)
                                   : 2.0 * low};
    for (double& level : next) level = std::clamp(level, bounds.smallest, bounds.largest);
  }
  const std::string gap = "separated data: the median lies between " + format_number(below) +
                          " and " + format_number(above);
  if (relative_gap(below, above) <= design.target_relative_width) {
    stop_with(decision, gap + ", a gap within the target width");
    return;
  }
  const bool inside = low < high ? low < next[0] && next[0] < next[1] && next[1] < high
                                 : (below == low || (below < next[0] && next[0] < low)) &&
                                       (above == low || (low < next[1] && next[1] < above));
  if (!inside) {
    stop_with(decision, gap + ", a gap too narrow to split");
    return;
  }
  decision.next_levels = next;
}

// Without a fit the batch brackets the median: further up when nothing exceeded (or nothing is
// known), further down when everything did, inside the gap of separated data.
void bracket_median(const AdaptiveDesign& design, const FragilityCurve& curve,
                    const std::vector<double>& levels, const LevelBounds& bounds,
                    BatchDecision& decision) {
  const auto [lowest, highest] = std::minmax_element(levels.begin(), levels.end());
  if (!std::isfinite(curve.median_high)) {
    if (*highest >= bounds.largest) {
      stop_with(decision, without_fit(curve) + " up to " + bounds.largest_reason);
      return;
    }
    decision.next_levels = {std::min(2.0 * *highest, bounds.largest),
                            std::min(4.0 * *highest, bounds.largest)};
    return;
  }
  if (!(curve.median_low > 0.0)) {
    if (*lowest <= bounds.smallest) {
      stop_with(decision, without_fit(curve) + " down to " + format_number(bounds.smallest) +
                              ", a thousandth of the study's smallest level");
      return;
    }
    decision.next_levels = {std::max(*lowest / 4.0, bounds.smallest),
                            std::max(*lowest / 2.0, bounds.smallest)};
    return;
  }
  split_separation(design, curve, bounds, decision);
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
