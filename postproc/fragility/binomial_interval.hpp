// Confidence intervals for a binomial proportion: the empirical probability of exceeding a limit
// state at one intensity level is exceedances / trials, and these say how far it may be off.
#pragma once

#include <cstdint>
#include <string>

#include "engine/errors.hpp"

namespace blockfrag {

class IntervalError : public ContractViolation {
 public:
  explicit IntervalError(const std::string& what) : ContractViolation(what) {}
};

struct ProportionInterval {
  double low;
  double high;
};

enum class IntervalMethod { wilson, clopper_pearson };

// Wilson's score interval: the set of p whose score test does not reject successes / trials. Well
// behaved at 0 and n successes (unlike the Wald interval) and close to nominal coverage on average.
// Requires trials > 0, 0 <= successes <= trials, 0 < confidence < 1; throws IntervalError
// otherwise.
ProportionInterval wilson_interval(std::int64_t successes, std::int64_t trials,
                                   double confidence = 0.95);

// Clopper-Pearson's exact interval from beta quantiles: coverage is at least the confidence level
// for every p, at the price of being wider than Wilson's. Same requirements as wilson_interval.
// Exact up to about a million trials; beyond, GSL's incomplete beta function may not converge and
// this throws IntervalError rather than return a wrong bound.
ProportionInterval clopper_pearson_interval(std::int64_t successes, std::int64_t trials,
                                            double confidence = 0.95);

ProportionInterval binomial_interval(IntervalMethod method, std::int64_t successes,
                                     std::int64_t trials, double confidence = 0.95);

}  // namespace blockfrag
