#include "postproc/fragility/cloud_fragility.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <vector>

#include "postproc/fragility/binomial_interval.hpp"
#include "postproc/fragility/fit_diagnostics.hpp"
#include "postproc/fragility/lognormal_fit.hpp"

namespace blockfrag {

namespace {

// The samples grouped by their exact intensity, in increasing order: what the fit sees.
struct IntensityGroups {
  std::vector<double> distinct;
  std::vector<std::int64_t> trials, exceedances;
};

IntensityGroups group_by_intensity(const std::vector<double>& im,
                                   const std::vector<bool>& exceeded) {
  std::map<double, std::pair<std::int64_t, std::int64_t>> groups;  // im -> (trials, exceedances)
  for (std::size_t i = 0; i < im.size(); ++i) {
    auto& [trials, exceedances] = groups[im[i]];
    ++trials;
    if (exceeded[i]) ++exceedances;
  }
  IntensityGroups grouped;
  for (const auto& [x, counts] : groups) {
    grouped.distinct.push_back(x);
    grouped.trials.push_back(counts.first);
    grouped.exceedances.push_back(counts.second);
  }
  return grouped;
}

// Each display bin's sums over its samples; expected: their fitted probabilities.
struct DisplayBins {
  std::vector<double> log_sum, expected;
  std::vector<std::int64_t> trials, exceedances;
};

// Equal widths in ln IM from the smallest intensity to the largest.
DisplayBins fill_display_bins(const std::vector<double>& im, const std::vector<bool>& exceeded,
                              const IntensityGroups& groups, const LognormalFit& fit,
                              std::size_t bins) {
  const double low = std::log(groups.distinct.front()), high = std::log(groups.distinct.back());
  const double width = high > low ? (high - low) / static_cast<double>(bins) : 1.0;
  DisplayBins binned{std::vector<double>(bins, 0.0), std::vector<double>(bins, 0.0),
                     std::vector<std::int64_t>(bins, 0), std::vector<std::int64_t>(bins, 0)};
  for (std::size_t i = 0; i < im.size(); ++i) {
    const double position = (std::log(im[i]) - low) / width;
    const auto k = std::min(bins - 1, static_cast<std::size_t>(std::max(0.0, position)));
    binned.log_sum[k] += std::log(im[i]);
    ++binned.trials[k];
    if (exceeded[i]) ++binned.exceedances[k];
    if (fit.status == FitStatus::ok) {
      binned.expected[k] +=
          0.5 * std::erfc(-std::log(im[i] / fit.median) / (fit.beta * std::sqrt(2.0)));
    }
  }
  return binned;
}

// The curve's points, one per bin that holds a sample (at the bin's geometric mean intensity);
// returns their expected exceedances.
std::vector<double> add_display_points(const DisplayBins& binned, FragilityCurve& curve) {
  std::vector<double> expected;
  for (std::size_t k = 0; k < binned.trials.size(); ++k) {
    const std::int64_t n = binned.trials[k], z = binned.exceedances[k];
    if (n == 0) continue;
    curve.im.push_back(std::exp(binned.log_sum[k] / static_cast<double>(n)));
    curve.trials.push_back(n);
    curve.exceedances.push_back(z);
    curve.probability.push_back(static_cast<double>(z) / static_cast<double>(n));
    const ProportionInterval interval = wilson_interval(z, n, 0.95);
    curve.ci_low.push_back(interval.low);
    curve.ci_high.push_back(interval.high);
    expected.push_back(binned.expected[k]);
  }
  return expected;
}

}  // namespace

FragilityCurve fragility_from_samples(const std::vector<double>& im,
                                      const std::vector<bool>& exceeded, std::size_t bins) {
  if (im.size() != exceeded.size())
    throw FitError("cloud fragility: im and exceeded differ in size");
  const IntensityGroups groups = group_by_intensity(im, exceeded);
  const LognormalFit fit =
      fit_lognormal_fragility(groups.distinct, groups.trials, groups.exceedances);
  FragilityCurve curve;
  fill_lognormal_fit(curve, fit, groups.distinct, groups.trials, groups.exceedances);
  if (im.empty() || bins == 0) return curve;
  const std::vector<double> expected =
      add_display_points(fill_display_bins(im, exceeded, groups, fit, bins), curve);
  // Goodness of fit over the display bins (Hosmer & Lemeshow's grouping): each bin's expected
  // exceedances are the sum of its samples' fitted probabilities.
  if (fit.status == FitStatus::ok) {
    fill_goodness_of_fit(curve, goodness_of_fit(curve.im, curve.trials, curve.exceedances,
                                                fit.median, fit.beta, expected));
  }
  return curve;
}

}  // namespace blockfrag
