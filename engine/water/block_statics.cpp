#include "engine/water/block_statics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "engine/contact/crack_seating.hpp"
#include "engine/errors.hpp"
#include "engine/scene/block_geometry.hpp"
#include "engine/sine_cosine.hpp"
#include "engine/tolerances.hpp"
#include "engine/water/block_outline.hpp"
#include "engine/water/crack_path.hpp"
#include "engine/water/crack_pressure.hpp"
#include "engine/water/linear_pressure.hpp"
#include "engine/water/westergaard.hpp"
#include "engine/water/wetted_face.hpp"

namespace blockfrag {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// A load split into its horizontal and vertical parts with their first moments (integrals of y dF_x
// and of x dF_y), so the moment of either part about any point follows. Coordinates are about the
// block's centre of mass.
struct SplitLoad {
  double fx = 0.0, fy = 0.0;
  double y_fx = 0.0, x_fy = 0.0;

  static SplitLoad at(const Vertex& p, double fx, double fy) {
    return {fx, fy, p[1] * fx, p[0] * fy};
  }
  // Counter-clockwise moments about p.
  double horizontal_moment(const Vertex& p) const { return p[1] * fx - y_fx; }
  double vertical_moment(const Vertex& p) const { return x_fy - p[0] * fy; }
  void add(const SplitLoad& other) {
    fx += other.fx;
    fy += other.fy;
    y_fx += other.y_fx;
    x_fy += other.x_fy;
  }
};

// A linear pressure on a segment (engine/water/linear_pressure.hpp), split: the horizontal part is
// the load of the normal's x component alone, the vertical part the y component's.
SplitLoad split_pressure(const Vertex& a, const Vertex& b, double p_a, double p_b,
                         const Vertex& outward) {
  const Vertex origin{0.0, 0.0};
  const WaterLoad h = linear_pressure_load(a, b, p_a, p_b, {outward[0], 0.0}, origin);
  const WaterLoad v = linear_pressure_load(a, b, p_a, p_b, {0.0, outward[1]}, origin);
  return {h.fx, v.fy, -h.moment, v.moment};
}

enum class UpliftUse { scene_rule, full };

// The block resting at a pose and what acts on it, about its centre of mass.
struct RestingBlock {
  double mass = 0.0, g = 0.0, mu = 0.0;
  double tolerance = 0.0;  // m: how far a support may be off its ground, and off its line
  SplitLoad weight, hydrostatic, uplift;
  AddedMass added;  // about the centre of mass's height
  std::vector<Support> supports;
  // Under "zero_in_gap" (the scene's rule): the crack about the centre of mass and its closed
  // pressure at the mouth, c rho_w g h, to open it from a lifting corner.
  bool opens_crack = false;
  std::vector<Vertex> crack;
  double crack_length = 0.0, mouth_pressure = 0.0;

  // The static loads' moment about p, and what a ground acceleration a adds to it per a (the
  // block's inertia -M a at the centre, the water's -M_a a at S_a / M_a above it).
  double static_moment(const Vertex& p) const {
    return weight.vertical_moment(p) + hydrostatic.horizontal_moment(p) +
           hydrostatic.vertical_moment(p) + uplift.horizontal_moment(p) + uplift.vertical_moment(p);
  }
  double inertia_moment(const Vertex& p) const {
    return -p[1] * (mass + added.mass) + added.first_moment;
  }
  Vertex static_force() const {
    return {hydrostatic.fx + uplift.fx, weight.fy + hydrostatic.fy + uplift.fy};
  }
  // The same block with its crack opened (the "zero_in_gap" pressure).
  RestingBlock opened(CrackOpening open) const {
    RestingBlock block = *this;
    block.uplift = {};
    const CrackPressure pressure =
        crack_pressure(UpliftRule::zero_in_gap, crack_length, mouth_pressure, 0.0, open);
    for_each_pressure_piece(crack, pressure, [&](const PressurePiece& piece) {
      block.uplift.add(split_pressure(piece.a, piece.b, piece.p_a, piece.p_b, piece.outward));
    });
    return block;
  }
};

// The block at `pose`, held where it was held at rest: its supports and crack at rest (on a seat,
// found within the contact tolerance) are carried with it to the pose.
RestingBlock resting_block(const Scene& scene, const BlockState& pose, UpliftUse use) {
  const BlockOutline outline(scene);
  RestingBlock block;
  block.tolerance = kContactHeight * scene_geometry(scene).size();
  block.mass = scene.polygon ? scene.polygon->mass : scene.block.mass;
  block.g = scene.g;
  block.mu = scene.contact.friction;
  block.weight = SplitLoad::at({0.0, 0.0}, 0.0, -block.mass * scene.g);
  const std::vector<Support> supports =
      scene_supports(scene, outline.rest_bottom(), outline.rest(), block.tolerance);
  if (supports.empty()) throw ContractViolation("block statics: the block does not rest");
  const SineCosine turn = sine_cosine(pose.theta);
  const auto turned = [&](const Vertex& v) -> Vertex {
    return {v[0] * turn.cos - v[1] * turn.sin, v[0] * turn.sin + v[1] * turn.cos};
  };
  const Vertex rest_centre = outline.rest_centre();
  const auto carried = [&](const Vertex& p) {
    return turned({p[0] - rest_centre[0], p[1] - rest_centre[1]});
  };
  for (const Support& s : supports) block.supports.push_back({carried(s.point), turned(s.normal)});
  if (!scene.reservoir) return block;
  const Reservoir& water = *scene.reservoir;
  WorldPolygon body;
  for (const Vertex& v : outline.rest()) body.push_back(carried(v));
  CrackPath crack = crack_under(outline.rest(), supports, block.tolerance);
  for (Vertex& p : crack.points) p = carried(p);
  const double surface = water.level - outline.centre(pose)[1];
  const double unit_weight = water.density * scene.g;  // rho_w g
  for_each_wetted_piece(body, surface, crack.edges, [&](const WettedPiece& piece) {
    block.hydrostatic.add(split_pressure(piece.a, piece.b, unit_weight * piece.depth_a,
                                         unit_weight * piece.depth_b, piece.outward()));
  });
  if (water.hydrodynamic == Hydrodynamic::westergaard) {
    block.added =
        westergaard_added_mass(body, surface, water.density, water.depth, crack.edges, 0.0);
  }
  if (use == UpliftUse::scene_rule && water.uplift == UpliftRule::none) return block;
  const double area = use == UpliftUse::full ? 1.0 : water.uplift_area_factor;
  const double head = std::max(0.0, surface - crack.points.front()[1]);
  // Closed: the static distribution, which "unchanged" keeps whatever the opening.
  const CrackPressure pressure =
      crack_pressure(UpliftRule::unchanged, crack.length(), area * unit_weight * head, 0.0,
                     CrackOpening::closed());
  for_each_pressure_piece(crack.points, pressure, [&](const PressurePiece& piece) {
    block.uplift.add(split_pressure(piece.a, piece.b, piece.p_a, piece.p_b, piece.outward));
  });
  if (use == UpliftUse::scene_rule && water.uplift == UpliftRule::zero_in_gap) {
    block.opens_crack = true;
    block.crack = crack.points;
    block.crack_length = crack.length();
    block.mouth_pressure = area * unit_weight * head;
  }
  return block;
}

// The lines of supports the block can slide along: each support's line (its point and normal),
// once.
struct SlideLine {
  Vertex normal;
  double offset;  // normal . point
};

bool on_line(const Support& s, const SlideLine& line, double tolerance) {
  return std::hypot(s.normal[0] - line.normal[0], s.normal[1] - line.normal[1]) <=
             kSameSupportDirection &&
         std::abs(s.normal[0] * s.point[0] + s.normal[1] * s.point[1] - line.offset) <= tolerance;
}

std::vector<SlideLine> slide_lines(const std::vector<Support>& supports, double tolerance) {
  std::vector<SlideLine> lines;
  for (const Support& s : supports) {
    const bool known = std::any_of(lines.begin(), lines.end(), [&](const SlideLine& line) {
      return on_line(s, line, tolerance);
    });
    if (!known) {
      lines.push_back({s.normal, s.normal[0] * s.point[0] + s.normal[1] * s.point[1]});
    }
  }
  return lines;
}

// A slide along `line` in the direction v lifts the block off every support not on the line.
bool can_slide(const std::vector<Support>& supports, const SlideLine& line, const Vertex& v,
               double tolerance) {
  return std::all_of(supports.begin(), supports.end(), [&](const Support& s) {
    return on_line(s, line, tolerance) || s.normal[0] * v[0] + s.normal[1] * v[1] > 0.0;
  });
}

// Calls visit(line normal n, direction v) for each slide the block can make with v_x of sign
// `sense` (+1 downstream, -1 upstream).
template <class Visit>
void for_each_slide(const RestingBlock& block, double sense, Visit&& visit) {
  const double tolerance = block.tolerance;
  for (const SlideLine& line : slide_lines(block.supports, tolerance)) {
    const Vertex n = line.normal;
    Vertex v{n[1], -n[0]};  // along the line
    if (v[0] == 0.0) continue;
    if ((v[0] > 0.0) != (sense > 0.0)) v = {-v[0], -v[1]};
    if (can_slide(block.supports, line, v, tolerance)) visit(n, v);
  }
}

// The ground acceleration's magnitude, in g, that starts a slide along v (sense sigma): the loads
// R0 + a k with k = (-(M + M_a), 0) reach R . v = mu (-R . n) at
//   a = R0 . (v + mu n) / ((M + M_a) (v_x + mu n_x)),  reported as -sigma a / g.
double slide_yield(const RestingBlock& block, double sense) {
  double least = kInfinity;
  const Vertex r0 = block.static_force();
  const double inertia = block.mass + block.added.mass;
  for_each_slide(block, sense, [&](const Vertex& n, const Vertex& v) {
    const Vertex w{v[0] + block.mu * n[0], v[1] + block.mu * n[1]};
    if (!(sense * w[0] > 0.0)) return;  // no acceleration that way drives this slide
    const double a = (r0[0] * w[0] + r0[1] * w[1]) / (inertia * w[0]);
    least = std::min(least, -sense * a / block.g);
  });
  return least;
}

// Rocking about p (downstream: clockwise, sense +1; upstream: counter-clockwise, sense -1) starts
// where the moment M_P + a c(P) reaches zero: a = -M_P / c(P), reported as -sense a / g.
double rock_yield(const RestingBlock& block, const Vertex& p, double sense) {
  const double per_acceleration = block.inertia_moment(p);
  if (!(per_acceleration > 0.0)) return kInfinity;
  return sense * block.static_moment(p) / (per_acceleration * block.g);
}

// One way (sense +1: downstream, about the downstream support; -1: upstream, about the upstream
// one), the pivot, the crack's side that lifts and the load's margin against rocking at a ground
// acceleration of magnitude `acceleration` (in g) that way: the lifting corner's normal force times
// the lever between the corners, >= 0 while the corner stays seated.
struct RockingWay {
  double sense;
  Vertex pivot;
  LiftingSide lifting;

  double margin(const RestingBlock& block, double acceleration) const {
    return sense * block.static_moment(pivot) -
           acceleration * block.g * block.inertia_moment(pivot);
  }
};

RockingWay rocking_way(const RestingBlock& block, double sense) {
  const OutermostSupports outermost = outermost_supports(block.supports);
  return sense > 0.0 ? RockingWay{sense, outermost.downstream, LiftingSide::upstream}
                     : RockingWay{sense, outermost.upstream, LiftingSide::downstream};
}

// Under "zero_in_gap" the crack of the block at rest under a ground acceleration of magnitude
// `acceleration` (in g) the way `way` rocks, opened from the lifting corner as far as that corner
// needs (engine/contact/crack_seating.hpp): the block the dynamics hold at rest.
RestingBlock seated_under(const RestingBlock& block, const RockingWay& way, double acceleration) {
  const auto opened = [&](double f) {
    return block.opened(CrackOpening::from_side(way.lifting, f));
  };
  const double fraction =
      seating_opening([&](double f) { return way.margin(opened(f), acceleration); });
  return fraction > 0.0 ? opened(fraction) : block;
}

// The rocking yield under "zero_in_gap": the crack opens as far as the lifting corner needs, so
// the block rocks where even a fully open crack leaves that corner in tension.
double seated_rock_yield(const RestingBlock& block, double sense) {
  const RockingWay way = rocking_way(block, sense);
  return rock_yield(block.opened(CrackOpening::from_side(way.lifting, 1.0)), way.pivot, sense);
}

// The sliding yield under "zero_in_gap": below the closed crack's rocking yield the crack stays
// closed; above it the block slides where the loads with the crack opened as far as the lifting
// corner needs at that acceleration reach friction's limit (bisected: a larger acceleration opens
// the crack further, which presses the block down).
double seated_slide_yield(const RestingBlock& block, double sense) {
  const double closed = slide_yield(block, sense);
  const RockingWay way = rocking_way(block, sense);
  double seated = rock_yield(block, way.pivot, sense);
  if (!(closed > seated)) return closed;
  double sliding = slide_yield(block.opened(CrackOpening::from_side(way.lifting, 1.0)), sense);
  if (!std::isfinite(sliding)) return sliding;
  for (;;) {
    const double middle = 0.5 * (seated + sliding);
    if (middle == seated || middle == sliding) return sliding;
    (slide_yield(seated_under(block, way, middle), sense) > middle ? seated : sliding) = middle;
  }
}

double ratio(double resisting, double driving) {
  if (!(driving > 0.0)) return kInfinity;
  return std::max(0.0, resisting) / driving;
}

SafetyFactors safety_factors(const RestingBlock& block, double coefficient) {
  const double g = block.g;
  const SplitLoad seismic = SplitLoad::at({0.0, 0.0}, coefficient * block.mass * g, 0.0);
  // Westergaard's force K g M_a at S_a / M_a above the centre of mass.
  const SplitLoad hydrodynamic{coefficient * g * block.added.mass, 0.0,
                               coefficient * g * block.added.first_moment, 0.0};
  const Vertex r0 = block.static_force();
  const Vertex r{r0[0] + seismic.fx + hydrodynamic.fx, r0[1]};
  double sliding = kInfinity;
  for_each_slide(block, 1.0, [&](const Vertex& n, const Vertex& v) {
    const double push = -(r[0] * n[0] + r[1] * n[1]);
    const double drive = r[0] * v[0] + r[1] * v[1];
    sliding = std::min(sliding, ratio(block.mu * push, drive));
  });
  const Vertex toe = outermost_supports(block.supports).downstream;
  double resisting = 0.0, overturning = 0.0;
  for (const double m :
       {block.weight.vertical_moment(toe), block.hydrostatic.horizontal_moment(toe),
        block.hydrostatic.vertical_moment(toe), block.uplift.horizontal_moment(toe),
        block.uplift.vertical_moment(toe), seismic.horizontal_moment(toe),
        hydrodynamic.horizontal_moment(toe)}) {
    (m > 0.0 ? resisting : overturning) += std::abs(m);
  }
  return {sliding, ratio(resisting, overturning)};
}

RestingBlock block_at_rest(const Scene& scene) {
  return resting_block(scene, BlockOutline(scene).rest_state(), UpliftUse::scene_rule);
}

}  // namespace

BlockStatics block_statics(const Scene& scene) {
  const RestingBlock block = block_at_rest(scene);
  const OutermostSupports outermost = outermost_supports(block.supports);
  const YieldAccelerations yield =
      block.opens_crack
          ? YieldAccelerations{seated_slide_yield(block, 1.0), seated_slide_yield(block, -1.0),
                               seated_rock_yield(block, 1.0), seated_rock_yield(block, -1.0)}
          : YieldAccelerations{slide_yield(block, 1.0), slide_yield(block, -1.0),
                               rock_yield(block, outermost.downstream, 1.0),
                               rock_yield(block, outermost.upstream, -1.0)};
  return {-block.weight.fy,
          block.hydrostatic.fx,
          block.hydrostatic.fy,
          block.uplift.fx,
          block.uplift.fy,
          block.added.mass,
          yield};
}

SafetyFactors pseudo_static_safety_factors(const Scene& scene, double coefficient) {
  const RestingBlock block = block_at_rest(scene);
  if (!block.opens_crack) return safety_factors(block, coefficient);
  // K W downstream lifts the heel: the crack opens as far as the heel needs, as at rest under a
  // ground acceleration K g upstream (CADAM's crack under a seismic coefficient).
  return safety_factors(seated_under(block, rocking_way(block, 1.0), coefficient), coefficient);
}

SafetyFactors post_earthquake_safety_factors(const Scene& scene, const BlockState& final_pose) {
  return safety_factors(resting_block(scene, final_pose, UpliftUse::full), 0.0);
}

PostEarthquakeCheck post_earthquake_check(const Scene& scene, const BlockState& final_pose,
                                          bool standing_at_rest) {
  PostEarthquakeCheck check;
  if (!standing_at_rest) return check;
  const SafetyFactors factors = post_earthquake_safety_factors(scene, final_pose);
  check.sliding_safety_factor = factors.sliding;
  check.overturning_safety_factor = factors.overturning;
  return check;
}

}  // namespace blockfrag
