#include "postproc/fragility/curve_set.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace blockfrag {
namespace {

// Where the curve places its median: the fit's, or the middle (in logs) of what the data allow.
double median_position(const FragilityCurve& curve) {
  if (std::isfinite(curve.median)) return std::log(curve.median);
  const double low = curve.median_low, high = curve.median_high;
  if (!(low > 0)) return std::isfinite(high) ? std::log(high) : 0.0;
  if (!std::isfinite(high)) return std::log(low);
  return 0.5 * (std::log(low) + std::log(high));
}

}  // namespace

std::vector<std::size_t> severity_order(const std::vector<FragilityCurve>& curves) {
  std::vector<std::size_t> order(curves.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    const double pa = median_position(curves[a]), pb = median_position(curves[b]);
    if (pa != pb) return pa < pb;
    return std::isfinite(curves[a].median) && !std::isfinite(curves[b].median);
  });
  return order;
}

double crossing_intensity(double median1, double beta1, double median2, double beta2) {
  if (beta1 == beta2) return std::numeric_limits<double>::quiet_NaN();
  return std::exp((beta2 * std::log(median1) - beta1 * std::log(median2)) / (beta2 - beta1));
}

std::vector<std::pair<std::size_t, std::size_t>> crossing_pairs(
    const std::vector<FragilityCurve>& curves, double low, double high) {
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for (std::size_t i = 0; i < curves.size(); ++i) {
    for (std::size_t j = i + 1; j < curves.size(); ++j) {
      const auto& a = curves[i];
      const auto& b = curves[j];
      if (!std::isfinite(a.median) || !std::isfinite(b.median)) continue;
      const double x = crossing_intensity(a.median, a.beta, b.median, b.beta);
      if (x >= low && x <= high) pairs.emplace_back(i, j);
    }
  }
  return pairs;
}

}  // namespace blockfrag
