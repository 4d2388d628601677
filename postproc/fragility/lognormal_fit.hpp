// The lognormal fragility curve fitted by maximum likelihood to binomial counts (Baker 2015):
// P(exceed | IM = x) = Phi(ln(x / median) / beta), with trials n_j and exceedances z_j at each
// intensity level x_j, maximising
//   ln L = sum_j [ln C(n_j, z_j) + z_j ln p_j + (n_j - z_j) ln(1 - p_j)].
// Some data have no maximum (all zeros, all ones, one level, separated levels): the fit then says
// which case it met and what the data still tell, instead of returning numbers that look like one.
#pragma once

#include <cstdint>
#include <limits>
#include <span>
#include <string>

#include "engine/errors.hpp"

namespace blockfrag {

class FitError : public ContractViolation {
 public:
  explicit FitError(const std::string& what) : ContractViolation(what) {}
};

enum class FitStatus {
  ok,              // the maximum exists and was found
  no_data,         // no level has any trial
  no_exceedances,  // every z_j = 0: the median lies above the largest level, beta is not identified
  all_exceedances,  // every z_j = n_j: the median lies below the smallest level
  single_level,     // one distinct level: only ln(x / median) / beta is identified
  separated,        // every level below some x has z = 0 and every one above has z = n (at most one
                    // level in between at x itself): the likelihood grows as beta -> 0
  no_trend,         // the probability does not grow with the intensity (or is the same at every
                    // level): the best curve is flat at the overall proportion, beta -> infinity
  not_converged,    // the iteration limit was reached (should not happen: reported, not hidden)
};

const char* fit_status_name(FitStatus status);

struct FitOptions {
  // Converged when |grad ln L| / (total trials) <= gradient_tolerance, the gradient taken with
  // respect to (ln median, ln beta): dividing by the trials makes it independent of the sample
  // size.
  double gradient_tolerance = 1e-10;
  int max_iterations = 100;
};

struct LognormalFit {
  static constexpr double nan = std::numeric_limits<double>::quiet_NaN();

  FitStatus status = FitStatus::no_data;
  bool converged = false;  // status == ok
  double median = nan;     // theta; NaN unless status == ok
  double beta = nan;       // NaN unless status == ok
  // ln L with the binomial coefficients, at the estimate when status == ok. For the other statuses
  // except not_converged it is the supremum of ln L, approached along the degenerate direction and
  // not attained (0 when there is no data).
  double log_likelihood = nan;
  // Where the data place the median: equal to it when status == ok; for no_exceedances
  // (largest level, inf), all_exceedances (0, smallest level), separated (the last level without
  // all exceedances, the first level with some; equal when one level sits at the separation),
  // single_level (x, inf), (0, x) or (x, x) as its proportion is below, above or at 1/2; (0, inf)
  // when nothing is known.
  double median_low = nan;
  double median_high = nan;
  int iterations = 0;
  double gradient_norm =
      nan;  // of ln L with respect to (ln median, ln beta); NaN unless status == ok
};

// im[j] > 0 and finite, trials[j] >= 0, 0 <= exceedances[j] <= trials[j], all of one size; levels
// without trials are ignored. Throws FitError naming the first offending level otherwise.
LognormalFit fit_lognormal_fragility(std::span<const double> im,
                                     std::span<const std::int64_t> trials,
                                     std::span<const std::int64_t> exceedances,
                                     const FitOptions& options = {});

// ln L as above at (median, beta), both > 0; same requirements on the data.
double lognormal_log_likelihood(std::span<const double> im, std::span<const std::int64_t> trials,
                                std::span<const std::int64_t> exceedances, double median,
                                double beta);

}  // namespace blockfrag
