// What a record's motion pieces reuse from the piece before (engine/seat/watched_list.hpp): each
// is checked against what building it anew gives.
#include <array>
#include <cstddef>
#include <vector>

#include <gtest/gtest.h>

#include "engine/seat/watched_list.hpp"

namespace blockfrag {
namespace {

WatchedList piece_list_of(int size, int first) {
  WatchedList list;
  for (int i = 0; i < size; ++i) list.push_back(first + 3 * i);
  return list;
}

std::vector<int> piece_items(const WatchedList& list) { return {list.begin(), list.end()}; }

// A list copied or assigned holds its source's indices, whatever the list it replaces held: every
// size over every size, the longer ones' indices beyond the source's left behind unread.
TEST(SeatPieceReuse, AWatchedListCopiedOrAssignedHoldsItsSourcesIndices) {
  for (int from = 0; from <= kMaxSeatClearances; ++from) {
    const WatchedList source = piece_list_of(from, 1);
    const WatchedList copied(source);
    EXPECT_EQ(piece_items(copied), piece_items(source)) << from;
    for (int over = 0; over <= kMaxSeatClearances; ++over) {
      WatchedList assigned = piece_list_of(over, 2);
      assigned = source;
      EXPECT_EQ(assigned.size(), source.size()) << from << " over " << over;
      EXPECT_EQ(piece_items(assigned), piece_items(source)) << from << " over " << over;
      EXPECT_TRUE(assigned == source);
      if (from < kMaxSeatClearances) {
        assigned.push_back(100);
        EXPECT_EQ(assigned[static_cast<std::size_t>(from)], 100);
      }
    }
  }
}

}  // namespace
}  // namespace blockfrag
