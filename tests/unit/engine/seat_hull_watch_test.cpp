// The block vertices a one-segment seat watches for touching (engine/seat/hull_watch.hpp): while
// the vertices carrying the block are on the seat's line and the watched ones above it, every
// vertex is above it, on random convex and non-convex blocks and random lines; and the seat's
// system watches exactly the carrying chain's hull neighbours on one segment, every vertex not in
// contact elsewhere.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "engine/seat/hull_watch.hpp"
#include "tests/support/random_trials.hpp"
#include "tests/support/type_b_block.hpp"

namespace blockfrag {
namespace {

// A random simple polygon, counter-clockwise: n vertices at increasing angles about the origin,
// on the unit circle (convex) or at random radii (mostly non-convex, star-shaped).
std::vector<Vec2> random_polygon(std::mt19937_64& rng, bool convex) {
  std::uniform_int_distribution<int> count(3, 12);
  std::uniform_real_distribution<double> turn(0.0, 2.0 * std::numbers::pi), radius(0.2, 1.0);
  std::vector<double> angles(static_cast<std::size_t>(count(rng)));
  for (double& a : angles) a = turn(rng);
  std::sort(angles.begin(), angles.end());
  std::vector<Vec2> out;
  for (const double a : angles) {
    const double r = convex ? 1.0 : radius(rng);
    out.push_back({r * std::cos(a), r * std::sin(a)});
  }
  return out;
}

double height(Vec2 v, Vec2 on_line, Vec2 normal) {
  return (v.x - on_line.x) * normal.x + (v.y - on_line.y) * normal.y;
}

// With the carrying vertices on a line of upward normal `normal`: whenever the watched vertices are
// all above it, every vertex but the carrying ones is; returns whether they were (so that the
// trials can count how often the claim was put to the test).
bool check_above(const std::vector<Vec2>& body, const std::vector<int>& carrying,
                 const WatchedList& watched, Vec2 normal) {
  const Vec2 p = body[static_cast<std::size_t>(carrying.front())];
  const auto above = [&](int v) {
    return height(body[static_cast<std::size_t>(v)], p, normal) > 0;
  };
  if (!std::all_of(watched.begin(), watched.end(), above)) return false;
  for (int v = 0; v < static_cast<int>(body.size()); ++v) {
    if (std::find(carrying.begin(), carrying.end(), v) != carrying.end()) continue;
    EXPECT_TRUE(above(v)) << "vertex " << v << " of " << body.size();
  }
  return true;
}

TEST(HullWatch, WhileTheWatchedVerticesAreAboveTheLineEveryVertexIs) {
  std::mt19937_64 rng(20261207);
  std::uniform_real_distribution<double> tilt(-std::numbers::pi, std::numbers::pi);
  int put_to_test = 0, pivots = 0, chains = 0;
  std::size_t dropped = 0;  // vertices a pivot does not watch
  const int trials = testing::random_trials(400);
  for (int trial = 0; trial < trials; ++trial) {
    const std::vector<Vec2> body = random_polygon(rng, trial % 2 == 0);
    const HullWatch watch(body);
    const std::vector<int>& hull = watch.hull();
    for (std::size_t k = 0; k < hull.size(); ++k) {
      // One pivot on lines of every tilt through it.
      const std::vector<int> pivot = {hull[k]};
      const WatchedList watched = watch.watched(pivot).value();
      dropped += body.size() - 1 - watched.size();
      for (int line = 0; line < 50; ++line) {
        const double a = tilt(rng);
        put_to_test += check_above(body, pivot, watched, {-std::sin(a), std::cos(a)});
        ++pivots;
      }
      // Two neighbouring hull vertices on their edge's line, the block on its inner side.
      const int next = hull[(k + 1) % hull.size()];
      const Vec2 from = body[static_cast<std::size_t>(hull[k])];
      const Vec2 to = body[static_cast<std::size_t>(next)];
      const double length = std::hypot(to.x - from.x, to.y - from.y);
      const Vec2 inward = {-(to.y - from.y) / length, (to.x - from.x) / length};
      for (const std::vector<int>& chain : {std::vector<int>{hull[k], next}, {next, hull[k]}}) {
        EXPECT_TRUE(check_above(body, chain, watch.watched(chain).value(), inward));
        ++chains;
      }
    }
  }
  // The claim was tested on a good share of the lines, not only on lines that cut the block.
  EXPECT_GT(put_to_test, pivots / 10);
  EXPECT_GT(chains, 0);
  EXPECT_GT(dropped, static_cast<std::size_t>(trials));
}

TEST(HullWatch, WatchesOnlyTheHullNeighboursOfTheChain) {
  const std::vector<Vec2> type_a = {{0, 0}, {12.55, 0}, {10, 3.4}, {10, 16.7}, {0, 16.7}};
  const HullWatch watch(type_a);
  EXPECT_EQ(watch.hull(), (std::vector<int>{0, 1, 3, 4}));
  EXPECT_EQ(watch.watched(std::vector<int>{1}), (WatchedList{0, 3}));
  EXPECT_EQ(watch.watched(std::vector<int>{0}), (WatchedList{1, 4}));
  EXPECT_EQ(watch.watched(std::vector<int>{0, 1}), (WatchedList{3, 4}));
  EXPECT_EQ(watch.watched(std::vector<int>{1, 0}), (WatchedList{3, 4}));
  // Off the hull (the reflex corner), or not one hull edge: no shortcut.
  EXPECT_FALSE(watch.watched(std::vector<int>{2}).has_value());
  EXPECT_FALSE(watch.watched(std::vector<int>{0, 3}).has_value());
  EXPECT_FALSE(watch.watched(std::vector<int>{}).has_value());
  EXPECT_FALSE(HullWatch().watched(std::vector<int>{1}).has_value());
}

TEST(HullWatch, WatchesTheVerticesOnTheHullEdgesAtThePivot) {
  // Vertices 2 and 4 lie on the hull's right face, from vertex 1 to 5: they land with vertex 5.
  const std::vector<Vec2> notched = {{0, 0}, {4, 0}, {4, 4}, {2.5, 5}, {4, 6}, {4, 12}, {0, 12}};
  const HullWatch watch(notched);
  EXPECT_EQ(watch.hull(), (std::vector<int>{0, 1, 5, 6}));
  EXPECT_EQ(watch.watched(std::vector<int>{1}), (WatchedList{0, 2, 4, 5}));
  EXPECT_EQ(watch.watched(std::vector<int>{0}), (WatchedList{1, 6}));
  // A hair inside the face, nearly on it, it is watched too.
  std::vector<Vec2> near = notched;
  near[2] = {4 - 1e-9, 4};
  EXPECT_EQ(HullWatch(near).watched(std::vector<int>{1}), (WatchedList{0, 2, 4, 5}));
}

ActiveContact on_segment(int vertex, int segment) {
  return {{ContactKind::block_vertex, vertex, segment}, ContactState::stick};
}

TEST(HullWatch, TheSeatWatchesTheHullNeighboursOnOneSegmentOnly) {
  const std::vector<Vertex> type_a = {{0, 0}, {12.55, 0}, {10, 3.4}, {10, 16.7}, {0, 16.7}};
  const SeatContacts flat(type_a, {{-100, 0}, {100, 0}});
  const HullWatch hull(body_vertices(flat));
  const std::vector<ActiveContact> pivot = {on_segment(1, 0)};
  const std::vector<ActiveContact> base = {on_segment(0, 0), on_segment(1, 0)};
  EXPECT_EQ(watched_block_vertices(flat, hull, pivot), (WatchedList{0, 3}));
  EXPECT_EQ(watched_block_vertices(flat, hull, base), (WatchedList{3, 4}));
  // In flight, or on the reflex corner, every vertex not in contact.
  EXPECT_EQ(watched_block_vertices(flat, hull, {}), (WatchedList{0, 1, 2, 3, 4}));
  EXPECT_EQ(watched_block_vertices(flat, hull, std::vector<ActiveContact>{on_segment(2, 0)}),
            (WatchedList{0, 1, 3, 4}));
  // A seat's end on a block edge carries the block: every vertex.
  const std::vector<ActiveContact> end = {on_segment(0, 0),
                                          {{ContactKind::seat_point, 1, 1}, ContactState::stick}};
  EXPECT_EQ(watched_block_vertices(flat, hull, end), (WatchedList{1, 2, 3, 4}));
  // The same flat ground as two segments: every vertex not in contact.
  const SeatContacts joint(type_a, {{-100, 0}, {5, 0}, {100, 0}});
  EXPECT_EQ(watched_block_vertices(joint, hull, pivot), (WatchedList{0, 2, 3, 4}));
  // The type B block on its folded seat, pivoting on its heel: every vertex not in contact.
  const SeatContacts folded(testing::kTypeB, testing::kTypeBSeat);
  const HullWatch type_b(body_vertices(folded));
  const std::vector<ActiveContact> pivot_on_heel = {on_segment(0, 0)};
  std::vector<int> all_but_heel;
  for (int i = 1; i < folded.vertex_count(); ++i) all_but_heel.push_back(i);
  const WatchedList watched = watched_block_vertices(folded, type_b, pivot_on_heel);
  EXPECT_EQ(std::vector<int>(watched.begin(), watched.end()), all_but_heel);
}

}  // namespace
}  // namespace blockfrag
