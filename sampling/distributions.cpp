#include "sampling/distributions.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include <gsl/gsl_cdf.h>

namespace blockfrag {
namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();

// A truncation interval in standard normal units; infinite ends are unbounded.
struct ZInterval {
  double lower = -infinity;
  double upper = infinity;
};

ZInterval z_interval(const Normal& normal) {
  return {normal.lower ? (*normal.lower - normal.mean) / normal.std_dev : -infinity,
          normal.upper ? (*normal.upper - normal.mean) / normal.std_dev : infinity};
}

ZInterval z_interval(const LogNormal& lognormal) {
  const double log_median = std::log(lognormal.median);
  return {lognormal.lower ? (std::log(*lognormal.lower) - log_median) / lognormal.beta : -infinity,
          lognormal.upper ? (std::log(*lognormal.upper) - log_median) / lognormal.beta : infinity};
}

double lower_tail(double z) { return std::isinf(z) ? (z < 0 ? 0.0 : 1.0) : gsl_cdf_ugaussian_P(z); }
double upper_tail(double z) { return std::isinf(z) ? (z < 0 ? 1.0 : 0.0) : gsl_cdf_ugaussian_Q(z); }

double mass(const ZInterval& z) {
  // Above the median, P is 1 - (something small) and loses that something to rounding; Q keeps it.
  return z.lower > 0 ? upper_tail(z.lower) - upper_tail(z.upper)
                     : lower_tail(z.upper) - lower_tail(z.lower);
}

// The standard normal truncated to z at u: Phi^-1(Phi(lo) + u (Phi(hi) - Phi(lo))). Below the
// median this is evaluated with lower-tail probabilities, above it with upper-tail ones,
// Q^-1(Q(hi) + (1 - u) (Q(lo) - Q(hi))), so that values far out in either tail (or an interval
// lying there) keep their full relative precision instead of being rounded against 1.
double truncated_standard_normal_quantile(const ZInterval& z, double u) {
  const double p_lower = lower_tail(z.lower);
  const double p = p_lower + u * (lower_tail(z.upper) - p_lower);
  double quantile = 0.0;
  if (p <= 0.5) {
    quantile = gsl_cdf_ugaussian_Pinv(p);
  } else {
    const double q_upper = upper_tail(z.upper);
    quantile = gsl_cdf_ugaussian_Qinv(q_upper + (1.0 - u) * (upper_tail(z.lower) - q_upper));
  }
  return std::clamp(quantile, z.lower, z.upper);
}

double clamp_to(double x, const std::optional<double>& lower, const std::optional<double>& upper) {
  return std::clamp(x, lower.value_or(-infinity), upper.value_or(infinity));
}

double quantile_of(const Fixed& fixed, double) { return fixed.value; }

double quantile_of(const Uniform& uniform, double u) {
  return std::min(uniform.min + u * (uniform.max - uniform.min), uniform.max);
}

double quantile_of(const Normal& normal, double u) {
  const double z = truncated_standard_normal_quantile(z_interval(normal), u);
  return clamp_to(normal.mean + normal.std_dev * z, normal.lower, normal.upper);
}

double quantile_of(const LogNormal& lognormal, double u) {
  const double z = truncated_standard_normal_quantile(z_interval(lognormal), u);
  return clamp_to(lognormal.median * std::exp(lognormal.beta * z), lognormal.lower,
                  lognormal.upper);
}

double mass_of(const Fixed&) { return 1.0; }
double mass_of(const Uniform&) { return 1.0; }
double mass_of(const Normal& normal) { return mass(z_interval(normal)); }
double mass_of(const LogNormal& lognormal) { return mass(z_interval(lognormal)); }

// Collects violations; each check reports at most one message per field and returns whether the
// value passed, so later rules can skip values already known to be broken.
class Rules {
 public:
  bool finite(const char* field, double value) {
    if (std::isfinite(value)) return true;
    add(field, "must be finite (got " + format_number(value) + ")");
    return false;
  }

  bool positive(const char* field, double value) {
    if (!finite(field, value)) return false;
    if (value > 0) return true;
    add(field, "must be > 0 (got " + format_number(value) + ")");
    return false;
  }

  bool optional_finite(const char* field, const std::optional<double>& value) {
    return !value || finite(field, *value);
  }

  bool optional_positive(const char* field, const std::optional<double>& value) {
    return !value || positive(field, *value);
  }

  bool greater(const char* field, double value, const char* other_field, double other) {
    if (value > other) return true;
    add(field, std::string("must be > ") + other_field + " (got " + field + " = " +
                   format_number(value) + ", " + other_field + " = " + format_number(other) + ")");
    return false;
  }

  bool ordered_bounds(const std::optional<double>& lower, const std::optional<double>& upper) {
    return !(lower && upper) || greater("upper", *upper, "lower", *lower);
  }

  void enough_mass(const Distribution& distribution, const std::optional<double>& lower,
                   const std::optional<double>& upper) {
    const double probability = truncation_mass(distribution);
    if (probability >= min_truncation_mass) return;
    add("", "the truncation interval [" + (lower ? format_number(*lower) : "-inf") + ", " +
                (upper ? format_number(*upper) : "inf") + "] has probability " +
                format_number(probability) + " (must be >= " + format_number(min_truncation_mass) +
                "; is a bound in the wrong units or sign?)");
  }

  std::vector<Violation> take() { return std::move(violations_); }

 private:
  void add(const char* field, std::string message) {
    violations_.push_back({field, std::move(message)});
  }

  std::vector<Violation> violations_;
};

void check(Rules& rules, const Fixed& fixed, const Distribution&) {
  rules.finite("value", fixed.value);
}

void check(Rules& rules, const Uniform& uniform, const Distribution&) {
  const bool min_ok = rules.finite("min", uniform.min);
  const bool max_ok = rules.finite("max", uniform.max);
  if (min_ok && max_ok) rules.greater("max", uniform.max, "min", uniform.min);
}

void check(Rules& rules, const Normal& normal, const Distribution& distribution) {
  const bool mean_ok = rules.finite("mean", normal.mean);
  const bool std_dev_ok = rules.positive("std_dev", normal.std_dev);
  const bool lower_ok = rules.optional_finite("lower", normal.lower);
  const bool upper_ok = rules.optional_finite("upper", normal.upper);
  if (lower_ok && upper_ok && rules.ordered_bounds(normal.lower, normal.upper) && mean_ok &&
      std_dev_ok) {
    rules.enough_mass(distribution, normal.lower, normal.upper);
  }
}

void check(Rules& rules, const LogNormal& lognormal, const Distribution& distribution) {
  const bool median_ok = rules.positive("median", lognormal.median);
  const bool beta_ok = rules.positive("beta", lognormal.beta);
  const bool lower_ok = rules.optional_positive("lower", lognormal.lower);
  const bool upper_ok = rules.optional_positive("upper", lognormal.upper);
  if (lower_ok && upper_ok && rules.ordered_bounds(lognormal.lower, lognormal.upper) && median_ok &&
      beta_ok) {
    rules.enough_mass(distribution, lognormal.lower, lognormal.upper);
  }
}

}  // namespace

double quantile(const Distribution& distribution, double u) {
  if (!(u > 0.0 && u < 1.0)) {
    throw SamplingError({{"u", "must be inside (0, 1) (got " + format_number(u) + ")"}});
  }
  return std::visit([u](const auto& law) { return quantile_of(law, u); }, distribution);
}

double truncation_mass(const Distribution& distribution) {
  return std::visit([](const auto& law) { return mass_of(law); }, distribution);
}

std::vector<Violation> validate(const Distribution& distribution) {
  Rules rules;
  std::visit([&](const auto& law) { check(rules, law, distribution); }, distribution);
  return rules.take();
}

}  // namespace blockfrag
