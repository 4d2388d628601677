#include "postproc/fragility/nested_fit.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_linalg.h>
#include <gsl/gsl_matrix.h>

#include "postproc/fragility/normal_probability.hpp"

namespace blockfrag {
namespace {

// The common beta is looked for in [kMinBeta, kMaxBeta]; each ln theta within kMedianReach
// betas of the levels.
constexpr double kMinBeta = 0.005;
constexpr double kMaxBeta = 10.0;
constexpr double kMedianReach = 20.0;
// Golden-section search stops when the bracket is this narrow (in ln theta or ln beta): the
// maximum's value is then exact to rounding, its place to about 1e-8 relative (a maximum is flat).
constexpr double kBracketTolerance = 1e-11;
// Central differences of ln L for its Hessian, in ln theta and ln beta.
constexpr double kHessianStep = 1e-4;

// One state's binomial ln L (coefficients included) at ln theta = u and beta.
double state_log_likelihood(const NestedStateData& state, double u, double beta) {
  double sum = 0.0;
  for (std::size_t j = 0; j < state.im.size(); ++j) {
    const auto n = static_cast<double>(state.trials[j]);
    if (n <= 0.0) continue;
    const auto z = static_cast<double>(state.exceedances[j]);
    const double eta = (std::log(state.im[j]) - u) / beta;
    sum += log_choose(n, z);
    if (z > 0.0) sum += z * log_normal_cdf(eta);
    if (n > z) sum += (n - z) * log_normal_cdf(-eta);
  }
  return sum;
}

// The x in [low, high] maximising a unimodal f, by golden section.
double golden_maximum(const std::function<double(double)>& f, double low, double high) {
  const double ratio = 0.5 * (std::sqrt(5.0) - 1.0);
  double a = low, b = high;
  double c = b - ratio * (b - a), d = a + ratio * (b - a);
  double fc = f(c), fd = f(d);
  while (b - a > kBracketTolerance * std::max(1.0, std::abs(a) + std::abs(b))) {
    if (fc >= fd) {
      b = d;
      d = c;
      fd = fc;
      c = b - ratio * (b - a);
      fc = f(c);
    } else {
      a = c;
      c = d;
      fc = fd;
      d = a + ratio * (b - a);
      fd = f(d);
    }
  }
  return 0.5 * (a + b);
}

struct MedianSearch {
  double low, high;  // ln theta's range
};

MedianSearch median_range(const NestedStateData& state) {
  const auto [lowest, highest] = std::minmax_element(state.im.begin(), state.im.end());
  return {std::log(*lowest) - kMedianReach * kMaxBeta,
          std::log(*highest) + kMedianReach * kMaxBeta};
}

// ln theta maximising one state's ln L at this beta (the log-likelihood is concave in it).
double best_log_median(const NestedStateData& state, double beta) {
  const MedianSearch range = median_range(state);
  return golden_maximum([&](double u) { return state_log_likelihood(state, u, beta); }, range.low,
                        range.high);
}

double profile_log_likelihood(const std::vector<NestedStateData>& states, double beta) {
  double sum = 0.0;
  for (const auto& state : states) {
    sum += state_log_likelihood(state, best_log_median(state, beta), beta);
  }
  return sum;
}

// ln L at p = (ln theta_1 .. ln theta_K, ln beta).
double joint_log_likelihood(const std::vector<NestedStateData>& states,
                            const std::vector<double>& p) {
  const double beta = std::exp(p.back());
  double sum = 0.0;
  for (std::size_t k = 0; k < states.size(); ++k) {
    sum += state_log_likelihood(states[k], p[k], beta);
  }
  return sum;
}

// The standard errors of p from the inverse of minus ln L's Hessian (central differences); NaN
// when it is not positive definite.
std::vector<double> standard_errors(const std::vector<NestedStateData>& states,
                                    const std::vector<double>& p) {
  const std::size_t m = p.size();
  const double h = kHessianStep;
  gsl_matrix* information = gsl_matrix_alloc(m, m);
  const auto at = [&](std::size_t i, double di, std::size_t j, double dj) {
    std::vector<double> q = p;
    q[i] += di;
    q[j] += dj;
    return joint_log_likelihood(states, q);
  };
  for (std::size_t i = 0; i < m; ++i) {
    for (std::size_t j = 0; j <= i; ++j) {
      const double second =
          (at(i, h, j, h) - at(i, h, j, -h) - at(i, -h, j, h) + at(i, -h, j, -h)) / (4 * h * h);
      gsl_matrix_set(information, i, j, -second);
      gsl_matrix_set(information, j, i, -second);
    }
  }
  std::vector<double> se(m, NestedFit::nan);
  gsl_error_handler_t* previous = gsl_set_error_handler_off();
  if (gsl_linalg_cholesky_decomp1(information) == GSL_SUCCESS &&
      gsl_linalg_cholesky_invert(information) == GSL_SUCCESS) {
    for (std::size_t i = 0; i < m; ++i) se[i] = std::sqrt(gsl_matrix_get(information, i, i));
  }
  gsl_set_error_handler(previous);
  gsl_matrix_free(information);
  return se;
}

}  // namespace

NestedFit fit_nested_lognormal(const std::vector<NestedStateData>& states) {
  NestedFit fit;
  if (states.empty()) return fit;
  const double v =
      golden_maximum([&](double w) { return profile_log_likelihood(states, std::exp(w)); },
                     std::log(kMinBeta), std::log(kMaxBeta));
  const double edge = 1e-6;
  if (v < std::log(kMinBeta) + edge || v > std::log(kMaxBeta) - edge) {
    fit.status = "the common beta's maximum lies at the search bound";
    return fit;
  }
  const double beta = std::exp(v);
  std::vector<double> p;
  for (const auto& state : states) {
    const double u = best_log_median(state, beta);
    const MedianSearch range = median_range(state);
    if (u < range.low + edge || u > range.high - edge) {
      fit.status = "a median's maximum lies outside the levels' reach";
      return fit;
    }
    p.push_back(u);
  }
  p.push_back(v);
  const std::vector<double> se = standard_errors(states, p);
  fit.status = "ok";
  fit.beta = beta;
  fit.beta_se = beta * se.back();  // the delta method from ln beta
  fit.log_likelihood = joint_log_likelihood(states, p);
  for (std::size_t k = 0; k < states.size(); ++k) {
    fit.median.push_back(std::exp(p[k]));
    fit.median_se.push_back(std::exp(p[k]) * se[k]);
  }
  return fit;
}

}  // namespace blockfrag
