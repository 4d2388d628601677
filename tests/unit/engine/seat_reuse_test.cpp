// What the seat's guards reuse instead of finding it again (engine/seat/seat_system.hpp,
// engine/seat/sinusoid.hpp, engine/seat/seat_ends.cpp): each is checked to the bit against the
// general path on random and edge inputs.
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "engine/scene/block_geometry.hpp"
#include "engine/seat/seat_system.hpp"
#include "engine/seat/sinusoid.hpp"
#include "tests/support/fixed_uniforms.hpp"
#include "tests/support/same_bits.hpp"
#include "tests/support/type_b_block.hpp"

namespace blockfrag {
namespace {

using testing::bits_of;

using testing::FixedUniforms;
using testing::kTypeB;
using testing::kTypeBSeat;

const std::vector<std::array<double, 2>> kReuseTypeA = {
    {0, 0}, {12.55, 0}, {10, 3.4}, {10, 16.7}, {0, 16.7}};

double reuse_norm(Vec2 v) { return std::sqrt(v.x * v.x + v.y * v.y); }

// Poses asked in turn as a step's guards and its penetration ask them: new ones, the same one
// again, ones differing from the last in one coordinate only (or in the sign of a zero), and the
// zero pose the kept one starts at.
std::vector<BlockState> reuse_poses_in_turn() {
  FixedUniforms u(61);
  std::vector<BlockState> poses{{}, {0.0, 0.0, -0.0}, {-0.0, 0.0, 0.0}, {0.0, -0.0, 0.0}, {}};
  for (int n = 0; n < 200; ++n) {
    BlockState s{u(-50, 50), u(-1, 20), u(-0.8, 0.8), 0.0, 0.0, 0.0};
    poses.push_back(s);
    poses.push_back(s);
    BlockState t = s;
    switch (n % 3) {
      case 0: t.x = std::nextafter(t.x, 1e9); break;
      case 1: t.y = u(-1, 20); break;
      default: t.theta = std::nextafter(t.theta, -1e9); break;
    }
    poses.push_back(t);
    poses.push_back(s);
  }
  return poses;
}

TEST(SeatReuse, ThePenetrationAtTheGuardsPoseIsTheOneFoundAnew) {
  MotionPiece still{MotionPiece::Formula{}, 0.0, 1e3};
  const std::vector<std::array<double, 2>> flat = {{-100, 0}, {100, 0}};
  for (const auto& block : {kReuseTypeA, kTypeB}) {
    for (const auto& seat : {flat, kTypeBSeat}) {
      const SeatContacts contacts(block, seat);
      const BlockGeometry geometry{PolygonBlock{block, 1.0}};
      const SeatSystemContext context{
          &contacts, &geometry, &still, &still, 9.81, 1.0, 0.5 * geometry.size()};
      WatchedList vertices;
      for (int i = 0; i < contacts.vertex_count(); ++i) vertices.push_back(i);
      SeatSystem system(context, {}, vertices, {});
      // Before any guards, then after the guards at each pose: at that pose and at the next asked
      // (the same again, or another differing in one coordinate, one bit or a zero's sign).
      const std::vector<BlockState> poses = reuse_poses_in_turn();
      EXPECT_EQ(bits_of(system.penetration(poses[0])), bits_of(contacts.penetration(poses[0])));
      int deep = 0;
      for (std::size_t k = 0; k + 1 < poses.size(); ++k) {
        system.guards(0.0, poses[k]);
        for (const BlockState& s : {poses[k], poses[k + 1]}) {
          const double anew = contacts.penetration(s);
          EXPECT_EQ(bits_of(system.penetration(s)), bits_of(anew))
              << s.x << " " << s.y << " " << s.theta;
          deep += anew > 0.0;
        }
      }
      EXPECT_GT(deep, 100);
    }
  }
}

// clearance_at as a seat with any number of segments finds it: past an end its distance from that
// end (or, under an end segment leaning away from it, its height over the segment's line), over the
// seat its height over the segment there.
double reuse_clearance_over_any_seat(const std::vector<Vec2>& seat, const SeatContacts& contacts,
                                     Vec2 p) {
  const Vec2 first = seat.front(), last = seat.back();
  if (p.x < first.x && !contacts.under_end_segment(p, false))
    return reuse_norm({p.x - first.x, p.y - first.y});
  if (p.x > last.x && !contacts.under_end_segment(p, true))
    return reuse_norm({p.x - last.x, p.y - last.y});
  std::size_t k = 1;
  while (k + 1 < seat.size() && !(p.x < seat[k].x)) ++k;
  const Vec2 a = seat[k - 1], b = seat[k];
  return p.y - (a.y + (b.y - a.y) * ((p.x - a.x) / (b.x - a.x)));
}

TEST(SeatReuse, AOneSegmentSeatsClearanceIsTheGeneralOnesToTheBitAndOtherSeatsKeepIt) {
  FixedUniforms u(62);
  const std::vector<std::vector<Vec2>> seats = {{{-100, 0}, {100, 0}},
                                                {{-3.1, 1.7}, {7.3, 2.9}},
                                                {{0.3, 4.1}, {6.7, -2.3}},
                                                {{-1, 0}, {1, 3}},
                                                // Seats of more segments take the general path.
                                                {{-2.3, 0.13}, {0.7, 0.71}, {3.1, 0.57}},
                                                {{-5, 0}, {-1, 0}, {2, 0}, {6, 4}}};
  for (const auto& seat : seats) {
    std::vector<std::array<double, 2>> points;
    for (const Vec2& p : seat) points.push_back({p.x, p.y});
    const SeatContacts contacts(kReuseTypeA, points);
    const double x0 = seat.front().x, x1 = seat.back().x;
    std::vector<Vec2> probes{
        {x0, 0.0},  {x1, -1.0},  {std::nextafter(x0, -1e9), 1.0}, {std::nextafter(x1, 1e9), -1.0},
        {0.0, 0.0}, {-0.0, -0.0}};
    // Each joint, and either side of it.
    for (const Vec2& joint : seat) {
      for (const double x :
           {std::nextafter(joint.x, -1e9), joint.x, std::nextafter(joint.x, 1e9)}) {
        probes.push_back({x, u(-1, 1)});
      }
    }
    for (int n = 0; n < 3000; ++n) {
      const double reach = (x1 - x0) * 0.6;
      probes.push_back({u(x0 - reach, x1 + reach), u(-5, 5)});
    }
    for (const Vec2& p : probes) {
      const double expected = reuse_clearance_over_any_seat(seat, contacts, p);
      EXPECT_EQ(bits_of(contacts.clearance_at(p)), bits_of(expected)) << p.x << " " << p.y;
    }
  }
}

TEST(SeatReuse, AStepsExtentIsItsLeastAndLargestToTheBit) {
  FixedUniforms u(63);
  std::vector<Sinusoid> fs{{1.0, 0.0, 0.0}, {-0.0, 0.0, -0.0}, {2.0, -0.0, 0.0}};
  for (int n = 0; n < 3000; ++n) fs.push_back({u(-3, 3), u(-5, 5), u(-5, 5)});
  int n = 0;
  for (const Sinusoid& f : fs) {
    const double lo = u(-4, 4);
    // Short and long steps, empty ones, and ones wider than half a turn.
    const double width = n % 4 == 0   ? 0.0
                         : n % 4 == 1 ? u(0, 1e-3)
                         : n % 4 == 2 ? u(0, 2)
                                      : u(2, 4);
    const ThetaStep step(lo, lo + width);
    const ThetaStep::Extent extent = step.extent(f);
    EXPECT_EQ(bits_of(extent.least), bits_of(step.least(f))) << n;
    EXPECT_EQ(bits_of(extent.largest), bits_of(step.largest(f))) << n;
    ++n;
  }
}

struct ReuseTypeBSeat {
  SeatContacts contacts{kTypeB, kTypeBSeat};
  BlockGeometry geometry{PolygonBlock{kTypeB, 1.0}};
  MotionPiece still{MotionPiece::Formula{}, 0.0, 1e3};
  SeatSystemContext context{&contacts, &geometry, &still, &still, 9.81, 1.0, 0.5 * geometry.size()};
};

// A sweep asked about steps in a chain (each starting where the last ended, as a pivot's steps do)
// reuses the last end's turn; it claims what a sweep asked about each step alone claims, on chains
// that turn back, stand still, cross zero's signs and break off, turning about the heel, the toe
// and the seat's fold; and the same step turned the other way claims the same.
TEST(SeatReuse, ASweepAskedAboutAChainOfStepsClaimsWhatOneAskedAboutEachAloneClaims) {
  const ReuseTypeBSeat seat;
  const SeatContacts& c = seat.contacts;
  struct Pivot {
    SeatPair pair;
    Vec2 point, body;
    WatchedList vertices, points;
  };
  const std::vector<Pivot> pivots = {{{ContactKind::block_vertex, 0, 0},
                                      c.seat_point(0),
                                      c.body_vertex(0),
                                      {1, 2, 3, 4, 5},
                                      {1, 2}},
                                     {{ContactKind::block_vertex, 2, 1},
                                      c.seat_point(2),
                                      c.body_vertex(2),
                                      {0, 1, 3, 4, 5},
                                      {0, 1}},
                                     {{ContactKind::seat_point, 0, 1},
                                      c.seat_point(1),
                                      {c.body_vertex(1).x - 1.0, c.body_vertex(1).y},
                                      {0, 1, 2, 3, 4, 5},
                                      {0, 2}}};
  GuardClaims every;
  every.fill(true);
  FixedUniforms u(64);
  int differing_ends = 0, claimed = 0;
  for (const Pivot& pivot : pivots) {
    const SeatSystem system(seat.context, {{pivot.pair, ContactState::stick}}, pivot.vertices,
                            pivot.points);
    const PivotChart chart{pivot.point, pivot.body};
    PivotSweep chained(system, chart);
    double theta = 0.0;
    for (int n = 0; n < 3000; ++n) {
      double next = std::clamp(theta + (n % 3 == 0 ? u(-0.3, 0.3) : u(-0.01, 0.01)), -1.2, 1.2);
      if (n % 50 == 7) next = theta;
      if (n % 50 == 9) next = -0.0;
      if (n % 50 == 10) next = 0.0;
      // A step that does not start where the last ended.
      const double start = n % 13 == 5 ? theta + u(-0.05, 0.05) : theta;
      differing_ends += start != theta;
      PivotSweep alone(system, chart);
      const GuardClaims claims = chained.claims(start, next, every);
      EXPECT_EQ(claims, alone.claims(start, next, every)) << n << " " << start << " " << next;
      // A step's claims do not depend on the way it turns.
      if (start != next) {
        PivotSweep reversed(system, chart);
        EXPECT_EQ(claims, reversed.claims(next, start, every)) << n;
      }
      claimed += static_cast<int>(std::count(claims.begin(), claims.end(), true));
      theta = next;
    }
  }
  EXPECT_GT(differing_ends, 300);
  EXPECT_GT(claimed, 3 * 3000 * kSeatGuards / 2);
}

// A seat point's claim as the sweep makes it (engine/seat/seat_ends.cpp), from sinusoids built
// here: none of its squared distances from the block's vertices holds a minimum in the step, it
// stays off each edge's line by the margin at both ends with no minimum of its distance between,
// and it is outside the block at the step's start.
bool reuse_point_claim(const SeatContacts& c, const PivotChart& chart, int k, double lo, double hi,
                       double off) {
  const ThetaStep step(lo, hi);
  const Vec2 s = c.seat_point(k);
  const Vec2 u{s.x - chart.point.x, s.y - chart.point.y};
  const int n = c.vertex_count();
  for (int j = 0; j < n; ++j) {
    const Vec2 a = c.body_vertex(j);
    const Vec2 e{chart.body.x - a.x, chart.body.y - a.y};
    const Sinusoid corner{e.x * e.x + e.y * e.y + u.x * u.x + u.y * u.y,
                          2 * (e.x * u.x + e.y * u.y), 2 * (e.x * u.y - e.y * u.x)};
    if (step.holds_minimum(corner)) return false;
  }
  for (int j = 0; j < n; ++j) {
    const Vec2 a = c.body_vertex(j), b = c.body_vertex((j + 1) % n);
    const Vec2 e{chart.body.x - a.x, chart.body.y - a.y};
    const double length = std::sqrt((b.x - a.x) * (b.x - a.x) + (b.y - a.y) * (b.y - a.y));
    const Vec2 normal{-(b.y - a.y) / length, (b.x - a.x) / length};
    const Sinusoid line{normal.x * e.x + normal.y * e.y, normal.x * u.x + normal.y * u.y,
                        normal.x * u.y - normal.y * u.x};
    const double at_lo = line.at(step.lo()), at_hi = line.at(step.hi());
    const bool above = at_lo > off && at_hi > off, below = at_lo < -off && at_hi < -off;
    if (!(above || below) || step.holds_minimum(above ? line : -line)) return false;
  }
  std::array<Vec2, kMaxSeatClearances> world{};
  c.world_vertices(chart.full(0.0, {lo, 0.0}), world);
  return !c.inside_block(k, world);
}

// The sweep keeps every vertex's and point's sinusoids in one block: each point's claims are the
// ones its own sinusoids make, on the type B block turning about its heel and about the fold.
TEST(SeatReuse, ASweepsPointClaimsAreTheOnesItsOwnSinusoidsMake) {
  const ReuseTypeBSeat seat;
  const SeatContacts& c = seat.contacts;
  const double off = kSeatLineMargin * seat.geometry.size();
  GuardClaims every;
  every.fill(true);
  FixedUniforms u(65);
  int claimed = 0, asked = 0;
  for (const Vec2 body : {c.body_vertex(0), Vec2{c.body_vertex(1).x - 1.0, c.body_vertex(1).y}}) {
    const Vec2 point = body.x == c.body_vertex(0).x ? c.seat_point(0) : c.seat_point(1);
    const WatchedList points = point.x == c.seat_point(0).x ? WatchedList{1, 2} : WatchedList{0, 2};
    const SeatSystem system(seat.context,
                            {{{ContactKind::block_vertex, 0, 0}, ContactState::stick}},
                            {1, 2, 3, 4, 5}, points);
    const PivotChart chart{point, body};
    PivotSweep sweep(system, chart);
    for (int n = 0; n < 2000; ++n) {
      const double lo = u(-1.2, 1.2), hi = lo + (n % 2 == 0 ? u(0, 0.3) : u(0, 1e-3));
      const GuardClaims claims = sweep.claims(lo, hi, every);
      for (std::size_t at = 0; at < points.size(); ++at) {
        const std::size_t g = kFirstClearanceGuard + 5 + at;
        const bool expected = reuse_point_claim(c, chart, points[at], lo, hi, off);
        EXPECT_EQ(claims[g], expected) << n << " point " << points[at];
        claimed += expected;
        ++asked;
      }
    }
  }
  EXPECT_GT(claimed, asked / 10);
  EXPECT_LT(claimed, asked * 9 / 10);
}

// On a long sloping one-segment seat, far inside its ends, each watched vertex's claim is that its
// own height over the segment's line holds no minimum in the step.
TEST(SeatReuse, ASweepsVertexClaimsAreTheOnesTheirOwnHeightsMake) {
  const std::vector<std::array<double, 2>> line = {{-100, -7}, {100, 9}};
  const SeatContacts c(kReuseTypeA, line);
  const BlockGeometry geometry{PolygonBlock{kReuseTypeA, 1.0}};
  MotionPiece still{MotionPiece::Formula{}, 0.0, 1e3};
  const SeatSystemContext context{&c, &geometry, &still, &still, 9.81, 1.0, geometry.size()};
  const WatchedList vertices{0, 2, 3, 4};
  const SeatSystem system(context, {{{ContactKind::block_vertex, 1, 0}, ContactState::stick}},
                          vertices, {});
  const double m = (9.0 - -7.0) / (100.0 - -100.0);
  const Vec2 pivot{3.0, -7.0 + m * 103.0};
  const PivotChart chart{pivot, c.body_vertex(1)};
  PivotSweep sweep(system, chart);
  GuardClaims every;
  every.fill(true);
  FixedUniforms u(66);
  int claimed = 0, asked = 0;
  for (int n = 0; n < 2000; ++n) {
    // Tilts all round, for steps that hold each height's minimum.
    const double lo = u(-3, 3), hi = lo + (n % 2 == 0 ? u(0, 1.2) : u(0, 1e-3));
    const ThetaStep step(lo, hi);
    const GuardClaims claims = sweep.claims(lo, hi, every);
    for (std::size_t at = 0; at < vertices.size(); ++at) {
      const Vec2 v = c.body_vertex(vertices[at]);
      const Vec2 w{v.x - chart.body.x, v.y - chart.body.y};
      const Sinusoid height{pivot.y - -7.0 - m * (pivot.x - -100.0), w.y - m * w.x, w.x + m * w.y};
      const bool expected = !step.holds_minimum(height);
      EXPECT_EQ(claims[kFirstClearanceGuard + at], expected) << n << " vertex " << vertices[at];
      claimed += expected;
      ++asked;
    }
  }
  EXPECT_GT(claimed, asked / 2);
  EXPECT_GT(asked - claimed, asked / 40);
}

}  // namespace
}  // namespace blockfrag
