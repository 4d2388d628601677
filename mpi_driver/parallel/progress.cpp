#include "mpi_driver/parallel/progress.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace blockfrag {
namespace {

double seconds_between(ProgressReporter::Clock::time_point from,
                       ProgressReporter::Clock::time_point to) {
  return std::chrono::duration<double>(to - from).count();
}

constexpr double terminal_redraw_s = 0.25;

}  // namespace

std::string format_duration(double seconds) {
  const auto whole = static_cast<long long>(std::llround(std::max(seconds, 0.0)));
  char text[64];
  if (whole >= 3600) {
    std::snprintf(text, sizeof text, "%lld h %02lld min", whole / 3600, (whole % 3600) / 60);
  } else if (whole >= 60) {
    std::snprintf(text, sizeof text, "%lld min %02lld s", whole / 60, whole % 60);
  } else {
    std::snprintf(text, sizeof text, "%lld s", whole);
  }
  return text;
}

ProgressReporter::ProgressReporter(std::ostream& out, bool is_terminal, std::int64_t total,
                                   std::int64_t already_done, double log_interval_s)
    : out_(out),
      is_terminal_(is_terminal),
      total_(total),
      already_done_(already_done),
      interval_s_(is_terminal ? terminal_redraw_s : log_interval_s),
      start_(Clock::now()),
      last_draw_(start_) {}

std::string ProgressReporter::line(std::int64_t done, Clock::time_point now) const {
  const double elapsed = seconds_between(start_, now);
  const auto done_here = done - already_done_;
  const double percent =
      total_ > 0 ? 100.0 * static_cast<double>(done) / static_cast<double>(total_) : 100.0;
  char head[96];
  std::snprintf(head, sizeof head, "%lld/%lld (%.1f %%)", static_cast<long long>(done),
                static_cast<long long>(total_), percent);
  if (done_here <= 0 || elapsed <= 0.0) return std::string(head) + ", ETA unknown";
  const double rate = static_cast<double>(done_here) / elapsed;
  char tail[64];
  std::snprintf(tail, sizeof tail, ", %.1f samples/s, ETA ", rate);
  return std::string(head) + tail + format_duration(static_cast<double>(total_ - done) / rate);
}

void ProgressReporter::update(std::int64_t done, Clock::time_point now) {
  if (seconds_between(last_draw_, now) < interval_s_) return;
  last_draw_ = now;
  if (is_terminal_) {
    out_ << '\r' << line(done, now) << "\033[K" << std::flush;
  } else {
    out_ << "progress: " << line(done, now) << '\n' << std::flush;
  }
}

void ProgressReporter::finish(std::int64_t done, Clock::time_point now) {
  if (is_terminal_) {
    out_ << '\r' << line(done, now) << "\033[K\n" << std::flush;
  } else {
    out_ << "progress: " << line(done, now) << '\n' << std::flush;
  }
}

}  // namespace blockfrag
