// The minimum overturning amplitude's refinement without MPI or the engine, on stand-in columns
// whose overturning bands are known exactly: a band narrower than the map's step, which the map
// steps over, is found and bisected to the tolerance when a neighbouring map point comes near
// overturning, and missed when none does (what the refinement cannot do); two bands found in one
// round keep the lower; the first segments of a column (failed points, a minimum below the grid, a
// column that never overturns); the budget and a failed midpoint; and the refinement's file: a
// round trip of every bit, damage refused.
#include "mpi_driver/study/minimum_overturning.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "mpi_driver/parallel/checkpoint.hpp"
#include "mpi_driver/parallel/minimum_refinement_state.hpp"

namespace blockfrag {
namespace {

using V = SpectrumVerdict;
using MinimumResponse = std::function<MinimumPoint(double amplitude)>;

// A stand-in response: overturns in [low, high) of each band (after more impacts) and stands
// elsewhere, with max |theta| / alpha = 1 - 2 sqrt(d) (d the distance to the nearest band's edge,
// at least 0), the square root with which a rocking block's peak approaches alpha.
MinimumResponse banded_response(std::vector<std::pair<double, double>> bands) {
  return [bands = std::move(bands)](double a) {
    double distance = 1e300;
    for (const auto& [low, high] : bands) {
      if (a >= low && a < high) return MinimumPoint{V::overturns_more_impacts, 6.0};
      distance = std::min({distance, std::abs(a - low), std::abs(a - high)});
    }
    return MinimumPoint{V::stands, std::max(0.0, 1.0 - 2.0 * std::sqrt(distance))};
  };
}

// The map's grid for the stand-ins: 1.0, 1.1, ..., 3.0.
std::vector<double> stand_in_grid() {
  std::vector<double> grid;
  for (int k = 0; k <= 20; ++k) grid.push_back(1.0 + 0.1 * k);
  return grid;
}

struct ColumnRun {
  SpectrumBracket map_onset;  // the map's lowest onset, bisected to 1e-9
  MinimumRefinement refinement;
  FrequencyMinimum minimum;
};

// One frequency as the runner does it: the map, its crossings bisected, the refinement's rounds.
ColumnRun refine_column(const MinimumResponse& response, const MinimumOverturningSettings& settings,
                        const std::vector<double>& grid = stand_in_grid()) {
  std::vector<MinimumPoint> column;
  std::vector<V> verdicts;
  for (const double a : grid) {
    column.push_back(response(a));
    verdicts.push_back(column.back().verdict);
  }
  std::vector<SpectrumBracket> brackets = column_brackets(0, grid, verdicts, 1e-9);
  for (SpectrumBracket& b : brackets) {
    while (b.is_open()) narrow(b, response(b.midpoint()).verdict, 1e-9, 60);
  }
  ColumnRun run;
  if (!brackets.empty()) run.map_onset = brackets.front();
  run.refinement = start_minimum_refinement(
      7, 1, column_segments(0, grid, column, brackets, settings), settings);
  for (int round = 0; round < 100; ++round) {
    std::vector<MinimumPoint> points;
    for (const MinimumSegment& s : run.refinement.segments) {
      if (s.is_open()) points.push_back(response(s.midpoint()));
    }
    if (points.empty()) break;
    refine_minimum(run.refinement, points, settings);
  }
  run.minimum = frequency_minima(run.refinement).at(0);
  return run;
}

TEST(MinimumOverturning, FindsABandNarrowerThanTheGridAndBisectsIt) {
  // The band [1.52, 1.523) lies between the map's 1.5 and 1.6, which stand; the map's lowest onset
  // is 2.0. 1.5 is 0.02 from the band: max |theta| / alpha = 0.72 there.
  const ColumnRun run = refine_column(banded_response({{1.52, 1.523}, {2.0, 1e9}}), {});
  EXPECT_NEAR(run.map_onset.midpoint(), 2.0, 1e-8);
  EXPECT_EQ(run.minimum.state, static_cast<std::int64_t>(MinimumState::found));
  EXPECT_LT(run.minimum.low, 1.52);
  EXPECT_GE(run.minimum.high, 1.52);
  EXPECT_LE(run.minimum.high - run.minimum.low, 1e-3 * run.minimum.high);
  EXPECT_EQ(run.minimum.verdict_high, static_cast<std::int64_t>(V::overturns_more_impacts));
  EXPECT_EQ(run.minimum.midpoints, run.refinement.midpoints[0]);
  // Only the onset bracket and nothing above it are left.
  ASSERT_EQ(run.refinement.segments.size(), 1u);
  EXPECT_TRUE(run.refinement.segments[0].onset());
}

TEST(MinimumOverturning, ATighterToleranceBracketsItTighter) {
  MinimumOverturningSettings settings;
  settings.tolerance = 1e-6;
  const ColumnRun run = refine_column(banded_response({{1.52, 1.523}, {2.0, 1e9}}), settings);
  EXPECT_LT(run.minimum.low, 1.52);
  EXPECT_GE(run.minimum.high, 1.52);
  EXPECT_LE(run.minimum.high - run.minimum.low, 1e-6 * run.minimum.high);
}

TEST(MinimumOverturning, MissesABandNoMapNeighbourComesNearTo) {
  // What it cannot do: with near_overturning = 0.8, 1.5 (0.72) and 1.6 (0.44) are not near, so
  // the band between them is never probed, and the minimum is the map's onset.
  MinimumOverturningSettings settings;
  settings.near_overturning = 0.8;
  const ColumnRun run = refine_column(banded_response({{1.52, 1.523}, {2.0, 1e9}}), settings);
  EXPECT_EQ(run.minimum.state, static_cast<std::int64_t>(MinimumState::found));
  EXPECT_EQ(run.minimum.low, run.map_onset.low);
  EXPECT_EQ(run.minimum.high, run.map_onset.high);
}

TEST(MinimumOverturning, KeepsTheLowerOfTwoBandsFoundInOneRound) {
  // The first round's probes have midpoints 1.45 and 1.65: both overturn, in two narrow bands.
  const ColumnRun run =
      refine_column(banded_response({{1.449, 1.451}, {1.649, 1.651}, {2.0, 1e9}}), {});
  EXPECT_LT(run.minimum.low, 1.449);
  EXPECT_GE(run.minimum.high, 1.449);
  EXPECT_LE(run.minimum.high - run.minimum.low, 1e-3 * run.minimum.high);
}

TEST(MinimumOverturning, ColumnSegmentsStartFromTheMapAndItsOnset) {
  const std::vector<double> grid{1.0, 2.0, 3.0, 4.0, 5.0, 6.0};
  const std::vector<MinimumPoint> column{{V::stands, 0.1}, {V::stands, 0.9},
                                         {V::failed, 0.0}, {V::still_moving, 0.95},
                                         {V::stands, 0.3}, {V::overturns_one_impact, 6.0}};
  SpectrumBracket onset;
  onset.frequency_index = 2;
  onset.low = 5.25;
  onset.high = 5.25 + 1e-8;
  onset.verdict_low = static_cast<std::int64_t>(V::stands);
  onset.verdict_high = static_cast<std::int64_t>(V::overturns_one_impact);
  onset.state = static_cast<std::int64_t>(BracketState::converged);
  const std::vector<MinimumSegment> segments =
      column_segments(2, grid, column, std::vector<SpectrumBracket>{onset}, {});
  // [1, 2] probe (0.9 is near); [2, 3] and [3, 4] touch the failed point; [4, 5] probe (0.95);
  // [5, 5.25] probe (its upper end's ratio unknown: near); the onset bracket, closed.
  ASSERT_EQ(segments.size(), 6u);
  const double lows[] = {1, 2, 3, 4, 5, 5.25};
  const SegmentState states[] = {SegmentState::open, SegmentState::failed, SegmentState::failed,
                                 SegmentState::open, SegmentState::open,   SegmentState::closed};
  for (std::size_t k = 0; k < segments.size(); ++k) {
    EXPECT_EQ(segments[k].frequency_index, 2);
    EXPECT_EQ(segments[k].low, lows[k]) << k;
    EXPECT_EQ(segments[k].state, static_cast<std::int64_t>(states[k])) << k;
    EXPECT_EQ(segments[k].onset(), k == 5) << k;
  }
  EXPECT_TRUE(std::isnan(segments[4].near_high));
  EXPECT_TRUE(std::isnan(segments[5].near_low));

  // A column whose lowest amplitude overturns: its marker only, closed.
  const std::vector<MinimumPoint> below{{V::overturns_no_impact, 6.0}, {V::stands, 0.2}};
  const auto marker = column_segments(0, std::vector<double>{1.0, 2.0}, below, {}, {});
  ASSERT_EQ(marker.size(), 1u);
  EXPECT_TRUE(marker[0].below_grid());
  MinimumRefinement refinement = start_minimum_refinement(1, 1, marker, {});
  const FrequencyMinimum minimum = frequency_minima(refinement)[0];
  EXPECT_EQ(minimum.state, static_cast<std::int64_t>(MinimumState::below_grid));
  EXPECT_EQ(minimum.high, 1.0);
  EXPECT_TRUE(std::isnan(minimum.amplitude_ratio));

  // A column that never overturns and never comes near: nothing to probe, no minimum.
  const std::vector<MinimumPoint> calm{{V::stands, 0.1}, {V::stands, 0.2}, {V::stands, 0.3}};
  EXPECT_TRUE(column_segments(0, std::vector<double>{1, 2, 3}, calm, {}, {}).empty());
  const FrequencyMinimum none = frequency_minima(start_minimum_refinement(1, 1, {}, {}))[0];
  EXPECT_EQ(none.state, static_cast<std::int64_t>(MinimumState::none));
  EXPECT_EQ(none.verdict_high, -1);
}

TEST(MinimumOverturning, StopsAtItsBudgetAndAtAFailedMidpoint) {
  MinimumOverturningSettings settings;
  settings.max_midpoints = 3;
  const ColumnRun capped = refine_column(banded_response({{1.52, 1.523}, {2.0, 1e9}}), settings);
  EXPECT_EQ(capped.minimum.state, static_cast<std::int64_t>(MinimumState::capped));
  EXPECT_EQ(capped.minimum.midpoints, 3);

  // The probe's midpoint 1.55 fails: the band is not found, and the minimum is uncertain.
  const MinimumResponse banded = banded_response({{1.52, 1.523}, {2.0, 1e9}});
  const ColumnRun failed = refine_column(
      [&](double a) {
        return a > 1.51 && a < 1.59 ? MinimumPoint{V::failed, 0.0} : banded(a);
      },
      {});
  EXPECT_EQ(failed.minimum.state, static_cast<std::int64_t>(MinimumState::failed));
  EXPECT_NEAR(failed.minimum.amplitude_ratio, 2.0, 1e-8);
}

TEST(MinimumOverturning, TheRefinementFileRoundTripsAndRefusesDamage) {
  MinimumRefinement refinement =
      start_minimum_refinement(0xabcdefULL, 3,
                               {MinimumSegment{0, 1.0, 1.5, 0, 0, 0.7, std::nan(""), 0},
                                MinimumSegment{2, 1.5, 2.0, 0, 3, 0.9, 6.0, 1}},
                               {});
  refinement.round = 4;
  refinement.midpoints = {11, 0, 5};
  const std::string bytes = encode_minimum_refinement(refinement);
  const MinimumRefinement back = decode_minimum_refinement(bytes, "s.minimum", 10, 3);
  EXPECT_EQ(encode_minimum_refinement(back), bytes);
  EXPECT_EQ(back.round, 4);
  EXPECT_EQ(back.midpoints, refinement.midpoints);
  ASSERT_EQ(back.segments.size(), 2u);
  EXPECT_TRUE(std::isnan(back.segments[0].near_high));

  EXPECT_THROW(decode_minimum_refinement(bytes, "s.minimum", 1, 3), CheckpointError);  // too many
  EXPECT_THROW(decode_minimum_refinement(bytes, "s.minimum", 10, 2),
               CheckpointError);  // frequencies
  std::string damaged = bytes;
  damaged[40] ^= 1;
  EXPECT_THROW(decode_minimum_refinement(damaged, "s.minimum", 10, 3), CheckpointError);
  EXPECT_THROW(decode_minimum_refinement(bytes.substr(0, bytes.size() - 1), "s.minimum", 10, 3),
               CheckpointError);
  // A segment the refinement could not have written, with a valid checksum: refused.
  MinimumRefinement implausible = refinement;
  implausible.segments[1].low = 2.5;
  try {
    decode_minimum_refinement(encode_minimum_refinement(implausible), "s.minimum", 10, 3);
    FAIL() << "accepted a segment whose ends are out of order";
  } catch (const CheckpointError& error) {
    EXPECT_NE(std::string(error.what()).find("s.minimum: not a usable blockfrag minimum"),
              std::string::npos)
        << error.what();
  }
}

}  // namespace
}  // namespace blockfrag
