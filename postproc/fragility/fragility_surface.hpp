// A fragility surface over two intensity measures fitted by maximum likelihood to binomial counts
// on a grid of cells: P(exceed | IM1 = x1, IM2 = x2) = Phi(b0 + b1 ln x1 + b2 ln x2), with trials
// n_j and exceedances z_j in cell j, maximising
//   ln L = sum_j [ln C(n_j, z_j) + z_j ln p_j + (n_j - z_j) ln(1 - p_j)].
// For each IM2 it is a lognormal curve in IM1: ln median1(IM2) = -(b0 + b2 ln IM2) / b1 and
// beta1 = 1 / b1, the form engineers read. Data without a maximum (no exceedances, all, cells on
// one line, hits and misses separated by a line in (ln IM1, ln IM2)) get a status saying so and no
// coefficients.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <span>

namespace blockfrag {

enum class SurfaceFitStatus {
  ok,               // the maximum exists, was found, and rises with IM1 (b1 > 0)
  no_data,          // no cell has any trial
  no_exceedances,   // every z_j = 0
  all_exceedances,  // every z_j = n_j
  collinear,        // the cells with trials lie on one line in (ln IM1, ln IM2): b1 and b2 are not
                    // both identified (one level of either measure, for instance)
  separated,  // a line in (ln IM1, ln IM2) has every cell with an exceedance on one side and every
              // cell with a non-exceedance on the other (cells on it may have both): ln L grows
              // without bound along some direction of b
  not_increasing,  // the maximum has b1 <= 0: no fragility in IM1 (the coefficients are still
                   // the maximum, but there is no median form)
  not_converged,   // the iteration limit was reached (should not happen: reported, not hidden)
};

const char* surface_fit_status_name(SurfaceFitStatus status);

struct SurfaceFit {
  static constexpr double nan = std::numeric_limits<double>::quiet_NaN();

  SurfaceFitStatus status = SurfaceFitStatus::no_data;
  // b0, b1, b2 and their covariance (the inverse of the observed information at the maximum):
  // NaN unless status is ok or not_increasing.
  std::array<double, 3> coefficients{nan, nan, nan};
  std::array<std::array<double, 3>, 3> covariance{
      {{nan, nan, nan}, {nan, nan, nan}, {nan, nan, nan}}};
  std::array<double, 3> standard_errors{nan, nan, nan};
  double log_likelihood = nan;  // with the binomial coefficients, at the maximum
  int iterations = 0;
  // The Newton decrement g' H^-1 g at the estimate: the squared distance to the maximum in
  // standard errors, about (independent of the measures' units).
  double newton_decrement = nan;

  // The median form (status ok): ln median1(x2) = ln_median_intercept + ln_median_slope ln x2,
  // beta1 = 1 / b1, with standard errors by the delta method.
  double ln_median_intercept = nan, ln_median_intercept_se = nan;
  double ln_median_slope = nan, ln_median_slope_se = nan;
  double beta1 = nan, beta1_se = nan;

  // P at (x1, x2) > 0; NaN without coefficients.
  double probability(double x1, double x2) const;
  // The median of IM1 at IM2 = x2 (status ok), else NaN.
  double median_im1(double x2) const;
};

struct SurfaceFitOptions {
  // Converged when the Newton decrement is at most this: the estimate is within about 1e-5
  // standard errors of the maximum.
  double decrement_tolerance = 1e-10;
  int max_iterations = 200;
};

// im1[j], im2[j] > 0 and finite, trials[j] >= 0, 0 <= exceedances[j] <= trials[j], all of one
// size; cells without trials are ignored. Throws FitError naming the first offending cell
// otherwise. Separation is checked before iterating, in O(cells^3) when fewer than three cells
// with both outcomes span the plane (in O(cells) otherwise).
SurfaceFit fit_fragility_surface(std::span<const double> im1, std::span<const double> im2,
                                 std::span<const std::int64_t> trials,
                                 std::span<const std::int64_t> exceedances,
                                 const SurfaceFitOptions& options = {});

}  // namespace blockfrag
