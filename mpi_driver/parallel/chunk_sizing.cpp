#include "mpi_driver/parallel/chunk_sizing.hpp"

#include <algorithm>
#include <cmath>

namespace blockfrag {
namespace {

// Each sample moves the average this far towards its own time: after 100 samples of a new
// level's cost, the old level's weighs e^-3 (5 %), and one slow sample among cheap ones moves the
// average by 1/32 of its time.
constexpr double kWeight = 1.0 / 32.0;

}  // namespace

ChunkSizer::ChunkSizer(double seconds, std::int64_t smallest, std::int64_t largest)
    : seconds_(seconds), smallest_(smallest), largest_(largest) {}

void ChunkSizer::record(double sample_seconds) {
  if (!(sample_seconds >= 0.0)) return;
  mean_seconds_ =
      timed_ ? mean_seconds_ + kWeight * (sample_seconds - mean_seconds_) : sample_seconds;
  timed_ = true;
}

std::int64_t ChunkSizer::limit() const {
  if (!timed_) return smallest_;
  if (!(mean_seconds_ > 0.0)) return largest_;
  const double samples = std::ceil(seconds_ / mean_seconds_);
  if (!(samples < static_cast<double>(largest_))) return largest_;
  return std::max(static_cast<std::int64_t>(samples), smallest_);
}

}  // namespace blockfrag
