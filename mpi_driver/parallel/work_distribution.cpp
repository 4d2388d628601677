#include "mpi_driver/parallel/work_distribution.hpp"

#include <algorithm>

namespace blockfrag {

WorkQueue::WorkQueue(const std::vector<IndexRange>& pending) {
  for (const IndexRange& range : pending) give_back(range);
}

IndexRange WorkQueue::next_chunk(int consumers, std::int64_t max_count) {
  if (ranges_.empty()) return {};
  const auto guided = remaining_ / (2 * std::max(consumers, 1));
  const auto wanted = std::clamp<std::int64_t>(guided, 1, std::max<std::int64_t>(max_count, 1));
  auto& front = ranges_.front();
  const IndexRange chunk{front.first, std::min(wanted, front.count)};
  front.first += chunk.count;
  front.count -= chunk.count;
  if (front.empty()) ranges_.pop_front();
  remaining_ -= chunk.count;
  return chunk;
}

void WorkQueue::give_back(IndexRange range) {
  if (range.empty()) return;
  ranges_.push_back(range);
  remaining_ += range.count;
}

}  // namespace blockfrag
