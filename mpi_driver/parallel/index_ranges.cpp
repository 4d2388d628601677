#include "mpi_driver/parallel/index_ranges.hpp"

#include <algorithm>
#include <iterator>

namespace blockfrag {

void IndexSet::add(IndexRange range) {
  if (range.empty()) return;
  std::int64_t first = range.first, end = range.end();
  // The first stored range that could touch [first, end): the one starting at or before first.
  auto it = ends_.upper_bound(first);
  if (it != ends_.begin() && std::prev(it)->second >= first) --it;
  while (it != ends_.end() && it->first <= end) {
    first = std::min(first, it->first);
    end = std::max(end, it->second);
    count_ -= it->second - it->first;
    it = ends_.erase(it);
  }
  ends_.emplace(first, end);
  count_ += end - first;
}

bool IndexSet::contains(std::int64_t index) const {
  auto it = ends_.upper_bound(index);
  if (it == ends_.begin()) return false;
  return std::prev(it)->second > index;
}

std::int64_t IndexSet::count_below(std::int64_t end) const {
  std::int64_t count = 0;
  for (const auto& [first, range_end] : ends_) {
    if (first >= end) break;
    count += std::min(range_end, end) - first;
  }
  return count;
}

std::vector<IndexRange> IndexSet::ranges() const {
  std::vector<IndexRange> out;
  out.reserve(ends_.size());
  for (const auto& [first, end] : ends_) out.push_back({first, end - first});
  return out;
}

std::vector<IndexRange> IndexSet::missing(std::int64_t total) const {
  std::vector<IndexRange> out;
  std::int64_t next = 0;
  for (const auto& [first, end] : ends_) {
    if (first >= total) break;
    if (first > next) out.push_back({next, first - next});
    next = std::max(next, end);
  }
  if (next < total) out.push_back({next, total - next});
  return out;
}

}  // namespace blockfrag
