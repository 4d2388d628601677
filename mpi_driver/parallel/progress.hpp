// The study's progress line on stderr: done/total, rate and time to go. Redrawn in place (carriage
// return) when the stream is a terminal; a log line every log_interval_s otherwise, so batch logs
// stay readable.
#pragma once

#include <chrono>
#include <cstdint>
#include <ostream>
#include <string>

namespace blockfrag {

class ProgressReporter {
 public:
  using Clock = std::chrono::steady_clock;

  // already_done: samples restored from a checkpoint (they count as done but not in the rate).
  ProgressReporter(std::ostream& out, bool is_terminal, std::int64_t total,
                   std::int64_t already_done, double log_interval_s = 30.0);

  // Cheap when called after every sample: draws only when the redraw or log interval has passed.
  void update(std::int64_t done, Clock::time_point now = Clock::now());
  // The last line (and the newline that ends a redrawn line).
  void finish(std::int64_t done, Clock::time_point now = Clock::now());

  // "1234/5000 (24.7 %), 81.3 samples/s, ETA 46 s", or "ETA unknown" before the first sample.
  std::string line(std::int64_t done, Clock::time_point now) const;

 private:
  std::ostream& out_;
  bool is_terminal_;
  std::int64_t total_;
  std::int64_t already_done_;
  double interval_s_;
  Clock::time_point start_;
  Clock::time_point last_draw_;
};

// "3 h 05 min", "12 min 07 s", "42 s".
std::string format_duration(double seconds);

}  // namespace blockfrag
