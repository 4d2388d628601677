#include "postproc/risk/hazard_curve.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>

namespace blockfrag {

void check_hazard_curve(const HazardCurve& curve) {
  const auto& im = curve.im;
  const auto& rate = curve.annual_rate;
  if (im.size() < 2 || im.size() != rate.size()) {
    throw ContractViolation("a hazard curve needs at least two intensities, each with its rate");
  }
  for (std::size_t i = 0; i < im.size(); ++i) {
    if (!(std::isfinite(im[i]) && im[i] > 0.0) || (i > 0 && !(im[i] > im[i - 1]))) {
      throw ContractViolation("hazard curve: intensity " + std::to_string(i) +
                              " is not finite, > 0 and above the one before");
    }
    if (!(std::isfinite(rate[i]) && rate[i] >= 0.0) || (i > 0 && rate[i] > rate[i - 1])) {
      throw ContractViolation("hazard curve: rate " + std::to_string(i) +
                              " is not finite, >= 0 and at most the one before");
    }
  }
  if (!(rate.front() > 0.0)) throw ContractViolation("hazard curve: its first rate is 0");
}

namespace {

// The segment holding x: im[i] <= x <= im[i + 1].
std::size_t segment_of(const HazardCurve& curve, double x) {
  const auto above = std::upper_bound(curve.im.begin(), curve.im.end(), x);
  const auto index = static_cast<std::size_t>(std::distance(curve.im.begin(), above));
  return std::clamp<std::size_t>(index, 1, curve.im.size() - 1) - 1;
}

}  // namespace

double hazard_rate(const HazardCurve& curve, double x) {
  const std::size_t i = segment_of(curve, x);
  const double x0 = curve.im[i], x1 = curve.im[i + 1];
  const double r0 = curve.annual_rate[i], r1 = curve.annual_rate[i + 1];
  const double t = std::log(x / x0) / std::log(x1 / x0);
  if (r0 == 0.0) return 0.0;
  if (r1 == 0.0) return r0 * (1.0 - t);
  return r0 * std::pow(r1 / r0, t);
}

double hazard_density(const HazardCurve& curve, std::size_t segment, double x) {
  const double x0 = curve.im[segment], x1 = curve.im[segment + 1];
  const double r0 = curve.annual_rate[segment], r1 = curve.annual_rate[segment + 1];
  const double width = std::log(x1 / x0);
  if (r0 == 0.0) return 0.0;
  if (r1 == 0.0) return r0 / width;
  // lambda = r0 (x / x0)^-k with k = ln(r0 / r1) / ln(x1 / x0): -d lambda / d ln x = k lambda.
  const double k = std::log(r0 / r1) / width;
  return k * r0 * std::pow(r1 / r0, std::log(x / x0) / width);
}

}  // namespace blockfrag
