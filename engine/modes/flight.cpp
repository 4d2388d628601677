#include "engine/modes/flight.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "engine/tolerances.hpp"

namespace blockfrag {

namespace {

// A corner's height above the ground, its rate and its arm's height above the centre of mass
// (which gives the height's acceleration), from one sine and cosine.
struct CornerHeight {
  BlockGeometry& geometry;
  const FlightStart& f;
  double g;
  int corner;

  struct Sample {
    double height, rate, arm_y;
  };
  Sample at(double tau) const {
    const CornerKinematics k = corner_kinematics(geometry, flight_pose(f, g, tau), corner);
    return {k.height, k.u_y, k.r.y};
  }
  // The height's second derivative: the arm's y turns at omega.
  double acceleration(const Sample& s) const { return -g - f.omega * f.omega * s.arm_y; }
};

// The step d from a sample to where the parabola with the sample's height, rate and acceleration
// reaches the ground, taking the root nearest the sample within (d_min, d_max); NaN if none.
double parabola_step(const CornerHeight::Sample& s, double acceleration, double d_min,
                     double d_max) {
  const double half_a = 0.5 * acceleration;
  const double discriminant = s.rate * s.rate - 4.0 * half_a * s.height;
  double best = std::numeric_limits<double>::quiet_NaN();
  if (!(discriminant >= 0)) return best;
  // The two roots without cancellation: q / half_a and height / q.
  const double q = -0.5 * (s.rate + std::copysign(std::sqrt(discriminant), s.rate));
  for (const double d : {q / half_a, s.height / q}) {
    if (d > d_min && d < d_max && !(std::abs(d) >= std::abs(best))) best = d;
  }
  return best;
}

// Inside [lo, hi] (height(lo) > 0 >= height(hi), sampled or bounded), each step goes to where the
// parabola through the last sample (its height, rate and acceleration -g - omega^2 r_y: all exact)
// reaches the ground. Over a flight's short brackets the height is that parabola up to a cubic
// term, so the search converges cubically from either side, and from the top of a corner's arc too
// (where Newton's tangent is flat and a micro-bounce's bracket took it ten halvings). A step that
// would leave the bracket bisects it; one kept half a tolerance inside it ends a search that
// converges from above by landing just past the crossing. Returns a time at or below the ground
// within the time tolerance of the crossing, or within the height's rounding noise of it.
double locate_landing(const CornerHeight& h, double lo, double hi, CornerHeight::Sample s,
                      double time_tolerance, double height_noise) {
  double x = lo;
  for (int iteration = 0; iteration < kMaxBracketSteps && hi - lo > time_tolerance; ++iteration) {
    const double inside = 0.5 * time_tolerance;
    double next = x + parabola_step(s, h.acceleration(s), lo - x, hi - x);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    x = std::clamp(next, lo + inside, hi - inside);
    s = h.at(x);
    if (s.height > 0) {
      lo = x;
    } else {
      hi = x;
      if (s.height >= -height_noise) break;
    }
  }
  return hi;
}

// The earliest time a point `depth` above a level, moving up at `rate`, can reach it when its
// downward acceleration is at most `bound` (>= 0); written so that neither a falling point nor a
// small bound loses precision.
double earliest_fall(double depth, double rate, double bound) {
  const double root = std::sqrt(rate * rate + 2.0 * bound * depth);
  return rate > 0 ? (rate + root) / bound : 2.0 * depth / (root - rate);
}

// No landing: a plain double, not std::optional, keeps corner_landing's result in a register (the
// optional's value and flag went through memory on every flight).
constexpr double kNoLanding = std::numeric_limits<double>::infinity();

// One corner's first landing in (0, tau_max], from `now`, its sample at the start; kNoLanding if
// none. Its height's second derivative lies in [-bound, -least]: the earliest fall under `bound`
// is a step that cannot skip the ground. When least > 0 the height is concave over the whole
// flight, so once it is above the ground it crosses it once, no later than its fall under
// `least`: that bracket is searched at once, with no stepping towards it.
double corner_landing(const CornerHeight& h, CornerHeight::Sample now, double bound, double least,
                      double tau_max, double min_step, double time_tolerance, double height_noise,
                      double sink_allowance) {
  double tau = 0.0;
  if (now.height <= 0.0) {
    // Leaving the ground: start where it has risen (half the earliest possible return). A corner
    // that has not risen by then is watched until it has; one that turns down first never left
    // the ground, and lands at once (ignoring it let a corner that left at 1e-8 m/s sink through
    // the ground for the rest of the flight). One not rising at the start is looked at again
    // before it can sink by more than the allowance (after min_step, a corner moving down at
    // the end of a vertical pulse sank 5e-9 R).
    tau = now.rate > 0 ? now.rate / bound : earliest_fall(sink_allowance, now.rate, bound);
    now = h.at(tau);
    while (now.height <= 0.0) {
      if (now.rate <= 0.0) return tau;
      tau *= 2.0;
      if (tau >= tau_max) return kNoLanding;
      now = h.at(tau);
    }
  }
  while (tau < tau_max) {
    const double safe = earliest_fall(now.height, now.rate, bound);
    if (tau + safe > tau_max) return kNoLanding;  // it cannot reach the ground in time
    if (least > 0) {
      const double latest = tau + earliest_fall(now.height, now.rate, least);
      if (latest <= tau_max) {
        return locate_landing(h, tau, latest, now, time_tolerance, height_noise);
      }
    }
    const double next = std::min(tau + std::max(safe, min_step), tau_max);
    const CornerHeight::Sample then = h.at(next);
    if (then.height <= 0.0) {
      return locate_landing(h, tau, next, now, time_tolerance, height_noise);
    }
    tau = next;
    now = then;
  }
  return kNoLanding;
}

}  // namespace

std::optional<double> first_landing(BlockGeometry& geometry, const FlightStart& f, double g,
                                    double tau_max, double min_step) {
  // A corner's height is y + r_y, and r_y turns at omega: its second derivative -g - omega^2 r_y
  // lies within omega^2 R of -g.
  const double bound = g + f.omega * f.omega * geometry.size();
  const double least = g - f.omega * f.omega * geometry.size();
  // While theta stays within the overturning range only a base corner can be the lowest point of
  // the block (BlockGeometry::overturn_angle), and where the block first touches the ground its
  // lowest point does: only the base corners need searching. theta is linear in time, so the
  // range holds throughout if it holds at both ends.
  const bool base_only = geometry.overturn_margin(f.theta) >= 0 &&
                         geometry.overturn_margin(f.theta + f.omega * tau_max) >= 0;
  const int corners = base_only ? 2 : geometry.corner_count();
  // The base corners at the start, one after the other (one rotation serves both), searched from
  // the one that can land sooner: the search after it stops where it lands, most often at once.
  const std::array<CornerHeight::Sample, 2> base = {CornerHeight{geometry, f, g, 0}.at(0.0),
                                                    CornerHeight{geometry, f, g, 1}.at(0.0)};
  const auto soonest_fall = [&](const CornerHeight::Sample& s) {
    return s.height <= 0.0 ? 0.0 : earliest_fall(s.height, s.rate, bound);
  };
  const int sooner = soonest_fall(base[1]) < soonest_fall(base[0]) ? 1 : 0;
  double first = kNoLanding;
  for (int k = 0; k < corners; ++k) {
    const int corner = k == 0 ? sooner : (k == 1 ? 1 - sooner : k);
    const CornerHeight h{geometry, f, g, corner};
    const CornerHeight::Sample now = k < 2 ? base[static_cast<std::size_t>(corner)] : h.at(0.0);
    const double limit = first < kNoLanding ? first : tau_max;
    const double tolerance = kLandingTimeTolerance * (1.0 + limit);
    // A corner's height is y plus an arm of size R: its rounding error is a few ulps of their sum.
    const double height_noise =
        4 * std::numeric_limits<double>::epsilon() * (std::abs(f.y) + geometry.size());
    first = std::min(first, corner_landing(h, now, bound, least, limit, min_step, tolerance,
                                           height_noise, kLandingSinkAllowance * geometry.size()));
  }
  if (first == kNoLanding) return std::nullopt;
  return first;
}

double flight_horizon(const FlightStart& start, double g, double t0, double t_stop, bool ends_run) {
  if (!ends_run) return t_stop;
  return t0 + (start.vy + std::sqrt(start.vy * start.vy + 2.0 * g * start.y)) / g;
}

FlightEnd flight_end(BlockGeometry& geometry, const FlightStart& start, double g, double t0,
                     double t_stop, bool ends_run, double min_step) {
  double t_end = flight_horizon(start, g, t0, t_stop, ends_run);
  bool overturns = false, lands = false;
  if (start.omega != 0.0) {
    const double tau = (geometry.overturn_theta(start.omega) - start.theta) / start.omega;
    if (tau > 0 && t0 + tau < t_end) {
      t_end = t0 + tau;
      overturns = true;
    }
  }
  if (const auto landing = first_landing(geometry, start, g, t_end - t0, min_step)) {
    if (t0 + *landing <= t_end) {
      t_end = t0 + *landing;
      overturns = false;
      lands = true;
    }
  }
  if (t_end > t_stop) {  // the run ends first
    t_end = t_stop;
    overturns = false;
    lands = false;
  }
  return {t_end, overturns, lands};
}

}  // namespace blockfrag
