// The seat's watched vertices or points, held without allocating: in order, compared by content,
// and refusing more than a system has guards for.
#include "engine/seat/watched_list.hpp"

#include <vector>

#include <gtest/gtest.h>

#include "engine/errors.hpp"

namespace blockfrag {
namespace {

TEST(WatchedList, KeepsItsIndicesInOrderAndComparesThem) {
  WatchedList list{4, 0, 7};
  list.push_back(2);
  EXPECT_EQ(std::vector<int>(list.begin(), list.end()), (std::vector<int>{4, 0, 7, 2}));
  EXPECT_EQ(list.size(), 4u);
  EXPECT_EQ(list[2], 7);
  EXPECT_EQ(list, (WatchedList{4, 0, 7, 2}));
  EXPECT_FALSE(list == (WatchedList{4, 0, 7}));
  EXPECT_FALSE(list == (WatchedList{4, 0, 7, 3}));
  EXPECT_TRUE(WatchedList{}.empty());
}

TEST(WatchedList, RefusesMoreThanTheSeatsClearanceGuards) {
  WatchedList list;
  for (int i = 0; i < kMaxSeatClearances; ++i) list.push_back(i);
  EXPECT_THROW(list.push_back(kMaxSeatClearances), ContractViolation);
  EXPECT_EQ(list.size(), static_cast<std::size_t>(kMaxSeatClearances));
}

}  // namespace
}  // namespace blockfrag
