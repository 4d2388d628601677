#include "postproc/fragility/lognormal_fit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <gsl/gsl_cdf.h>
#include <gsl/gsl_math.h>
#include <gsl/gsl_sf_erf.h>

#include "postproc/fragility/backtracking_line_search.hpp"
#include "postproc/fragility/normal_probability.hpp"

// The fit works in probit coordinates: p_j = Phi(a + s (u_j - centre)), u_j = ln x_j, s = 1 / beta,
// a = (centre - ln median) / beta. There ln L is concave (Pratt 1981), so Newton's method with a
// backtracking line search climbs to the maximum from any start, and whether that maximum exists is
// decided by the data alone (Albert & Anderson 1984: it does unless the levels are separated),
// which is checked before iterating. Centring u at the trials-weighted mean of ln x decouples a
// from s and makes the result independent of the units of the intensity measure.

namespace blockfrag {
namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

struct Level {
  double u;  // ln im
  double n;
  double z;
};

std::vector<Level> checked_levels(std::span<const double> im, std::span<const std::int64_t> trials,
                                  std::span<const std::int64_t> exceedances) {
  if (trials.size() != im.size() || exceedances.size() != im.size())
    throw FitError("lognormal fit: im, trials and exceedances differ in size (" +
                   std::to_string(im.size()) + ", " + std::to_string(trials.size()) + ", " +
                   std::to_string(exceedances.size()) + ")");
  std::vector<Level> levels;
  for (std::size_t j = 0; j < im.size(); ++j) {
    const std::string where = "lognormal fit: level " + std::to_string(j) + ": ";
    if (!(std::isfinite(im[j]) && im[j] > 0.0))
      throw FitError(where + "im must be finite and > 0 (got " + std::to_string(im[j]) + ")");
    if (trials[j] < 0)
      throw FitError(where + "trials must be >= 0 (got " + std::to_string(trials[j]) + ")");
    if (exceedances[j] < 0 || exceedances[j] > trials[j])
      throw FitError(where + "exceedances must lie in [0, trials] (got " +
                     std::to_string(exceedances[j]) + " of " + std::to_string(trials[j]) + ")");
    if (trials[j] > 0)
      levels.push_back(
          {std::log(im[j]), static_cast<double>(trials[j]), static_cast<double>(exceedances[j])});
  }
  return levels;
}

// z ln p + (n - z) ln(1 - p) over all levels with the binomial coefficients, p = p(level); terms
// with a zero count are left out so that p = 0 or 1 where it should be gives 0, not NaN.
template <class Probability>
double binomial_log_likelihood(const std::vector<Level>& levels, const Probability& probability) {
  double sum = 0.0;
  for (const auto& level : levels) {
    const double p = probability(level);
    sum += log_choose(level.n, level.z);
    if (level.z > 0.0) sum += level.z * std::log(p);
    if (level.n > level.z) sum += (level.n - level.z) * std::log1p(-p);
  }
  return sum;
}

// The supremum of ln L when the curve cannot rise: a flat one at the overall proportion.
double flat_log_likelihood(const std::vector<Level>& levels) {
  double n_total = 0.0, z_total = 0.0;
  for (const auto& level : levels) {
    n_total += level.n;
    z_total += level.z;
  }
  return binomial_log_likelihood(levels, [&](const Level&) { return z_total / n_total; });
}

struct ProbitPoint {
  double a, s;
};

struct ProbitEvaluation {
  double log_likelihood = 0.0;
  // ln L without the binomial coefficients, and the sum of its terms' magnitudes: what ln L can
  // resolve is set by the terms (~ trials each), not by their sum, which may be small.
  double kernel = 0.0, kernel_scale = 0.0;
  double gradient_a = 0.0, gradient_s = 0.0;                          // of ln L
  double curvature_aa = 0.0, curvature_as = 0.0, curvature_ss = 0.0;  // of -ln L, positive definite
  double gradient_log_median = 0.0, gradient_log_beta = 0.0;
};

ProbitEvaluation evaluate(const std::vector<Level>& levels, double centre, ProbitPoint point) {
  ProbitEvaluation e;
  const double log_sqrt_2pi = 0.5 * std::log(2.0 * M_PI);
  for (const auto& level : levels) {
    const double v = level.u - centre;
    const double eta = point.a + point.s * v;
    const double misses = level.n - level.z;
    // Mills ratios phi / Phi and phi / (1 - Phi) from logarithms: finite in both tails. Each is
    // needed only where its count is not zero (a level of one trial needs one of the two).
    const double log_density = -0.5 * eta * eta - log_sqrt_2pi;
    double hit_term = 0.0, miss_term = 0.0, ratio_p = 0.0, ratio_q = 0.0;
    if (level.z > 0.0) {
      const double log_p = log_normal_cdf(eta);
      hit_term = level.z * log_p;
      ratio_p = std::exp(log_density - log_p);
    }
    if (misses > 0.0) {
      const double log_q = log_normal_cdf(-eta);
      miss_term = misses * log_q;
      ratio_q = std::exp(log_density - log_q);
    }
    e.kernel += hit_term + miss_term;
    e.kernel_scale -= hit_term + miss_term;  // both terms are <= 0
    e.log_likelihood += log_choose(level.n, level.z) + hit_term + miss_term;
    const double slope = level.z * ratio_p - misses * ratio_q;
    const double weight = std::max(0.0, level.z * ratio_p * (eta + ratio_p)) +
                          std::max(0.0, misses * ratio_q * (ratio_q - eta));
    e.gradient_a += slope;
    e.gradient_s += slope * v;
    e.curvature_aa += weight;
    e.curvature_as += weight * v;
    e.curvature_ss += weight * v * v;
    // d eta / d ln median = -s and d eta / d ln beta = -eta.
    e.gradient_log_median -= point.s * slope;
    e.gradient_log_beta -= eta * slope;
  }
  return e;
}

// Levels pooled by distinct im, in increasing order: separation is a property of those.
std::vector<Level> pooled_by_im(std::vector<Level> levels) {
  std::sort(levels.begin(), levels.end(), [](const Level& l, const Level& r) { return l.u < r.u; });
  std::vector<Level> pooled;
  for (const auto& level : levels) {
    if (!pooled.empty() && pooled.back().u == level.u) {
      pooled.back().n += level.n;
      pooled.back().z += level.z;
    } else {
      pooled.push_back(level);
    }
  }
  return pooled;
}

LognormalFit degenerate(FitStatus status, double log_likelihood, double median_low,
                        double median_high) {
  LognormalFit fit;
  fit.status = status;
  fit.log_likelihood = log_likelihood;
  fit.median_low = median_low;
  fit.median_high = median_high;
  return fit;
}

// The data cases without a maximum, each with the supremum of ln L: a curve that matches the
// proportion at every distinct level where the data are separated, a flat curve at the overall
// proportion where they do not increase.
std::optional<LognormalFit> degenerate_case(const std::vector<Level>& levels) {
  if (levels.empty()) return degenerate(FitStatus::no_data, 0.0, 0.0, inf);
  const auto pooled = pooled_by_im(levels);
  double n_total = 0.0, z_total = 0.0;
  for (const auto& level : levels) {
    n_total += level.n;
    z_total += level.z;
  }
  auto pooled_proportion = [&pooled](const Level& level) {
    const auto at = std::lower_bound(pooled.begin(), pooled.end(), level.u,
                                     [](const Level& l, double u) { return l.u < u; });
    return at->z / at->n;
  };
  const double saturated = binomial_log_likelihood(levels, pooled_proportion);
  const double lowest = std::exp(pooled.front().u), highest = std::exp(pooled.back().u);

  if (z_total == 0.0) return degenerate(FitStatus::no_exceedances, saturated, highest, inf);
  if (z_total == n_total) return degenerate(FitStatus::all_exceedances, saturated, 0.0, lowest);
  if (pooled.size() == 1) {
    const double p = z_total / n_total;
    return degenerate(FitStatus::single_level, saturated, p <= 0.5 ? lowest : 0.0,
                      p >= 0.5 ? lowest : inf);
  }
  // u of the first level with any exceedance and of the last without all, and the reverse pair.
  const auto first_hit =
      std::find_if(pooled.begin(), pooled.end(), [](const Level& l) { return l.z > 0.0; })->u;
  const auto last_miss =
      std::find_if(pooled.rbegin(), pooled.rend(), [](const Level& l) { return l.z < l.n; })->u;
  const auto last_hit =
      std::find_if(pooled.rbegin(), pooled.rend(), [](const Level& l) { return l.z > 0.0; })->u;
  const auto first_miss =
      std::find_if(pooled.begin(), pooled.end(), [](const Level& l) { return l.z < l.n; })->u;
  if (last_miss <= first_hit)
    return degenerate(FitStatus::separated, saturated, std::exp(last_miss), std::exp(first_hit));
  if (last_hit <= first_miss)
    return degenerate(FitStatus::no_trend, flat_log_likelihood(levels), 0.0, inf);
  return std::nullopt;
}

// The classical linearised start: least squares of probit((z + 1/2) / (n + 1)) on u - centre,
// weighted by the trials; a curve spanning the levels when that slope is not positive.
ProbitPoint starting_point(const std::vector<Level>& levels, double centre, double n_total) {
  double mean_y = 0.0, sxy = 0.0, sxx = 0.0;
  for (const auto& level : levels)
    mean_y += level.n * gsl_cdf_ugaussian_Pinv((level.z + 0.5) / (level.n + 1.0));
  mean_y /= n_total;
  for (const auto& level : levels) {
    const double v = level.u - centre;
    const double y = gsl_cdf_ugaussian_Pinv((level.z + 0.5) / (level.n + 1.0));
    sxy += level.n * v * (y - mean_y);
    sxx += level.n * v * v;
  }
  const double slope = sxy / sxx;
  return {mean_y, slope > 0.0 ? slope : 1.0 / std::sqrt(sxx / n_total)};
}

double gradient_norm(const ProbitEvaluation& e) {
  return std::hypot(e.gradient_log_median, e.gradient_log_beta);
}

// Stationary in the probit coordinates, and in the fragility ones when they exist (s > 0): near
// s = 0 the map between them degenerates and either test alone could pass too early.
bool stationary(const ProbitEvaluation& e, double s, double tolerance) {
  return std::hypot(e.gradient_a, e.gradient_s) <= tolerance &&
         (s <= 0.0 || gradient_norm(e) <= tolerance);
}

// Where the Newton iteration stopped, after how many steps, and whether it was stationary there.
struct ProbitClimb {
  ProbitPoint point;
  ProbitEvaluation e;
  int iterations = 0;
  bool converged = false;
};

// One step up ln L from point, e updated with it; false when even the shortest step gains nothing
// (rounding alone is left).
bool climb_one_step(const std::vector<Level>& levels, double centre, ProbitPoint& point,
                    ProbitEvaluation& e) {
  // Newton's step on the concave ln L; steepest ascent if the curvature is numerically singular.
  const double det = e.curvature_aa * e.curvature_ss - e.curvature_as * e.curvature_as;
  const bool newton = det > 1e-12 * e.curvature_aa * e.curvature_ss;
  const double da =
      newton ? (e.curvature_ss * e.gradient_a - e.curvature_as * e.gradient_s) / det : e.gradient_a;
  const double ds =
      newton ? (e.curvature_aa * e.gradient_s - e.curvature_as * e.gradient_a) / det : e.gradient_s;
  const double predicted = e.gradient_a * da + e.gradient_s * ds;
  ProbitPoint trial = point;
  ProbitEvaluation trial_e;
  const auto kernel_at = [&](double t) {
    trial = {point.a + t * da, point.s + t * ds};
    trial_e = evaluate(levels, centre, trial);
    return trial_e.kernel;
  };
  if (!backtracking_line_search({e.kernel, e.kernel_scale, predicted, newton}, kernel_at))
    return false;
  point = trial;
  e = trial_e;
  return true;
}

ProbitClimb climb_to_maximum(const std::vector<Level>& levels, double centre, double tolerance,
                             int max_iterations, const ProbitPoint& start) {
  ProbitClimb climb{start, evaluate(levels, centre, start)};
  for (; climb.iterations < max_iterations; ++climb.iterations) {
    if (stationary(climb.e, climb.point.s, tolerance)) {
      climb.converged = true;
      break;
    }
    if (!climb_one_step(levels, centre, climb.point, climb.e)) break;
  }
  return climb;
}

// The fit where the climb stopped: not converged, flat (no_trend) or the maximum's median and beta.
LognormalFit fit_at_maximum(const std::vector<Level>& levels, double centre,
                            const ProbitClimb& climb) {
  const ProbitPoint& point = climb.point;
  LognormalFit fit;
  fit.iterations = climb.iterations;
  fit.log_likelihood = climb.e.log_likelihood;
  if (!climb.converged) {
    fit.status = FitStatus::not_converged;
    fit.median_low = 0.0;
    fit.median_high = inf;
    return fit;
  }
  // The unconstrained maximum has a falling curve, or one flat to rounding over the levels (equal
  // proportions everywhere: median and beta then overflow): under beta > 0 the best is a flat one.
  const auto [lowest, highest] = std::minmax_element(
      levels.begin(), levels.end(), [](const Level& l, const Level& r) { return l.u < r.u; });
  const double median = std::exp(centre - point.a / point.s);
  if (!(point.s * (highest->u - lowest->u) > 1e-9) || !std::isfinite(median) || median == 0.0) {
    auto flat = degenerate(FitStatus::no_trend, flat_log_likelihood(levels), 0.0, inf);
    flat.iterations = climb.iterations;
    return flat;
  }
  fit.status = FitStatus::ok;
  fit.converged = true;
  fit.median = median;
  fit.beta = 1.0 / point.s;
  fit.median_low = fit.median_high = fit.median;
  fit.gradient_norm = gradient_norm(climb.e);
  return fit;
}

}  // namespace

const char* fit_status_name(FitStatus status) {
  switch (status) {
    case FitStatus::ok: return "ok";
    case FitStatus::no_data: return "no_data";
    case FitStatus::no_exceedances: return "no_exceedances";
    case FitStatus::all_exceedances: return "all_exceedances";
    case FitStatus::single_level: return "single_level";
    case FitStatus::separated: return "separated";
    case FitStatus::no_trend: return "no_trend";
    case FitStatus::not_converged: return "not_converged";
  }
  return "unknown";
}

LognormalFit fit_lognormal_fragility(std::span<const double> im,
                                     std::span<const std::int64_t> trials,
                                     std::span<const std::int64_t> exceedances,
                                     const FitOptions& options) {
  if (!(options.gradient_tolerance > 0.0) || options.max_iterations <= 0)
    throw FitError("lognormal fit: gradient_tolerance and max_iterations must be > 0");
  const auto levels = checked_levels(im, trials, exceedances);
  if (auto result = degenerate_case(levels)) return *result;

  double n_total = 0.0, centre = 0.0;
  for (const auto& level : levels) {
    n_total += level.n;
    centre += level.n * level.u;
  }
  centre /= n_total;
  const double tolerance = options.gradient_tolerance * n_total;
  const ProbitClimb climb = climb_to_maximum(levels, centre, tolerance, options.max_iterations,
                                             starting_point(levels, centre, n_total));
  return fit_at_maximum(levels, centre, climb);
}

double lognormal_log_likelihood(std::span<const double> im, std::span<const std::int64_t> trials,
                                std::span<const std::int64_t> exceedances, double median,
                                double beta) {
  if (!(median > 0.0 && beta > 0.0))
    throw FitError("lognormal log-likelihood: median and beta must be > 0");
  const auto levels = checked_levels(im, trials, exceedances);
  return evaluate(levels, 0.0, {-std::log(median) / beta, 1.0 / beta}).log_likelihood;
}

}  // namespace blockfrag
