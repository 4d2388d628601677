#include "postproc/fragility/bootstrap.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <gsl/gsl_cdf.h>
#include <gsl/gsl_randist.h>

#include "postproc/fragility/lognormal_fit.hpp"

namespace blockfrag {
namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();
constexpr int kBandPoints = 200;

double normal_cdf(double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); }

// The q-quantile of values (sorted here), interpolated between order statistics (Hyndman & Fan
// type 7, numpy's default).
double quantile(std::vector<double> values, double q) {
  if (values.empty()) return nan;
  std::sort(values.begin(), values.end());
  const double position = q * static_cast<double>(values.size() - 1);
  const auto below = static_cast<std::size_t>(std::floor(position));
  const std::size_t above = std::min(below + 1, values.size() - 1);
  const double weight = position - static_cast<double>(below);
  return values[below] + weight * (values[above] - values[below]);
}

// The intervals and the band from the refits that exist.
BootstrapResult summarise(int resamples, const std::vector<LognormalFit>& fits, double im_max) {
  BootstrapResult result;
  result.resamples = resamples;
  std::vector<double> medians, betas;
  for (const auto& fit : fits) {
    if (fit.status != FitStatus::ok) continue;
    medians.push_back(fit.median);
    betas.push_back(fit.beta);
  }
  result.fitted = static_cast<int>(medians.size());
  result.median_low = quantile(medians, 0.025);
  result.median_high = quantile(medians, 0.975);
  result.beta_low = quantile(betas, 0.025);
  result.beta_high = quantile(betas, 0.975);
  // Evenly spaced from im_max / 200 to 1.1 im_max, both included.
  const double first = im_max / kBandPoints, last = 1.1 * im_max;
  for (int k = 0; k < kBandPoints; ++k) {
    const double x = first + (last - first) * k / (kBandPoints - 1);
    std::vector<double> probabilities;
    probabilities.reserve(medians.size());
    for (std::size_t b = 0; b < medians.size(); ++b) {
      probabilities.push_back(normal_cdf(std::log(x / medians[b]) / betas[b]));
    }
    result.band_im.push_back(x);
    result.band_low.push_back(quantile(probabilities, 0.025));
    result.band_high.push_back(quantile(probabilities, 0.975));
  }
  return result;
}

}  // namespace

std::int64_t binomial_quantile(double u, std::int64_t n, double p) {
  if (n <= 0 || p <= 0.0) return 0;
  if (p >= 1.0) return n;
  const auto nd = static_cast<double>(n);
  auto k = static_cast<std::int64_t>(std::floor((nd + 1) * p));
  k = std::min(k, n);
  const double ratio = p / (1.0 - p);
  double cdf = gsl_cdf_binomial_P(static_cast<unsigned>(k), p, static_cast<unsigned>(n));
  double pmf = gsl_ran_binomial_pdf(static_cast<unsigned>(k), p, static_cast<unsigned>(n));
  if (u <= cdf) {
    // Down: P(X <= k - 1) = P(X <= k) - pmf(k), pmf(k - 1) = pmf(k) k / ((n - k + 1) ratio).
    while (k > 0) {
      const double below = cdf - pmf;
      if (u > below) break;
      pmf *= static_cast<double>(k) / ((nd - static_cast<double>(k) + 1.0) * ratio);
      cdf = below;
      --k;
    }
    return k;
  }
  // Up: pmf(k + 1) = pmf(k) (n - k) ratio / (k + 1).
  while (k < n && u > cdf) {
    pmf *= (nd - static_cast<double>(k)) * ratio / static_cast<double>(k + 1);
    cdf += pmf;
    ++k;
  }
  return k;
}

BootstrapResult bootstrap_stripes(const std::vector<double>& im,
                                  const std::vector<std::int64_t>& trials,
                                  const std::vector<std::int64_t>& exceedances, int resamples,
                                  const UniformDraw& uniform) {
  std::vector<LognormalFit> fits;
  fits.reserve(static_cast<std::size_t>(resamples));
  std::vector<std::int64_t> drawn(im.size());
  for (int b = 0; b < resamples; ++b) {
    for (std::size_t j = 0; j < im.size(); ++j) {
      const double p = trials[j] > 0
                           ? static_cast<double>(exceedances[j]) / static_cast<double>(trials[j])
                           : 0.0;
      drawn[j] = binomial_quantile(uniform(static_cast<std::uint64_t>(b), j), trials[j], p);
    }
    fits.push_back(fit_lognormal_fragility(im, trials, drawn));
  }
  const double im_max = im.empty() ? 1.0 : *std::max_element(im.begin(), im.end());
  return summarise(resamples, fits, im_max);
}

BootstrapResult bootstrap_cloud(const std::vector<double>& im, const std::vector<bool>& exceeded,
                                int resamples, const UniformDraw& uniform) {
  std::vector<LognormalFit> fits;
  fits.reserve(static_cast<std::size_t>(resamples));
  const std::size_t n = im.size();
  std::vector<double> drawn_im(n);
  std::vector<std::int64_t> ones(n, 1), drawn_exceeded(n);
  for (int b = 0; b < resamples; ++b) {
    for (std::size_t i = 0; i < n; ++i) {
      // Each draw picks one of the n samples, every one as likely.
      const auto k =
          std::min(n - 1, static_cast<std::size_t>(uniform(static_cast<std::uint64_t>(b), i) *
                                                   static_cast<double>(n)));
      drawn_im[i] = im[k];
      drawn_exceeded[i] = exceeded[k] ? 1 : 0;
    }
    fits.push_back(fit_lognormal_fragility(drawn_im, ones, drawn_exceeded));
  }
  const double im_max = im.empty() ? 1.0 : *std::max_element(im.begin(), im.end());
  return summarise(resamples, fits, im_max);
}

}  // namespace blockfrag
