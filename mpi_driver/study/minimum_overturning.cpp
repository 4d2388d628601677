#include "mpi_driver/study/minimum_overturning.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "engine/errors.hpp"

namespace blockfrag {
namespace {

constexpr double kUnknown = std::numeric_limits<double>::quiet_NaN();

std::int64_t code(SegmentState state) { return static_cast<std::int64_t>(state); }
std::int64_t code(SpectrumVerdict verdict) { return static_cast<std::int64_t>(verdict); }

bool within_tolerance(double low, double high, double tolerance) {
  return high - low <= tolerance * high;
}

// An end whose ratio is not known lies at an edge of overturning: near.
bool near_overturning(double near_low, double near_high, double threshold) {
  return std::isnan(near_low) || std::isnan(near_high) ||
         std::max(near_low, near_high) >= threshold;
}

MinimumSegment segment(std::int64_t frequency_index, double low, double high,
                       std::int64_t verdict_low, std::int64_t verdict_high, double near_low,
                       double near_high, SegmentState state) {
  return {frequency_index, low, high, verdict_low, verdict_high, near_low, near_high, code(state)};
}

// The interval [low, high] between two standing amplitudes, kept (open) only when it is worth a
// midpoint: near overturning and wider than the resolution.
void add_probe(std::vector<MinimumSegment>& out, std::int64_t frequency_index, double low,
               double high, std::int64_t verdict_low, std::int64_t verdict_high, double near_low,
               double near_high, const MinimumOverturningSettings& settings) {
  if (within_tolerance(low, high, settings.resolution) ||
      !near_overturning(near_low, near_high, settings.near_overturning)) {
    return;
  }
  out.push_back(segment(frequency_index, low, high, verdict_low, verdict_high, near_low, near_high,
                        SegmentState::open));
}

// An onset bracket [low, high] (stands, overturns): open until within the tolerance.
MinimumSegment onset_segment(std::int64_t frequency_index, double low, double high,
                             std::int64_t verdict_low, std::int64_t verdict_high, double near_low,
                             double near_high, const MinimumOverturningSettings& settings) {
  return segment(
      frequency_index, low, high, verdict_low, verdict_high, near_low, near_high,
      within_tolerance(low, high, settings.tolerance) ? SegmentState::closed : SegmentState::open);
}

// One open segment narrowed, or halved, by the point at its midpoint; what remains of it goes to
// `out`, in order of amplitude.
void split(const MinimumSegment& s, const MinimumPoint& at_midpoint,
           const MinimumOverturningSettings& settings, std::vector<MinimumSegment>& out) {
  if (!decided(at_midpoint.verdict)) {
    MinimumSegment failed = s;
    failed.state = code(SegmentState::failed);
    out.push_back(failed);
    return;
  }
  const double m = s.midpoint();
  const std::int64_t verdict = code(at_midpoint.verdict);
  const double near = at_midpoint.near;
  const std::int64_t f = s.frequency_index;
  if (overturned(at_midpoint.verdict)) {
    // The lower half brackets an onset, of this minimum or of a lower one found by a probe; the
    // upper half lies above an overturning amplitude and no longer matters.
    out.push_back(onset_segment(f, s.low, m, s.verdict_low, verdict, s.near_low, near, settings));
    return;
  }
  add_probe(out, f, s.low, m, s.verdict_low, verdict, s.near_low, near, settings);
  if (s.onset()) {
    out.push_back(
        onset_segment(f, m, s.high, verdict, s.verdict_high, near, s.near_high, settings));
  } else {
    add_probe(out, f, m, s.high, verdict, s.verdict_high, near, s.near_high, settings);
  }
}

// Each frequency keeps only what lies below its lowest overturning amplitude (the upper end of its
// lowest onset bracket).
void drop_above_minimum(std::vector<MinimumSegment>& segments) {
  std::vector<MinimumSegment> kept;
  kept.reserve(segments.size());
  auto first = segments.begin();
  while (first != segments.end()) {
    const auto last = std::find_if(first, segments.end(), [&](const MinimumSegment& s) {
      return s.frequency_index != first->frequency_index;
    });
    double lowest = std::numeric_limits<double>::infinity();
    for (auto s = first; s != last; ++s) {
      if (s->onset()) lowest = std::min(lowest, s->high);
    }
    std::copy_if(first, last, std::back_inserter(kept),
                 [&](const MinimumSegment& s) { return s.below_grid() || s.low < lowest; });
    first = last;
  }
  segments = std::move(kept);
}

// The open segments past a frequency's budget, or past the whole spectrum's, are capped: the
// lowest amplitudes of a frequency get its midpoints first.
void apply_budget(MinimumRefinement& refinement, const MinimumOverturningSettings& settings) {
  std::int64_t left =
      kMaxSpectrumPoints -
      std::accumulate(refinement.midpoints.begin(), refinement.midpoints.end(), std::int64_t{0});
  std::vector<std::int64_t> planned(refinement.midpoints.size(), 0);
  for (MinimumSegment& s : refinement.segments) {
    if (!s.is_open()) continue;
    const auto f = static_cast<std::size_t>(s.frequency_index);
    if (left > 0 && refinement.midpoints[f] + planned[f] < settings.max_midpoints) {
      ++planned[f];
      --left;
    } else {
      s.state = code(SegmentState::capped);
    }
  }
}

}  // namespace

MinimumPoint minimum_point(const SampleRecord& record, double alpha) {
  return {spectrum_verdict(record), record.max_abs_theta / alpha};
}

std::vector<MinimumSegment> column_segments(std::int64_t frequency_index,
                                            std::span<const double> amplitude_ratio,
                                            std::span<const MinimumPoint> column,
                                            std::span<const SpectrumBracket> brackets,
                                            const MinimumOverturningSettings& settings) {
  if (amplitude_ratio.size() != column.size() || column.size() < 2)
    throw ContractViolation("column_segments: one point per amplitude ratio, at least two");
  const std::int64_t f = frequency_index;
  const auto first_overturned = static_cast<std::size_t>(
      std::find_if(column.begin(), column.end(),
                   [](const MinimumPoint& p) { return overturned(p.verdict); }) -
      column.begin());
  if (first_overturned == 0) {
    return {segment(f, amplitude_ratio[0], amplitude_ratio[1], code(column[0].verdict),
                    code(column[1].verdict), column[0].near, column[1].near, SegmentState::closed)};
  }
  std::vector<MinimumSegment> out;
  const std::size_t last = std::min(first_overturned, column.size() - 1);
  for (std::size_t j = 1; j <= last; ++j) {
    const MinimumPoint& below = column[j - 1];
    const MinimumPoint& above = column[j];
    const double low = amplitude_ratio[j - 1], high = amplitude_ratio[j];
    if (!decided(below.verdict) || !decided(above.verdict)) {
      out.push_back(segment(f, low, high, code(below.verdict), code(above.verdict), below.near,
                            above.near, SegmentState::failed));
      continue;
    }
    if (j < first_overturned) {
      add_probe(out, f, low, high, code(below.verdict), code(above.verdict), below.near, above.near,
                settings);
      continue;
    }
    // The map's lowest onset, as its bisection left it: the column's first crossing.
    if (brackets.empty() || brackets.front().low < low || brackets.front().high > high ||
        brackets.front().direction() != +1) {
      throw ContractViolation("column_segments: the column's first crossing is not its onset");
    }
    const SpectrumBracket& b = brackets.front();
    const double near_low = b.low == low ? below.near : kUnknown;
    const double near_high = b.high == high ? above.near : kUnknown;
    if (b.low > low) {
      add_probe(out, f, low, b.low, code(below.verdict), b.verdict_low, below.near, kUnknown,
                settings);
    }
    MinimumSegment onset = onset_segment(f, b.low, b.high, b.verdict_low, b.verdict_high, near_low,
                                         near_high, settings);
    if (b.state == static_cast<std::int64_t>(BracketState::failed))
      onset.state = code(SegmentState::failed);
    out.push_back(onset);
  }
  return out;
}

MinimumRefinement start_minimum_refinement(std::uint64_t config_hash, std::int64_t frequencies,
                                           std::vector<MinimumSegment> segments,
                                           const MinimumOverturningSettings& settings) {
  MinimumRefinement refinement{config_hash, 0,
                               std::vector<std::int64_t>(static_cast<std::size_t>(frequencies), 0),
                               std::move(segments)};
  apply_budget(refinement, settings);
  return refinement;
}

void refine_minimum(MinimumRefinement& refinement, std::span<const MinimumPoint> at_midpoints,
                    const MinimumOverturningSettings& settings) {
  std::vector<MinimumSegment> next;
  next.reserve(refinement.segments.size() + at_midpoints.size());
  std::size_t k = 0;
  for (const MinimumSegment& s : refinement.segments) {
    if (!s.is_open()) {
      next.push_back(s);
      continue;
    }
    if (k == at_midpoints.size())
      throw ContractViolation("refine_minimum: fewer points than open segments");
    ++refinement.midpoints[static_cast<std::size_t>(s.frequency_index)];
    split(s, at_midpoints[k++], settings, next);
  }
  if (k != at_midpoints.size())
    throw ContractViolation("refine_minimum: more points than open segments");
  drop_above_minimum(next);
  refinement.segments = std::move(next);
  ++refinement.round;
  apply_budget(refinement, settings);
}

std::vector<FrequencyMinimum> frequency_minima(const MinimumRefinement& refinement) {
  std::vector<FrequencyMinimum> minima(refinement.midpoints.size());
  for (std::size_t f = 0; f < minima.size(); ++f) minima[f].midpoints = refinement.midpoints[f];
  std::vector<bool> failed(minima.size(), false), capped(minima.size(), false);
  for (const MinimumSegment& s : refinement.segments) {
    if (s.is_open()) throw ContractViolation("frequency_minima: a segment is still open");
    const auto f = static_cast<std::size_t>(s.frequency_index);
    FrequencyMinimum& minimum = minima[f];
    failed[f] = failed[f] || s.state == code(SegmentState::failed);
    capped[f] = capped[f] || s.state == code(SegmentState::capped);
    if (s.below_grid()) {
      minimum.high = s.low;
      minimum.verdict_high = s.verdict_low;
      minimum.state = static_cast<std::int64_t>(MinimumState::below_grid);
    } else if (s.onset()) {
      minimum.amplitude_ratio = s.midpoint();
      minimum.low = s.low;
      minimum.high = s.high;
      minimum.verdict_high = s.verdict_high;
      minimum.state = static_cast<std::int64_t>(MinimumState::found);
    }
  }
  for (std::size_t f = 0; f < minima.size(); ++f) {
    if (minima[f].state == static_cast<std::int64_t>(MinimumState::below_grid)) continue;
    if (capped[f]) {
      minima[f].state = static_cast<std::int64_t>(MinimumState::capped);
    } else if (failed[f]) {
      minima[f].state = static_cast<std::int64_t>(MinimumState::failed);
    }
  }
  return minima;
}

}  // namespace blockfrag
