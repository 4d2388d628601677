// Which sample indices are still to be computed, handed out in contiguous chunks. Chunks shrink
// as the queue empties (guided self-scheduling): large chunks keep messages rare early on, small
// ones near the end keep every rank busy until the last sample, whatever each scene costs.
// Which rank computes a sample never changes its result (samples are pure), only when.
#pragma once

#include <cstdint>
#include <deque>
#include <vector>

#include "mpi_driver/parallel/index_ranges.hpp"

namespace blockfrag {

class WorkQueue {
 public:
  // The indices of `pending`, in order.
  explicit WorkQueue(const std::vector<IndexRange>& pending);

  // At most max_count indices, about remaining / (2 * consumers) and at least one; an empty
  // range when nothing is left.
  IndexRange next_chunk(int consumers, std::int64_t max_count);

  // Puts back indices that were handed out but not computed (an interrupted chunk).
  void give_back(IndexRange range);

  std::int64_t remaining() const { return remaining_; }

 private:
  std::deque<IndexRange> ranges_;
  std::int64_t remaining_ = 0;
};

}  // namespace blockfrag
