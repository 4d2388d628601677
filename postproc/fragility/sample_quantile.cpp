#include "postproc/fragility/sample_quantile.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace blockfrag {

double sample_quantile(std::vector<double> values, double q) {
  if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(values.begin(), values.end());
  const double position = q * static_cast<double>(values.size() - 1);
  const auto below = static_cast<std::size_t>(std::floor(position));
  const std::size_t above = std::min(below + 1, values.size() - 1);
  const double fraction = position - static_cast<double>(below);
  // An order statistic hit exactly, or two equal ones (inf among them), need no interpolation.
  if (fraction == 0.0 || values[below] == values[above]) return values[below];
  return values[below] + fraction * (values[above] - values[below]);
}

}  // namespace blockfrag
