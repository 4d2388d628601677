#include "mpi_driver/study/adaptive_levels.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <gsl/gsl_cdf.h>

#include "postproc/fragility/fragility_curve.hpp"

namespace blockfrag {
namespace {

// Two levels around x, a factor `spread` apart, inside (0, largest].
std::vector<double> pair_around(double x, double spread, double largest) {
  const double low = x / std::sqrt(spread), high = x * std::sqrt(spread);
  return {std::min(low, largest), std::min(high, largest)};
}

std::vector<double> bracketing_levels(const FragilityCurve& curve,
                                      const std::vector<double>& levels, double largest) {
  const auto [lowest, highest] = std::minmax_element(levels.begin(), levels.end());
  const double low = curve.median_low, high = curve.median_high;
  if (!std::isfinite(high)) {  // nothing exceeded (or only the top level): look further up
    const double base = std::max(*highest, low > 0 ? low : *highest);
    return {std::min(2.0 * base, largest), std::min(4.0 * base, largest)};
  }
  if (!(low > 0)) return {*lowest / 4.0, *lowest / 2.0};  // everything exceeded: look down
  // The median lies between low and high (separated data, or one informative level): the pair
  // splits the gap in thirds (of its logarithm), so no level repeats one that told nothing.
  const double middle = std::sqrt(low * high);
  return pair_around(middle, std::max(std::cbrt(high / low), 1.1), largest);
}

}  // namespace

double median_relative_width(const FragilityCurve& curve) {
  if (curve.fit_status != "ok" || !std::isfinite(curve.median_se))
    return std::numeric_limits<double>::quiet_NaN();
  const double s = curve.median_se / curve.median;
  return std::exp(1.96 * s) - std::exp(-1.96 * s);
}

BatchDecision decide_next_batch(const AdaptiveDesign& design, const FragilityCurve& curve,
                                const std::vector<double>& levels, std::int64_t samples,
                                std::int64_t batch_samples, double largest_level) {
  BatchDecision decision;
  decision.relative_width = median_relative_width(curve);
  if (decision.relative_width <= design.target_relative_width) {
    decision.stop = true;
    decision.reason = "target reached";
    return decision;
  }
  if (samples + batch_samples > design.max_samples) {
    decision.stop = true;
    decision.reason = "budget spent";
    return decision;
  }
  if (curve.fit_status == "ok") {
    const double z = gsl_cdf_ugaussian_Qinv(design.pair_probability);
    const double spread = std::exp(2.0 * z * curve.beta);
    decision.next_levels = pair_around(curve.median, spread, largest_level);
    return decision;
  }
  decision.next_levels = bracketing_levels(curve, levels, largest_level);
  if (decision.next_levels.front() >= largest_level &&
      *std::max_element(levels.begin(), levels.end()) >= largest_level) {
    decision.stop = true;  // the levels would only repeat the largest, which told nothing
    decision.reason = "no exceedance up to the measure's largest level";
    decision.next_levels.clear();
  }
  return decision;
}

}  // namespace blockfrag
