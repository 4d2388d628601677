// How uncertain a lognormal fragility fit is, by the bootstrap: the data are resampled, the curve
// refitted, and the spread of the refitted medians, betas and curves gives 95 % intervals of the
// median and beta and a pointwise 95 % band of the curve. Stripes resample each level's samples
// (a binomial draw of its trials at its observed proportion); a cloud resamples its samples.
// The random numbers come from the caller, a function of (resample, draw), so that a study's
// bootstrap is a pure function of its seed, whatever ran it.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "postproc/fragility/lognormal_fit.hpp"

namespace blockfrag {

// A uniform in (0, 1): the draw-th number of the resample-th resample.
using UniformDraw = std::function<double(std::uint64_t resample, std::uint64_t draw)>;

struct BootstrapResult {
  int resamples = 0;  // asked for
  int fitted = 0;     // of them, those whose refit exists (status ok); the intervals are theirs
  double median_low, median_high;  // 2.5 % and 97.5 % of the refitted medians
  double beta_low, beta_high;
  // The pointwise band: at each intensity of `band_im`, the 2.5 % and 97.5 % of the refitted
  // curves' probabilities.
  std::vector<double> band_im, band_low, band_high;
};

// The band is drawn at 200 intensities from im_max / 200 to 1.1 im_max, im_max the largest
// intensity of the data: the range a plot of the curve shows.
BootstrapResult bootstrap_stripes(const std::vector<double>& im,
                                  const std::vector<std::int64_t>& trials,
                                  const std::vector<std::int64_t>& exceedances, int resamples,
                                  const UniformDraw& uniform);

BootstrapResult bootstrap_cloud(const std::vector<double>& im, const std::vector<bool>& exceeded,
                                int resamples, const UniformDraw& uniform);

// The refitted curves of a stripe study's resamples, in order (each with its status): what
// bootstrap_stripes summarises, for a caller that needs each resample's curve (the risk of a
// limit state per resample, postproc/risk/).
std::vector<LognormalFit> bootstrap_stripe_fits(const std::vector<double>& im,
                                                const std::vector<std::int64_t>& trials,
                                                const std::vector<std::int64_t>& exceedances,
                                                int resamples, const UniformDraw& uniform);

// The exceedances of resample b: each level's count drawn from Binomial(trials, observed
// proportion) by the b-th resample's uniforms.
std::vector<std::int64_t> resampled_exceedances(const std::vector<std::int64_t>& trials,
                                                const std::vector<std::int64_t>& exceedances,
                                                std::uint64_t resample, const UniformDraw& uniform);

// The k with P(X <= k - 1) < u <= P(X <= k) for X ~ Binomial(n, p): the inverse CDF, by GSL's CDF
// in the tail where u lies (a few evaluations from the Cornish-Fisher approximation), right to the
// CDF's accuracy for u however close to 0 or 1.
std::int64_t binomial_quantile(double u, std::int64_t n, double p);

}  // namespace blockfrag
