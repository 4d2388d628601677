// ChunkSizer: chunks of a fixed time at the recent cost per sample, within their bounds.
#include "mpi_driver/parallel/chunk_sizing.hpp"

#include <gtest/gtest.h>

namespace blockfrag {
namespace {

TEST(ChunkSizer, StartsAtTheSmallestChunkUntilASampleIsTimed) {
  ChunkSizer sizer(0.2, 64, 16384);
  EXPECT_EQ(sizer.limit(), 64);
  sizer.record(1e-3);
  EXPECT_EQ(sizer.limit(), 200);  // 0.2 s / 1 ms
}

TEST(ChunkSizer, StaysWithinItsBounds) {
  ChunkSizer cheap(0.2, 64, 16384);
  for (int i = 0; i < 100; ++i) cheap.record(1e-7);
  EXPECT_EQ(cheap.limit(), 16384);
  ChunkSizer dear(0.2, 64, 16384);
  for (int i = 0; i < 100; ++i) dear.record(0.5);
  EXPECT_EQ(dear.limit(), 64);
  ChunkSizer instant(0.2, 64, 16384);
  instant.record(0.0);  // a clock too coarse to see a sample
  EXPECT_EQ(instant.limit(), 16384);
}

// The example study's first level costs 1.4 us a sample, the next ones about 70 us: after a
// hundred of those the chunks are sized for them (0.2 s / 70 us = 2,858), not for the average since
// the start (which still gave the largest chunk).
TEST(ChunkSizer, FollowsALevelThatCostsMoreWithinAHundredSamples) {
  ChunkSizer sizer(0.2, 64, 16384);
  for (int i = 0; i < 10000; ++i) sizer.record(1.4e-6);
  EXPECT_EQ(sizer.limit(), 16384);
  for (int i = 0; i < 100; ++i) sizer.record(70e-6);
  EXPECT_GT(sizer.limit(), 2858);
  EXPECT_LT(sizer.limit(), 1.1 * 2858);
  for (int i = 0; i < 200; ++i) sizer.record(70e-6);
  EXPECT_NEAR(static_cast<double>(sizer.limit()), 2858.0, 1.0);
}

TEST(ChunkSizer, OneSlowSampleAmongCheapOnesMovesTheLimitLittle) {
  ChunkSizer sizer(0.2, 64, 100000);
  for (int i = 0; i < 1000; ++i) sizer.record(1e-4);
  EXPECT_EQ(sizer.limit(), 2000);
  sizer.record(1e-3);  // ten times the others: the mean grows by 9/32 of theirs
  EXPECT_NEAR(static_cast<double>(sizer.limit()), 0.2 / (1e-4 * (1 + 9.0 / 32)), 1.0);
}

}  // namespace
}  // namespace blockfrag
