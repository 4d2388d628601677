#include "postproc/fragility/bootstrap.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include <gsl/gsl_cdf.h>

#include "postproc/fragility/lognormal_fit.hpp"
#include "postproc/fragility/normal_probability.hpp"
#include "postproc/fragility/sample_quantile.hpp"

namespace blockfrag {
namespace {

constexpr int kBandPoints = 200;

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
  result.median_low = sample_quantile(medians, 0.025);
  result.median_high = sample_quantile(medians, 0.975);
  result.beta_low = sample_quantile(betas, 0.025);
  result.beta_high = sample_quantile(betas, 0.975);
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
    result.band_low.push_back(sample_quantile(probabilities, 0.025));
    result.band_high.push_back(sample_quantile(probabilities, 0.975));
  }
  return result;
}

}  // namespace

std::int64_t binomial_quantile(double u, std::int64_t n, double p) {
  if (n <= 0 || p <= 0.0 || !(u > 0.0)) return 0;
  if (p >= 1.0 || u >= 1.0) return n;
  // Whether P(X <= k) >= u, compared in the tail where u lies: P for u <= 1/2, and above it
  // P(X > k) <= 1 - u (exact there), so that a u within 1e-12 of 0 or 1 is resolved.
  const auto nu = static_cast<unsigned>(n);
  const auto reaches = [&](std::int64_t k) {
    if (k < 0) return false;
    if (k >= n) return true;
    const auto ku = static_cast<unsigned>(k);
    return u <= 0.5 ? gsl_cdf_binomial_P(ku, p, nu) >= u : gsl_cdf_binomial_Q(ku, p, nu) <= 1.0 - u;
  };
  // Start at the Cornish-Fisher approximation (the normal quantile corrected for skewness),
  // bracket the answer by steps that double, and bisect: P(lo) < u <= P(hi) throughout.
  const auto nd = static_cast<double>(n);
  const double sigma = std::sqrt(nd * p * (1.0 - p)), z = gsl_cdf_ugaussian_Pinv(u);
  const double guess =
      std::floor(nd * p + sigma * (z + (1.0 - 2.0 * p) / sigma * (z * z - 1.0) / 6.0) + 0.5);
  const auto start = static_cast<std::int64_t>(guess > 0.0 ? std::min(guess, nd) : 0.0);
  std::int64_t lo = start - 1, hi = start;
  if (reaches(start)) {
    for (std::int64_t step = 1; reaches(lo); step *= 2) {
      hi = lo;
      lo = std::max<std::int64_t>(lo - step, -1);
    }
  } else {
    lo = start;
    hi = start + 1;
    for (std::int64_t step = 1; !reaches(hi); step *= 2) {
      lo = hi;
      hi = std::min(hi + step, n);
    }
  }
  while (hi - lo > 1) {
    const std::int64_t mid = lo + (hi - lo) / 2;
    (reaches(mid) ? hi : lo) = mid;
  }
  return hi;
}

std::vector<std::int64_t> resampled_exceedances(const std::vector<std::int64_t>& trials,
                                                const std::vector<std::int64_t>& exceedances,
                                                std::uint64_t resample,
                                                const UniformDraw& uniform) {
  std::vector<std::int64_t> drawn(trials.size());
  for (std::size_t j = 0; j < trials.size(); ++j) {
    const double p =
        trials[j] > 0 ? static_cast<double>(exceedances[j]) / static_cast<double>(trials[j]) : 0.0;
    drawn[j] = binomial_quantile(uniform(resample, j), trials[j], p);
  }
  return drawn;
}

std::vector<LognormalFit> bootstrap_stripe_fits(const std::vector<double>& im,
                                                const std::vector<std::int64_t>& trials,
                                                const std::vector<std::int64_t>& exceedances,
                                                int resamples, const UniformDraw& uniform) {
  std::vector<LognormalFit> fits;
  fits.reserve(static_cast<std::size_t>(std::max(resamples, 0)));
  std::vector<std::int64_t> previous;
  for (int b = 0; b < resamples; ++b) {
    std::vector<std::int64_t> drawn =
        resampled_exceedances(trials, exceedances, static_cast<std::uint64_t>(b), uniform);
    // A level observed at 0 or 1 draws its own count every time, so where every level is (a grid
    // of one sample a level) all resamples are the data: the fit, a pure function of the counts,
    // is taken once for a run of equal draws.
    if (drawn == previous) {
      fits.push_back(fits.back());
    } else {
      fits.push_back(fit_lognormal_fragility(im, trials, drawn));
      previous = std::move(drawn);
    }
  }
  return fits;
}

BootstrapResult bootstrap_stripes(const std::vector<double>& im,
                                  const std::vector<std::int64_t>& trials,
                                  const std::vector<std::int64_t>& exceedances, int resamples,
                                  const UniformDraw& uniform) {
  const auto fits = bootstrap_stripe_fits(im, trials, exceedances, resamples, uniform);
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
