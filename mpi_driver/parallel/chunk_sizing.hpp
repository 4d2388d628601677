// How many samples a worker's chunk holds: about a fixed time of one rank's work at the cost per
// sample measured most recently on rank 0. A study's samples run level by level, and levels differ
// in cost by orders of magnitude (the example study's lowest level moves no block: 1.4 us a
// sample, fifty times less than the levels above it). Sized from the average since the start, the
// first expensive chunks held 16,384 samples, a second each, and at 100,000 samples the last of
// them kept one rank busy while the other waited (4.20 s on 2 ranks against 3.99 s with chunks of
// at most 2,000).
#pragma once

#include <cstdint>

namespace blockfrag {

class ChunkSizer {
 public:
  // Chunks of about `seconds` of work, within [smallest, largest] samples.
  ChunkSizer(double seconds, std::int64_t smallest, std::int64_t largest);

  // One sample's evaluation time on this rank, s.
  void record(double sample_seconds);

  // The largest chunk to hand out now: `smallest` until a sample has been timed.
  std::int64_t limit() const;

 private:
  double seconds_;
  std::int64_t smallest_, largest_;
  double mean_seconds_ = 0.0;  // exponentially weighted over the last few dozen samples
  bool timed_ = false;
};

}  // namespace blockfrag
