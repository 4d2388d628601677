// Sets of sample indices as sorted, disjoint ranges: what a study has done and what it still has
// to do take memory in the number of gaps, not in the number of samples, so a study of a billion
// samples is tracked in a few kilobytes.
#pragma once

#include <cstdint>
#include <map>
#include <vector>

namespace blockfrag {

struct IndexRange {
  std::int64_t first = 0;
  std::int64_t count = 0;
  bool empty() const { return count <= 0; }
  std::int64_t end() const { return first + count; }
};

class IndexSet {
 public:
  // Adds the indices of range; adjacent and overlapping ranges merge.
  void add(IndexRange range);
  bool contains(std::int64_t index) const;
  std::int64_t count() const { return count_; }
  // How many of the indices below `end` the set holds.
  std::int64_t count_below(std::int64_t end) const;
  // Sorted, disjoint, none adjacent to the next.
  std::vector<IndexRange> ranges() const;
  // The indices of [0, total) not in the set, sorted.
  std::vector<IndexRange> missing(std::int64_t total) const;

 private:
  std::map<std::int64_t, std::int64_t> ends_;  // first -> end (one past the last)
  std::int64_t count_ = 0;
};

}  // namespace blockfrag
