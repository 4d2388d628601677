// What the fragility tests draw their data from: Phi, uniforms and binomial counts that are the
// same bits with every standard library (the std::*_distribution algorithms are each library's
// own), the counts a lognormal fit takes (with Baker's example), and the surface tests' grid of
// cells.
#pragma once

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "postproc/fragility/lognormal_fit.hpp"

namespace blockfrag::testing {

inline double normal_cdf(double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); }

// Uniforms in (0, 1) from mt19937_64's raw bits.
inline double uniform(std::mt19937_64& engine) {
  return (static_cast<double>(engine() >> 11) + 0.5) * 0x1.0p-53;
}

// A Binomial(n, p) count as a sum of Bernoulli trials: slow, and independent of the library's
// binomial_quantile.
inline std::int64_t binomial_draw(std::mt19937_64& engine, std::int64_t n, double p) {
  std::int64_t count = 0;
  for (std::int64_t i = 0; i < n; ++i) count += uniform(engine) < p ? 1 : 0;
  return count;
}

struct FragilityCounts {
  std::vector<double> im;
  std::vector<std::int64_t> trials;
  std::vector<std::int64_t> exceedances;
};

// Baker's (2015) multiple-stripe example: 40 records at each of eight levels (docs/references.md).
inline const FragilityCounts kBakerStripes{{0.2, 0.3, 0.4, 0.6, 0.7, 0.8, 0.9, 1.0},
                                           std::vector<std::int64_t>(8, 40),
                                           {0, 0, 0, 4, 6, 13, 12, 16}};

inline LognormalFit fit(const FragilityCounts& d) {
  return fit_lognormal_fragility(d.im, d.trials, d.exceedances);
}

// The surface tests' cells: pulse amplitudes (g) by pulse periods (s).
inline const std::vector<double> kSurfaceAmplitudes{0.3, 0.45, 0.65, 0.9, 1.3, 2.0};
inline const std::vector<double> kSurfacePeriods{0.5, 0.7, 1.0, 1.4, 2.0};

}  // namespace blockfrag::testing
