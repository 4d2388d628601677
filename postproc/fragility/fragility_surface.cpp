#include "postproc/fragility/fragility_surface.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <gsl/gsl_cdf.h>
#include <gsl/gsl_math.h>
#include <gsl/gsl_sf_erf.h>

#include "postproc/fragility/backtracking_line_search.hpp"
#include "postproc/fragility/lognormal_fit.hpp"
#include "postproc/fragility/normal_probability.hpp"

// The fit works in centred coordinates: eta_j = a + b1 v1_j + b2 v2_j, v = ln x - (the trials-
// weighted mean of ln x). ln L of a probit is concave (Pratt 1981), so Newton's method with a
// backtracking line search climbs to the maximum from any start, and whether the maximum exists is
// decided by the data alone (Albert & Anderson 1984: unless the design is rank-deficient or the
// outcomes are separated), which is checked before iterating. Centring decorrelates a from the
// slopes and makes the iteration independent of the measures' units.

namespace blockfrag {
namespace {

using Vector3 = std::array<double, 3>;
using Matrix3 = std::array<Vector3, 3>;

struct Cell {
  double u1, u2;  // ln im1, ln im2
  double n, z;
};

std::vector<Cell> checked_cells(std::span<const double> im1, std::span<const double> im2,
                                std::span<const std::int64_t> trials,
                                std::span<const std::int64_t> exceedances) {
  const std::size_t size = im1.size();
  if (im2.size() != size || trials.size() != size || exceedances.size() != size)
    throw FitError("surface fit: im1, im2, trials and exceedances differ in size");
  std::vector<Cell> cells;
  for (std::size_t j = 0; j < size; ++j) {
    const std::string where = "surface fit: cell " + std::to_string(j) + ": ";
    for (const double x : {im1[j], im2[j]}) {
      if (!(std::isfinite(x) && x > 0.0))
        throw FitError(where + "im1 and im2 must be finite and > 0 (got " + std::to_string(x) +
                       ")");
    }
    if (trials[j] < 0 || exceedances[j] < 0 || exceedances[j] > trials[j])
      throw FitError(where + "needs 0 <= exceedances <= trials (got " +
                     std::to_string(exceedances[j]) + " of " + std::to_string(trials[j]) + ")");
    if (trials[j] > 0)
      cells.push_back({std::log(im1[j]), std::log(im2[j]), static_cast<double>(trials[j]),
                       static_cast<double>(exceedances[j])});
  }
  return cells;
}

// The inverse of a symmetric positive definite matrix by Cholesky; none when it is not (to
// rounding).
std::optional<Matrix3> inverse_spd(const Matrix3& m) {
  Matrix3 l{};
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j <= i; ++j) {
      double sum = m[i][j];
      for (int k = 0; k < j; ++k) sum -= l[i][k] * l[j][k];
      if (i == j) {
        if (!(sum > 1e-14 * m[i][i])) return std::nullopt;
        l[i][i] = std::sqrt(sum);
      } else {
        l[i][j] = sum / l[j][j];
      }
    }
  }
  Matrix3 inverse{};
  for (int column = 0; column < 3; ++column) {
    Vector3 y{};  // L y = e_column, then L' x = y
    for (int i = 0; i < 3; ++i) {
      double sum = i == column ? 1.0 : 0.0;
      for (int k = 0; k < i; ++k) sum -= l[i][k] * y[k];
      y[i] = sum / l[i][i];
    }
    for (int i = 2; i >= 0; --i) {
      double sum = y[i];
      for (int k = i + 1; k < 3; ++k) sum -= l[k][i] * inverse[k][column];
      inverse[i][column] = sum / l[i][i];
    }
  }
  return inverse;
}

Vector3 times(const Matrix3& m, const Vector3& v) {
  Vector3 out{};
  for (int i = 0; i < 3; ++i) out[i] = m[i][0] * v[0] + m[i][1] * v[1] + m[i][2] * v[2];
  return out;
}

double dot(const Vector3& x, const Vector3& y) { return x[0] * y[0] + x[1] * y[1] + x[2] * y[2]; }

// (1, v1, v2) of a cell about the centre.
Vector3 regressors(const Cell& cell, double c1, double c2) {
  return {1.0, cell.u1 - c1, cell.u2 - c2};
}

struct Evaluation {
  double log_likelihood = 0.0;
  // ln L without the binomial coefficients, and the sum of its terms' magnitudes: what ln L can
  // resolve is set by the terms, not by their sum.
  double kernel = 0.0, kernel_scale = 0.0;
  Vector3 gradient{};     // of ln L
  Matrix3 information{};  // -d2 ln L, the observed information
};

Evaluation evaluate(const std::vector<Cell>& cells, double c1, double c2, const Vector3& theta) {
  Evaluation e;
  const double log_sqrt_2pi = 0.5 * std::log(2.0 * M_PI);
  for (const auto& cell : cells) {
    const Vector3 x = regressors(cell, c1, c2);
    const double eta = dot(theta, x);
    const double log_p = log_normal_cdf(eta), log_q = log_normal_cdf(-eta);
    const double misses = cell.n - cell.z;
    const double hit_term = cell.z > 0.0 ? cell.z * log_p : 0.0;
    const double miss_term = misses > 0.0 ? misses * log_q : 0.0;
    e.kernel += hit_term + miss_term;
    e.kernel_scale -= hit_term + miss_term;
    e.log_likelihood += log_choose(cell.n, cell.z) + hit_term + miss_term;
    // Mills ratios phi / Phi and phi / (1 - Phi) from logarithms: finite in both tails.
    const double log_density = -0.5 * eta * eta - log_sqrt_2pi;
    const double ratio_p = std::exp(log_density - log_p);
    const double ratio_q = std::exp(log_density - log_q);
    const double slope = cell.z * ratio_p - misses * ratio_q;
    const double weight = std::max(0.0, cell.z * ratio_p * (eta + ratio_p)) +
                          std::max(0.0, misses * ratio_q * (ratio_q - eta));
    for (int i = 0; i < 3; ++i) {
      e.gradient[i] += slope * x[i];
      for (int j = 0; j < 3; ++j) e.information[i][j] += weight * x[i] * x[j];
    }
  }
  return e;
}

// Whether every cell lies on one line of the (u1, u2) plane (to rounding).
bool collinear(const std::vector<Cell>& cells) {
  double scale = 0.0;
  for (const auto& c : cells) scale = std::max({scale, std::abs(c.u1), std::abs(c.u2)});
  const double eps = 1e-12 * (1.0 + scale);
  const Cell& first = cells.front();
  const auto far = std::find_if(cells.begin(), cells.end(), [&](const Cell& c) {
    return std::hypot(c.u1 - first.u1, c.u2 - first.u2) > eps;
  });
  if (far == cells.end()) return true;
  const double dx = far->u1 - first.u1, dy = far->u2 - first.u2, length = std::hypot(dx, dy);
  return std::all_of(cells.begin(), cells.end(), [&](const Cell& c) {
    return std::abs(dx * (c.u2 - first.u2) - dy * (c.u1 - first.u1)) / length <= eps;
  });
}

// Whether a line leaves every cell with an exceedance on one closed side and every cell with a
// non-exceedance on the other. The cells do not lie on one line, so the cone of such separating
// (c, w) is pointed, and when it is not {0} it has an extreme ray: a line through two cells.
bool separated(const std::vector<Cell>& cells) {
  std::vector<const Cell*> mixed;
  for (const auto& c : cells) {
    if (c.z > 0.0 && c.z < c.n) mixed.push_back(&c);
  }
  // Cells with both outcomes must lie on a separating line: three off one line rule it out.
  if (mixed.size() >= 3) {
    std::vector<Cell> points;
    for (const Cell* c : mixed) points.push_back(*c);
    if (!collinear(points)) return false;
  }
  double scale = 0.0;
  for (const auto& c : cells) scale = std::max({scale, std::abs(c.u1), std::abs(c.u2)});
  const double eps = 1e-10 * (1.0 + scale);
  for (std::size_t i = 0; i < cells.size(); ++i) {
    for (std::size_t j = i + 1; j < cells.size(); ++j) {
      const double dx = cells[j].u1 - cells[i].u1, dy = cells[j].u2 - cells[i].u2;
      const double length = std::hypot(dx, dy);
      if (!(length > eps)) continue;
      // s > 0 on one side of the line through cells i and j, in units of distance.
      const auto side = [&](const Cell& c) {
        return (dx * (c.u2 - cells[i].u2) - dy * (c.u1 - cells[i].u1)) / length;
      };
      bool hits_above = true, hits_below = true;
      for (const auto& c : cells) {
        const double s = side(c);
        if (c.z > 0.0) {
          hits_above = hits_above && s >= -eps;
          hits_below = hits_below && s <= eps;
        }
        if (c.z < c.n) {
          hits_above = hits_above && s <= eps;
          hits_below = hits_below && s >= -eps;
        }
        if (!hits_above && !hits_below) break;
      }
      if (hits_above || hits_below) return true;
    }
  }
  return false;
}

std::optional<SurfaceFitStatus> degenerate_case(const std::vector<Cell>& cells) {
  if (cells.empty()) return SurfaceFitStatus::no_data;
  double n_total = 0.0, z_total = 0.0;
  for (const auto& c : cells) {
    n_total += c.n;
    z_total += c.z;
  }
  if (z_total == 0.0) return SurfaceFitStatus::no_exceedances;
  if (z_total == n_total) return SurfaceFitStatus::all_exceedances;
  if (collinear(cells)) return SurfaceFitStatus::collinear;
  if (separated(cells)) return SurfaceFitStatus::separated;
  return std::nullopt;
}

// The classical linearised start: trials-weighted least squares of probit((z + 1/2) / (n + 1)) on
// (1, v1, v2); the cells span the plane, so the normal equations are positive definite.
Vector3 starting_point(const std::vector<Cell>& cells, double c1, double c2) {
  Matrix3 normal{};
  Vector3 right{};
  for (const auto& cell : cells) {
    const Vector3 x = regressors(cell, c1, c2);
    const double y = gsl_cdf_ugaussian_Pinv((cell.z + 0.5) / (cell.n + 1.0));
    for (int i = 0; i < 3; ++i) {
      right[i] += cell.n * x[i] * y;
      for (int j = 0; j < 3; ++j) normal[i][j] += cell.n * x[i] * x[j];
    }
  }
  const auto inverse = inverse_spd(normal);
  return inverse ? times(*inverse, right) : Vector3{0.0, 0.0, 0.0};
}

double quadratic_form(const Vector3& g, const Matrix3& m) { return dot(g, times(m, g)); }

// The median form and its standard errors (delta method) from b and its covariance.
void fill_median_form(SurfaceFit& fit) {
  const auto [b0, b1, b2] = fit.coefficients;
  fit.ln_median_intercept = -b0 / b1;
  fit.ln_median_slope = -b2 / b1;
  fit.beta1 = 1.0 / b1;
  fit.ln_median_intercept_se =
      std::sqrt(quadratic_form({-1.0 / b1, b0 / (b1 * b1), 0.0}, fit.covariance));
  fit.ln_median_slope_se =
      std::sqrt(quadratic_form({0.0, b2 / (b1 * b1), -1.0 / b1}, fit.covariance));
  fit.beta1_se = std::sqrt(fit.covariance[1][1]) / (b1 * b1);
}

// Where the Newton iteration stopped, after how many steps, and whether it met the tolerance
// there; newton_decrement: the last step's predicted gain (NaN when the information was singular).
struct SurfaceClimb {
  Vector3 theta;
  Evaluation e;
  int iterations = 0;
  bool converged = false;
  double newton_decrement = SurfaceFit::nan;
};

// theta moved along `step` by the backtracking line search, with e; false when even the shortest
// step gains nothing (rounding alone is left).
bool search_along_step(const std::vector<Cell>& cells, double c1, double c2, const Vector3& step,
                       const AscentStart& start, Vector3& theta, Evaluation& e) {
  Vector3 trial = theta;
  Evaluation trial_e;
  const auto kernel_at = [&](double t) {
    trial = {theta[0] + t * step[0], theta[1] + t * step[1], theta[2] + t * step[2]};
    trial_e = evaluate(cells, c1, c2, trial);
    return trial_e.kernel;
  };
  if (!backtracking_line_search(start, kernel_at)) return false;
  theta = trial;
  e = trial_e;
  return true;
}

SurfaceClimb climb_surface(const std::vector<Cell>& cells, double c1, double c2,
                           const SurfaceFitOptions& options) {
  const Vector3 start = starting_point(cells, c1, c2);
  SurfaceClimb climb{start, evaluate(cells, c1, c2, start)};
  for (; climb.iterations < options.max_iterations; ++climb.iterations) {
    const Evaluation& e = climb.e;
    // Newton's step on the concave ln L; steepest ascent if the information is numerically
    // singular (far out in a tail, where every weight underflows).
    const auto inverse = inverse_spd(e.information);
    const Vector3 step = inverse ? times(*inverse, e.gradient) : e.gradient;
    const double predicted = dot(e.gradient, step);
    climb.newton_decrement = inverse ? predicted : SurfaceFit::nan;
    if (inverse && predicted <= options.decrement_tolerance) {
      climb.converged = true;
      break;
    }
    const AscentStart from{e.kernel, e.kernel_scale, predicted, inverse.has_value()};
    if (!search_along_step(cells, c1, c2, step, from, climb.theta, climb.e)) break;
  }
  return climb;
}

// b0 = a - b1 c1 - b2 c2: the covariance of (b0, b1, b2) is J C J' with J's first row
// (1, -c1, -c2) and the identity below it.
void fill_uncentred_coefficients(const Vector3& theta, const Matrix3& c, double c1, double c2,
                                 SurfaceFit& fit) {
  const Vector3 j0{1.0, -c1, -c2};
  fit.coefficients = {theta[0] - theta[1] * c1 - theta[2] * c2, theta[1], theta[2]};
  const Vector3 c_j0 = times(c, j0);
  fit.covariance[0][0] = dot(j0, c_j0);
  for (int i = 1; i < 3; ++i) {
    fit.covariance[0][i] = fit.covariance[i][0] = c_j0[i];
    for (int k = 1; k < 3; ++k) fit.covariance[i][k] = c[i][k];
  }
  for (int i = 0; i < 3; ++i) fit.standard_errors[i] = std::sqrt(fit.covariance[i][i]);
}

}  // namespace

const char* surface_fit_status_name(SurfaceFitStatus status) {
  switch (status) {
    case SurfaceFitStatus::ok: return "ok";
    case SurfaceFitStatus::no_data: return "no_data";
    case SurfaceFitStatus::no_exceedances: return "no_exceedances";
    case SurfaceFitStatus::all_exceedances: return "all_exceedances";
    case SurfaceFitStatus::collinear: return "collinear";
    case SurfaceFitStatus::separated: return "separated";
    case SurfaceFitStatus::not_increasing: return "not_increasing";
    case SurfaceFitStatus::not_converged: return "not_converged";
  }
  return "unknown";
}

double SurfaceFit::probability(double x1, double x2) const {
  return gsl_cdf_ugaussian_P(coefficients[0] + coefficients[1] * std::log(x1) +
                             coefficients[2] * std::log(x2));
}

double SurfaceFit::median_im1(double x2) const {
  if (status != SurfaceFitStatus::ok) return nan;
  return std::exp(ln_median_intercept + ln_median_slope * std::log(x2));
}

SurfaceFit fit_fragility_surface(std::span<const double> im1, std::span<const double> im2,
                                 std::span<const std::int64_t> trials,
                                 std::span<const std::int64_t> exceedances,
                                 const SurfaceFitOptions& options) {
  if (!(options.decrement_tolerance > 0.0) || options.max_iterations <= 0)
    throw FitError("surface fit: decrement_tolerance and max_iterations must be > 0");
  const auto cells = checked_cells(im1, im2, trials, exceedances);
  SurfaceFit fit;
  if (const auto status = degenerate_case(cells)) {
    fit.status = *status;
    return fit;
  }
  double n_total = 0.0, c1 = 0.0, c2 = 0.0;
  for (const auto& cell : cells) {
    n_total += cell.n;
    c1 += cell.n * cell.u1;
    c2 += cell.n * cell.u2;
  }
  c1 /= n_total;
  c2 /= n_total;

  const SurfaceClimb climb = climb_surface(cells, c1, c2, options);
  fit.newton_decrement = climb.newton_decrement;
  fit.iterations = climb.iterations;
  fit.log_likelihood = climb.e.log_likelihood;
  const auto centred_covariance = inverse_spd(climb.e.information);
  if (!climb.converged || !centred_covariance) {
    fit.status = SurfaceFitStatus::not_converged;
    return fit;
  }
  fill_uncentred_coefficients(climb.theta, *centred_covariance, c1, c2, fit);
  fit.status = climb.theta[1] > 0.0 ? SurfaceFitStatus::ok : SurfaceFitStatus::not_increasing;
  if (fit.status == SurfaceFitStatus::ok) fill_median_form(fit);
  return fit;
}

}  // namespace blockfrag
