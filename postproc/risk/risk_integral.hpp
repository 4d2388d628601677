// The mean annual frequency of a limit state at a site: its fragility integrated against the
// site's hazard curve,
//   lambda_LS = integral P(LS | x) |d lambda(x)|
// (USBR/USACE risk practice; Cornell et al. 2002, whose closed form for a power-law hazard
// k0 x^-k and a lognormal fragility, k0 theta^-k exp(k^2 beta^2 / 2), tests it). The integral
// runs over the hazard curve's intensities, per segment between two of them (the bins, "which
// shaking matters"), and says how much of it comes from intensities beyond the study's levels,
// where the fragility is not observed but extrapolated (a fit) or held at its end value (the
// points). Motions stronger than the hazard curve's last intensity, whose rate is that
// intensity's, count with the fragility at it; motions weaker than its first are not counted
// (the rate below the curve is unknown, and unbounded where an OpenQuake curve has poe = 1).
#pragma once

#include <functional>
#include <vector>

#include "postproc/risk/hazard_curve.hpp"

namespace blockfrag {

// P(LS | x): a number in [0, 1] for x > 0.
using ExceedanceProbability = std::function<double(double x)>;

struct RiskIntegral {
  double lambda = 0.0;  // per year, everything counted
  // Of lambda: from intensities below the study's lowest level, and above its highest.
  double lambda_below_levels = 0.0;
  double lambda_above_levels = 0.0;
  // Of lambda: from motions stronger than the hazard curve's last intensity (its rate times
  // P(LS) there: a lower bound on theirs when P(LS) grows, its rate an upper one).
  double lambda_beyond_hazard = 0.0;
  // bin_lambda[i]: from intensities between the hazard curve's im[i] and im[i + 1].
  std::vector<double> bin_lambda;

  // The share of lambda from intensities beyond the study's levels (0 when lambda is 0).
  double share_beyond_levels() const;
};

// `levels` are the study's intensity levels, increasing, where the fragility is observed; the
// integral is split at each of them (the points' kinks) and at the hazard curve's intensities.
RiskIntegral integrate_risk(const HazardCurve& hazard, const ExceedanceProbability& probability,
                            const std::vector<double>& levels);

// A lognormal fragility: Phi(ln(x / median) / beta).
ExceedanceProbability lognormal_exceedance(double median, double beta);

// The observed points: straight in ln x between the levels (increasing, with their probability
// in [0, 1]), held at the end values beyond them.
ExceedanceProbability points_exceedance(std::vector<double> levels,
                                        std::vector<double> probability);

// 1 - exp(-lambda t): the probability of at least one occurrence in t years.
double probability_in_years(double lambda, double years);

}  // namespace blockfrag
