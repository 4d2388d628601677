#include "engine/motion/accelerogram.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "engine/errors.hpp"
#include "engine/tolerances.hpp"

namespace blockfrag {

void check_accelerogram(const Accelerogram& record) {
  const auto fail = [](const char* rule) {
    throw InvalidInput(std::string("invalid record: ") + rule);
  };
  if (record.times.size() != record.acceleration_g.size())
    fail("times and accelerations differ in length");
  if (record.times.size() < 2) fail("needs at least 2 samples");
  if (!(record.times.front() >= 0)) fail("times must be >= 0");
  for (std::size_t k = 0; k < record.times.size(); ++k) {
    if (!std::isfinite(record.times[k]) || !std::isfinite(record.acceleration_g[k]))
      fail("values must be finite");
    if (k > 0 && !(record.times[k] > record.times[k - 1])) fail("times must increase strictly");
  }
}

double peak_acceleration_g(const Accelerogram& record) {
  double peak = 0.0;
  for (const double a : record.acceleration_g) peak = std::max(peak, std::abs(a));
  return peak;
}

bool on_step_grid(const Accelerogram& record, double step) {
  return std::all_of(record.times.begin(), record.times.end(), [step](double t) {
    const double k = std::round(t / step);
    return std::abs(t - k * step) <= kStepGridRounding * std::max(t, step);
  });
}

Accelerogram resample(const Accelerogram& record, double step) {
  const auto& t = record.times;
  const auto& a = record.acceleration_g;
  const double last = t.back();
  const auto count = static_cast<std::size_t>(std::floor(last / step * (1 + kGridRounding))) + 1;
  Accelerogram out;
  out.times.reserve(count);
  out.acceleration_g.reserve(count);
  std::size_t i = 0;  // t[i] <= x < t[i + 1] once x reaches the first sample
  for (std::size_t k = 0; k < count; ++k) {
    const double x = std::min(static_cast<double>(k) * step, last);
    while (i + 2 < t.size() && t[i + 1] <= x) ++i;
    double value = 0.0;
    if (x >= t[i]) {
      const double w = (x - t[i]) / (t[i + 1] - t[i]);
      value = a[i] + w * (a[i + 1] - a[i]);
    }
    out.times.push_back(static_cast<double>(k) * step);
    out.acceleration_g.push_back(value);
  }
  return out;
}

}  // namespace blockfrag
