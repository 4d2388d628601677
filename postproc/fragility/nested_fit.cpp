#include "postproc/fragility/nested_fit.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <utility>

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
// The fit costs about 0.2 ms per level and limit state (3 x 1000 levels: 0.64 s): a grid of more
// levels than this over its limit states (about a second) is not fitted.
constexpr std::size_t kMaxLevelStates = 5'000;
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

// r(t) = phi(t) / Phi(t), the inverse Mills ratio, from logs (Phi(t) underflows far below 0).
double mills(double t) {
  return std::exp(-0.5 * t * t - 0.5 * std::log(2.0 * M_PI) - log_normal_cdf(t));
}

// One state's d ln L / d ln theta and d2 ln L / d ln theta^2 at u = ln theta.
std::pair<double, double> state_slopes(const NestedStateData& state, double u, double beta) {
  double first = 0.0, second = 0.0;
  for (std::size_t j = 0; j < state.im.size(); ++j) {
    const auto n = static_cast<double>(state.trials[j]);
    if (n <= 0.0) continue;
    const auto z = static_cast<double>(state.exceedances[j]);
    const double eta = (std::log(state.im[j]) - u) / beta;
    const double up = mills(eta), down = mills(-eta);
    // d/d eta of z ln Phi(eta) + (n - z) ln Phi(-eta), and its derivative (r' = -r (t + r)).
    first += z * up - (n - z) * down;
    second += -z * up * (eta + up) - (n - z) * down * (-eta + down);
  }
  return {-first / beta, second / (beta * beta)};
}

// ln theta maximising one state's ln L at this beta (concave in it): Newton's method from
// `start`, each step halved until ln L rises, kept in the search range. A search of its own, not
// backtracking_line_search.hpp: the move is clamped to the range (halving the step need not halve
// it), a move that does not lower ln L is accepted and the halving stops on the move's size.
double best_log_median(const NestedStateData& state, double beta, double start) {
  const MedianSearch range = median_range(state);
  double u = std::clamp(start, range.low, range.high);
  double value = state_log_likelihood(state, u, beta);
  for (int iteration = 0; iteration < 200; ++iteration) {
    const auto [slope, curvature] = state_slopes(state, u, beta);
    double step = curvature < 0.0 ? -slope / curvature : (slope > 0.0 ? 1.0 : -1.0);
    double next = std::clamp(u + step, range.low, range.high);
    double next_value = state_log_likelihood(state, next, beta);
    while (next_value < value && std::abs(next - u) > 1e-15) {
      step *= 0.5;
      next = std::clamp(u + step, range.low, range.high);
      next_value = state_log_likelihood(state, next, beta);
    }
    const bool done = std::abs(next - u) <= 1e-13 * std::max(1.0, std::abs(u));
    if (next_value >= value) {
      u = next;
      value = next_value;
    }
    if (done) break;
  }
  return u;
}

// A start for ln theta: the log of the level nearest where the proportion reaches 1/2.
double start_log_median(const NestedStateData& state) {
  double best = std::log(state.im.front()), distance = 2.0;
  for (std::size_t j = 0; j < state.im.size(); ++j) {
    if (state.trials[j] <= 0) continue;
    const double p =
        static_cast<double>(state.exceedances[j]) / static_cast<double>(state.trials[j]);
    if (std::abs(p - 0.5) < distance) {
      distance = std::abs(p - 0.5);
      best = std::log(state.im[j]);
    }
  }
  return best;
}

// The sum of every state's ln L maximised over its ln theta at this beta; `starts` holds the last
// maxima, from which Newton's method starts (the profile is searched in small moves of beta).
double profile_log_likelihood(const std::vector<NestedStateData>& states, double beta,
                              std::vector<double>& starts) {
  double sum = 0.0;
  for (std::size_t k = 0; k < states.size(); ++k) {
    starts[k] = best_log_median(states[k], beta, starts[k]);
    sum += state_log_likelihood(states[k], starts[k], beta);
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
  std::size_t levels = 0;
  for (const auto& state : states) levels += state.im.size();
  if (levels > kMaxLevelStates) {
    fit.status = "not fitted: " + std::to_string(levels) +
                 " levels over its limit states, more than " + std::to_string(kMaxLevelStates);
    return fit;
  }
  std::vector<double> starts;
  for (const auto& state : states) starts.push_back(start_log_median(state));
  const double v =
      golden_maximum([&](double w) { return profile_log_likelihood(states, std::exp(w), starts); },
                     std::log(kMinBeta), std::log(kMaxBeta));
  const double edge = 1e-6;
  if (v < std::log(kMinBeta) + edge || v > std::log(kMaxBeta) - edge) {
    fit.status = "the common beta's maximum lies at the search bound";
    return fit;
  }
  const double beta = std::exp(v);
  std::vector<double> p;
  for (std::size_t k = 0; k < states.size(); ++k) {
    const double u = best_log_median(states[k], beta, starts[k]);
    const MedianSearch range = median_range(states[k]);
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
