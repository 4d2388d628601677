// The standard normal's distribution function and the binomial coefficient, as the fragility fits
// and their diagnostics use them.
#pragma once

#include <cmath>

#include <gsl/gsl_math.h>
#include <gsl/gsl_sf_erf.h>

namespace blockfrag {

// Phi(x).
inline double normal_cdf(double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); }

// ln Phi(eta), accurate far into the lower tail where Phi itself underflows.
inline double log_normal_cdf(double eta) { return gsl_sf_log_erfc(-eta / M_SQRT2) - M_LN2; }

// ln (n choose z), for counts held as doubles.
inline double log_choose(double n, double z) {
  return std::lgamma(n + 1.0) - std::lgamma(z + 1.0) - std::lgamma(n - z + 1.0);
}

}  // namespace blockfrag
