#include "engine/flight.hpp"

#include <cmath>
#include <limits>

#include "engine/root_finding.hpp"

namespace blockfrag {

namespace {

struct CornerHeight {
  const BlockGeometry& geometry;
  const FlightStart& f;
  double g;
  int corner;

  double height(double tau) const {
    return corner_kinematics(geometry, flight_pose(f, g, tau), corner).height;
  }
  double rate(double tau) const {
    return corner_kinematics(geometry, flight_pose(f, g, tau), corner).u_y;
  }
};

std::optional<double> corner_landing(const CornerHeight& h, double bound, double tau_max,
                                     double min_step, double time_tolerance,
                                     double height_noise) {
  double tau = 0.0;
  double value = h.height(0.0);
  if (value <= 0.0) {
    // Leaving the ground: start where it has risen (half the earliest possible return).
    const double rate = h.rate(0.0);
    tau = rate > 0 ? rate / bound : min_step;
    value = h.height(tau);
    if (value <= 0.0) return std::nullopt;  // it does not leave: not a flight for this corner
  }
  while (tau < tau_max) {
    const double rate = h.rate(tau);
    const double safe = (rate + std::sqrt(rate * rate + 2.0 * bound * value)) / bound;
    const double next = std::min(tau + std::max(safe, min_step), tau_max);
    const double next_value = h.height(next);
    if (next_value <= 0.0) {
      return locate_crossing([&](double t) { return h.height(t); }, tau, next, value, next_value,
                             time_tolerance, height_noise)
          .after;
    }
    tau = next;
    value = next_value;
  }
  return std::nullopt;
}

}  // namespace

std::optional<double> first_landing(const BlockGeometry& geometry, const FlightStart& f, double g,
                                    double tau_max, double min_step) {
  const double bound = g + f.omega * f.omega * geometry.size();
  std::optional<double> first;
  for (int corner = 0; corner < geometry.corner_count(); ++corner) {
    const CornerHeight h{geometry, f, g, corner};
    const double limit = first ? *first : tau_max;
    const double tolerance = 4e-16 * (1.0 + limit);
    // A corner's height is y plus an arm of size R: its rounding error is a few ulps of their sum.
    const double height_noise =
        4 * std::numeric_limits<double>::epsilon() * (std::abs(f.y) + geometry.size());
    if (auto tau = corner_landing(h, bound, limit, min_step, tolerance, height_noise)) {
      if (!first || *tau < *first) first = tau;
    }
  }
  return first;
}

}  // namespace blockfrag
