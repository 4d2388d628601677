#include "engine/contact/impact.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

#include "engine/errors.hpp"

namespace blockfrag {
namespace {

// The corner's compliance W = [[a1, -a2], [-a2, a3]]: an impulse dP at the corner changes its
// velocity by W dP (paper eq. 2.11). The impact is followed along the normal impulse p = P_y with
// a tangential law dP_x = k dp, so along a phase the corner velocity moves at
// du_x/dp = a1 k - a2 and du_y/dp = a3 - a2 k.
struct Compliance {
  double a1, a2, a3;
  double det;  // a1 a3 - a2^2, written without the cancellation: 1/M^2 + |r|^2/(M I) > 0

  explicit Compliance(const CornerImpactInput& in)
      : a1(1.0 / in.mass + in.r_y * in.r_y / in.inertia),
        a2(in.r_x * in.r_y / in.inertia),
        a3(1.0 / in.mass + in.r_x * in.r_x / in.inertia),
        det((1.0 / in.mass + (in.r_x * in.r_x + in.r_y * in.r_y) / in.inertia) / in.mass) {}
};

enum class Phase { slip, stick, reversal, painleve_jump };

// dP_x = k dp over `length` of normal impulse, with du_y/dp = slope_y.
struct Segment {
  Phase phase;
  double k, slope_y, length;
};

struct Path {
  std::array<Segment, 2> segments;
  int count = 0;
  void add(const Segment& s) { segments[count++] = s; }
};

// Impulse with du_x = -u_x and du_y = 0: solve W P = (-u_x, 0). Its P_y >= 0 and
// |P_x| <= mu P_y reduce to s a2 <= 0 and a3 <= mu |a2|, i.e. a3 + s mu a2 <= 0 (times I:
// I/M + r_x^2 + s mu r_x r_y <= 0): the cone holds it exactly when slipping is impossible.
// It dissipates: Delta T = P.(u- + u+)/2 = P_x u_x / 2 = -a3 u_x^2 / (2 det) < 0.
CornerImpulse stick_jump(const Compliance& w, double u_x) {
  return {-u_x * w.a3 / w.det, -u_x * w.a2 / w.det, ImpactRegime::slip_then_stick, true, false};
}

// The Darboux-Keller path of the impact, up to Newton's end u_y = -e u_y-. It has at most two
// phases: a slip that stops meets the stick line u_x = 0 and never leaves it, and a reversed slip
// (possible only when mu < |a2|/a1) accelerates away from it.
Path newton_path(const CornerImpactInput& in, const Compliance& w) {
  Path path;
  const double target = -in.restitution * in.u_y;
  double u_y = in.u_y;
  bool sticks = in.friction * w.a1 >= std::abs(w.a2);
  if (in.u_x != 0.0) {
    const double s = in.u_x > 0.0 ? 1.0 : -1.0;
    const double k = -s * in.friction;
    const double slope_y = w.a3 - w.a2 * k;
    if (slope_y <= 0.0) {
      // Painleve: a3 <= mu |a2| implies mu > |a2|/a1 (as a1 a3 > a2^2), so the stick reached by
      // the jump is sustainable. The plain slip would also stop before Newton's end (u_y only
      // falls while it lasts) and then stick; both paths end at u = (0, -e u_y-), so they give
      // the same total impulse, but the jump keeps u_y non-decreasing along the path.
      // As a phase: dP_x = (a3/a2) dp holds u_y still while u_x runs to 0 (a2 != 0 here).
      path.add({Phase::painleve_jump, w.a3 / w.a2, 0.0, stick_jump(w, in.u_x).p_y});
      sticks = true;
    } else {
      const double to_end = (target - u_y) / slope_y;
      const double slope_x = w.a1 * k - w.a2;  // slip decelerates iff s slope_x < 0 (eq. 2.15)
      const double to_stop =
          s * slope_x < 0.0 ? -in.u_x / slope_x : std::numeric_limits<double>::infinity();
      if (to_stop >= to_end) {
        path.add({Phase::slip, k, slope_y, to_end});
        return path;
      }
      path.add({Phase::slip, k, slope_y, to_stop});
      u_y += slope_y * to_stop;
    }
  }
  if (sticks) {
    const double slope_y = w.det / w.a1;  // stick: dP_x = (a2/a1) dp keeps du_x = 0
    path.add({Phase::stick, w.a2 / w.a1, slope_y, (target - u_y) / slope_y});
  } else {
    // Slip with s' = -sign(a2), the only direction whose friction does not drive u_x back
    // through zero. Its slope a3 - mu |a2| > 0, since mu < |a2|/a1 gives mu |a2| < a2^2/a1 < a3.
    const double k = std::copysign(in.friction, w.a2);
    const double slope_y = w.a3 - w.a2 * k;
    path.add(
        {path.count == 0 ? Phase::slip : Phase::reversal, k, slope_y, (target - u_y) / slope_y});
  }
  return path;
}

// Kinetic energy change for a corner impulse P: T+ - T- = P.u- + P.W P / 2 (T is quadratic in
// the velocities, and u+ = u- + W P). Along the path dT/dp = u_y + k u_x = u_y - mu |u_x| (zero
// friction work in stick), continuous across phase changes since they happen at u_x = 0, and
// d2T/dp2 = (k, 1).W.(k, 1) > 0: T is convex in p, falls through compression (u_y < 0), and only
// the restitution can push it above T-.
struct EnergyChange {
  double value, magnitude;  // magnitude bounds its rounding error, up to a few epsilons
};

EnergyChange energy_change(const Compliance& w, const CornerImpactInput& in, double p_x,
                           double p_y) {
  const double work_x = p_x * in.u_x, work_y = p_y * in.u_y;
  const double quadratic = 0.5 * (w.a1 * p_x * p_x - 2.0 * w.a2 * p_x * p_y + w.a3 * p_y * p_y);
  return {work_x + work_y + quadratic, std::abs(work_x) + std::abs(work_y) + quadratic};
}

ImpactRegime regime_of(const Path& path, int used) {
  if (used == 1) {
    return path.segments[0].phase == Phase::stick ? ImpactRegime::stick : ImpactRegime::slip;
  }
  return path.segments[1].phase == Phase::stick ? ImpactRegime::slip_then_stick
                                                : ImpactRegime::slip_reversal;
}

void require(bool ok, const char* what, double value) {
  if (!ok) {
    throw ContractViolation(std::string("corner impact: ") + what + " (got " +
                            std::to_string(value) + ")");
  }
}

void validate(const CornerImpactInput& in) {
  // Every impact of a chattering block comes here: one test passes the valid inputs, and the
  // checks that name the bad value run only when it fails (a sum of finite values may overflow,
  // but then they all pass).
  const double sum = in.mass + in.inertia + in.friction + in.r_x + in.r_y + in.u_x + in.u_y;
  if (in.mass > 0.0 && in.inertia > 0.0 && in.friction >= 0.0 && in.restitution >= 0.0 &&
      in.restitution <= 1.0 && std::isfinite(sum)) {
    return;
  }
  require(std::isfinite(in.mass) && in.mass > 0.0, "mass must be positive", in.mass);
  require(std::isfinite(in.inertia) && in.inertia > 0.0, "inertia must be positive", in.inertia);
  require(std::isfinite(in.friction) && in.friction >= 0.0, "friction must be >= 0", in.friction);
  require(in.restitution >= 0.0 && in.restitution <= 1.0, "restitution must be in [0, 1]",
          in.restitution);
  for (const double value : {in.r_x, in.r_y, in.u_x, in.u_y}) {
    require(std::isfinite(value), "corner position and velocity must be finite", value);
  }
}

}  // namespace

CornerImpulse corner_impact(const CornerImpactInput& in) {
  validate(in);
  if (in.u_y >= 0.0) {
    return {0.0, 0.0, in.u_x == 0.0 ? ImpactRegime::stick : ImpactRegime::slip, false, false};
  }
  const Compliance w(in);
  const Path path = newton_path(in, w);

  double p_x = 0.0, p_y = 0.0;
  for (int i = 0; i < path.count; ++i) {
    p_x += path.segments[i].k * path.segments[i].length;
    p_y += path.segments[i].length;
  }
  const EnergyChange newton = energy_change(w, in, p_x, p_y);
  const bool capped =
      newton.value > 16.0 * std::numeric_limits<double>::epsilon() * newton.magnitude;
  int used = path.count;
  if (capped) {
    // Walk the path to the phase where T first exceeds T- (convexity: T < T- at its start) and
    // stop at the larger root of Delta T(p0 + t) = c + b t + q t^2 / 2 = 0 there: the largest
    // normal impulse with Delta T <= 0. It lies beyond the end of compression, so only the
    // restitution part of the impulse is reduced.
    p_x = p_y = 0.0;
    for (used = 1; used <= path.count; ++used) {
      const Segment& seg = path.segments[used - 1];
      const double c = energy_change(w, in, p_x, p_y).value;
      const double u_x = in.u_x + w.a1 * p_x - w.a2 * p_y;
      const double u_y = in.u_y - w.a2 * p_x + w.a3 * p_y;
      const double b = seg.k * u_x + u_y;
      const double q = seg.k * (w.a1 * seg.k - w.a2) + seg.slope_y;
      const double end = c + b * seg.length + 0.5 * q * seg.length * seg.length;
      if (end > 0.0 || used == path.count) {
        const double root = std::sqrt(b * b - 2.0 * q * std::min(c, 0.0));
        const double t = b > 0.0 ? -2.0 * std::min(c, 0.0) / (b + root) : (root - b) / q;
        p_x += seg.k * std::min(t, seg.length);
        p_y += std::min(t, seg.length);
        break;
      }
      p_x += seg.k * seg.length;
      p_y += seg.length;
    }
  }
  return {p_x, p_y, regime_of(path, used), path.segments[0].phase == Phase::painleve_jump, capped};
}

std::optional<CornerImpulse> painleve_stick_impulse(const CornerImpactInput& in) {
  validate(in);
  if (in.u_x == 0.0) return std::nullopt;
  const double s = in.u_x > 0.0 ? 1.0 : -1.0;
  const double condition =
      in.inertia / in.mass + in.r_x * in.r_x + s * in.friction * in.r_x * in.r_y;
  if (condition > 0.0) return std::nullopt;
  return stick_jump(Compliance(in), in.u_x);
}

}  // namespace blockfrag
