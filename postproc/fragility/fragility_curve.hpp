// A fragility curve from binomial counts: per intensity level the empirical probability with its
// Wilson 95 % interval, and the lognormal maximum-likelihood fit over the counts.
#pragma once

#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "postproc/fragility/bootstrap.hpp"

namespace blockfrag {

struct LognormalFit;
struct GoodnessOfFit;

struct FragilityCurve {
  std::vector<double> im;
  std::vector<std::int64_t> trials;
  std::vector<std::int64_t> exceedances;
  std::vector<double> probability;  // exceedances / trials; NaN without trials
  std::vector<double> ci_low;
  std::vector<double> ci_high;
  double median;  // of the lognormal fit; NaN when the fit does not exist
  double beta;
  double log_likelihood;  // binomial log-likelihood at the fit, coefficients included; NaN likewise
  std::string fit_status;  // FitStatus's name: "ok", "no_exceedances", "separated", ...
  double median_low;       // where the data place the median when the fit does not exist
  double median_high;
  // With a fit: its standard errors from the observed information, and its goodness of fit
  // (postproc/fragility/fit_diagnostics.hpp); NaN (dof 0) without one.
  double median_se = std::numeric_limits<double>::quiet_NaN();
  double beta_se = std::numeric_limits<double>::quiet_NaN();
  double deviance = std::numeric_limits<double>::quiet_NaN();
  int gof_dof = 0;
  double gof_p_value = std::numeric_limits<double>::quiet_NaN();
  double max_misfit = std::numeric_limits<double>::quiet_NaN();
  // The bootstrap's intervals and band (postproc/fragility/bootstrap.hpp); resamples 0 when not
  // run.
  BootstrapResult bootstrap;
};

// im[k] is level k's intensity, trials[k] its samples, exceedances[k] those past the limit state.
FragilityCurve fragility_from_counts(std::vector<double> im, std::vector<std::int64_t> trials,
                                     std::vector<std::int64_t> exceedances);

// The fit's status and the bounds the data place on its median; with a fit (status ok) its median,
// beta, log-likelihood and their standard errors over the counts it was fitted to, NaN without.
// The binned and the cloud curves (cloud_fragility.hpp) report their fits alike.
void fill_lognormal_fit(FragilityCurve& curve, const LognormalFit& fit, std::span<const double> im,
                        std::span<const std::int64_t> trials,
                        std::span<const std::int64_t> exceedances);

void fill_goodness_of_fit(FragilityCurve& curve, const GoodnessOfFit& gof);

}  // namespace blockfrag
