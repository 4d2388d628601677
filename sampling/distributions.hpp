// The distributions of a study's random inputs, and the map from a uniform u in (0, 1) to a value.
//
// Every value is an inverse CDF at u, x = F^-1(u), never a rejection loop: one uniform makes one
// value, in the same time for every u, and x is non-decreasing in u (Latin hypercube strata of u
// are strata of x), up to the last bit: between neighbouring doubles u, GSL's rational
// approximations of the normal quantile can step back by one ulp. Truncation to [lower, upper] is
// exact: u is mapped onto the CDF range of the interval,
// x = F^-1(F(lower) + u (F(upper) - F(lower))), so the values follow the truncated law with no
// loop; results are clamped into [lower, upper] so that rounding never steps outside.
#pragma once

#include <optional>
#include <variant>
#include <vector>

#include "sampling/validation.hpp"

namespace blockfrag {

struct Fixed {
  double value = 0.0;
};

struct Uniform {
  double min = 0.0;
  double max = 1.0;
};

struct Normal {
  double mean = 0.0;
  double std_dev = 1.0;
  std::optional<double> lower{};  // truncation bounds; absent = unbounded on that side
  std::optional<double> upper{};
};

// ln x is normal with mean ln(median) and standard deviation beta (the fragility literature's
// "median and log standard deviation").
struct LogNormal {
  double median = 1.0;
  double beta = 0.1;
  std::optional<double> lower{};  // truncation bounds, > 0; absent = unbounded on that side
  std::optional<double> upper{};
};

using Distribution = std::variant<Fixed, Uniform, Normal, LogNormal>;

// A truncation interval must keep at least this probability of the untruncated law. Smaller
// intervals are almost certainly a unit or sign mistake in the config (a bound many standard
// deviations from the mean), and the values would depend on the far tail of the CDF.
inline constexpr double min_truncation_mass = 1e-9;

// The value at u of a valid distribution (see validate), for 0 < u < 1; throws SamplingError
// for u outside (0, 1) or NaN.
double quantile(const Distribution& distribution, double u);

// The probability of the truncation interval under the untruncated law (1 when not truncated).
double truncation_mass(const Distribution& distribution);

// Every rule the distribution breaks, each with the member it concerns:
// finite numbers; min < max; std_dev > 0; median > 0; beta > 0; lognormal bounds > 0;
// lower < upper; truncation mass >= min_truncation_mass. Empty when it is valid.
std::vector<Violation> validate(const Distribution& distribution);

}  // namespace blockfrag
