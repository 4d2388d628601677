// What the seat's guards reuse instead of finding it again (engine/seat/seat_contacts.hpp): each
// is checked to the bit against the general path on random and edge inputs.
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "engine/seat/seat_contacts.hpp"
#include "engine/sine_cosine.hpp"
#include "tests/support/fixed_uniforms.hpp"
#include "tests/support/type_b_block.hpp"

namespace blockfrag {
namespace {

using testing::FixedUniforms;
using testing::kTypeB;

const std::vector<std::array<double, 2>> kReuseTypeA = {
    {0, 0}, {12.55, 0}, {10, 3.4}, {10, 16.7}, {0, 16.7}};

std::uint64_t reuse_bits(double x) { return std::bit_cast<std::uint64_t>(x); }
double reuse_norm(Vec2 v) { return std::sqrt(v.x * v.x + v.y * v.y); }

// The block's vertices at s, each turned on its own.
std::vector<Vec2> reuse_turned_anew(const SeatContacts& contacts, const BlockState& s) {
  const SineCosine turn = sine_cosine(s.theta);
  std::vector<Vec2> out;
  for (int i = 0; i < contacts.vertex_count(); ++i) {
    const Vec2 r = rotate(contacts.body_vertex(i), turn.cos, turn.sin);
    out.push_back({s.x + r.x, s.y + r.y});
  }
  return out;
}

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

TEST(SeatReuse, TheVerticesKeptForAPoseAreTheOnesTurnedAnewThere) {
  for (const auto& block : {kReuseTypeA, kTypeB}) {
    const SeatContacts contacts(block, {{-100, 0}, {100, 0}});
    for (const BlockState& s : reuse_poses_in_turn()) {
      const std::vector<Vec2> expected = reuse_turned_anew(contacts, s);
      // Alternating the two askers: the copy out and the kept vertices read in place.
      std::array<Vec2, kMaxSeatClearances> out{};
      contacts.world_vertices(s, out);
      const std::span<const Vec2> kept = contacts.world_at(s);
      ASSERT_EQ(kept.size(), expected.size());
      for (std::size_t i = 0; i < expected.size(); ++i) {
        EXPECT_EQ(reuse_bits(out[i].x), reuse_bits(expected[i].x))
            << s.x << " " << s.y << " " << s.theta;
        EXPECT_EQ(reuse_bits(out[i].y), reuse_bits(expected[i].y));
        EXPECT_EQ(reuse_bits(kept[i].x), reuse_bits(expected[i].x));
        EXPECT_EQ(reuse_bits(kept[i].y), reuse_bits(expected[i].y));
      }
      contacts.world_vertices(s, out);
      EXPECT_EQ(reuse_bits(out[1].x), reuse_bits(expected[1].x));
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

TEST(SeatReuse, AOneSegmentSeatsClearanceIsTheGeneralOnesToTheBit) {
  FixedUniforms u(62);
  const std::vector<std::vector<Vec2>> seats = {{{-100, 0}, {100, 0}},
                                                {{-3.1, 1.7}, {7.3, 2.9}},
                                                {{0.3, 4.1}, {6.7, -2.3}},
                                                {{-1, 0}, {1, 3}}};
  for (const auto& seat : seats) {
    std::vector<std::array<double, 2>> points;
    for (const Vec2& p : seat) points.push_back({p.x, p.y});
    const SeatContacts contacts(kReuseTypeA, points);
    const double x0 = seat.front().x, x1 = seat.back().x;
    std::vector<Vec2> probes{
        {x0, 0.0},  {x1, -1.0},  {std::nextafter(x0, -1e9), 1.0}, {std::nextafter(x1, 1e9), -1.0},
        {0.0, 0.0}, {-0.0, -0.0}};
    for (int n = 0; n < 3000; ++n) {
      const double reach = (x1 - x0) * 0.6;
      probes.push_back({u(x0 - reach, x1 + reach), u(-5, 5)});
    }
    for (const Vec2& p : probes) {
      const double expected = reuse_clearance_over_any_seat(seat, contacts, p);
      EXPECT_EQ(reuse_bits(contacts.clearance_at(p)), reuse_bits(expected)) << p.x << " " << p.y;
    }
  }
}

}  // namespace
}  // namespace blockfrag
