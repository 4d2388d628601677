// The minimum overturning amplitude of each frequency of a spectrum, refined below what the map
// and its bisection find, without MPI or files. A block can overturn in bands of amplitude
// narrower than the map's step: the map steps over them, and its lowest onset is then too high.
// Approaching such a band from a standing amplitude, the response comes near overturning
// (max |theta| / alpha rises towards 1), so the refinement probes the intervals between two
// standing amplitudes where one end comes near (MinimumOverturningSettings::near_overturning):
// each such interval is halved, its halves probed again while they are near overturning and wider
// than the resolution. A probe that overturns is a lower minimum, bisected like the map's onset to
// the tolerance.
//
// Each frequency's segments partition the amplitudes explored below its lowest known overturning
// amplitude, in order: probes (neither end overturned), then the onset bracket (its upper end
// overturned), whose upper end is that lowest amplitude. Everything above it is dropped. The
// runner (mpi_driver/parallel/spectrum_runner.hpp) evaluates the midpoints of every open segment
// of a round in parallel; they depend only on the config, so the minima are the same on any
// number of ranks and after any restart.
#pragma once

#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "mpi_driver/config/spectrum_config.hpp"
#include "mpi_driver/study/spectrum_bisection.hpp"
#include "mpi_driver/study/study_record.hpp"

namespace blockfrag {

enum class SegmentState : std::int64_t {
  open = 0,    // its midpoint is evaluated next round
  closed = 1,  // an onset bracket within the tolerance, or the marker of a minimum below the grid
  failed = 2,  // a point of it failed (or was refused): not refined further
  capped = 3,  // the frequency's midpoints ran out (max_midpoints) while it was open
};

struct MinimumSegment {
  std::int64_t frequency_index = 0;
  double low = 0.0, high = 0.0;  // amplitude ratios
  std::int64_t verdict_low = 0, verdict_high = 0;
  // max |theta| / alpha at each end; NaN where it is not known (the ends of the map's bisected
  // onset bracket, which lie at an edge of overturning, where the response comes nearest).
  double near_low = 0.0, near_high = 0.0;
  std::int64_t state = static_cast<std::int64_t>(SegmentState::open);

  // Its upper end overturns: the bracket of the frequency's minimum.
  bool onset() const { return overturned(static_cast<SpectrumVerdict>(verdict_high)); }
  // Its lower end overturns: the marker of a frequency whose lowest map amplitude overturns.
  bool below_grid() const { return overturned(static_cast<SpectrumVerdict>(verdict_low)); }
  double midpoint() const { return 0.5 * (low + high); }
  bool is_open() const { return state == static_cast<std::int64_t>(SegmentState::open); }
};
static_assert(sizeof(MinimumSegment) == 8 * 8,
              "segments are stored as raw bytes: no padding allowed");

// The refinement between rounds: every frequency's segments, and the midpoints spent on each.
struct MinimumRefinement {
  std::uint64_t config_hash = 0;
  std::int64_t round = 0;                // the round about to run
  std::vector<std::int64_t> midpoints;   // per frequency
  std::vector<MinimumSegment> segments;  // by frequency, then amplitude
};

// What the refinement needs of an evaluated point.
struct MinimumPoint {
  SpectrumVerdict verdict = SpectrumVerdict::stands;
  double near = 0.0;  // max |theta| / alpha
};
MinimumPoint minimum_point(const SampleRecord& record, double alpha);

// The first segments of one frequency, from its map column (a point per amplitude ratio) and its
// crossings bisected to their end (column_brackets, then narrow): the probes between neighbouring
// standing amplitudes below the lowest overturning one, and the onset bracket, the map's lowest
// onset as bisected. A failed point below it leaves a failed segment; a column whose lowest
// amplitude overturns gets only the below-grid marker, and one that never overturns only probes.
std::vector<MinimumSegment> column_segments(std::int64_t frequency_index,
                                            std::span<const double> amplitude_ratio,
                                            std::span<const MinimumPoint> column,
                                            std::span<const SpectrumBracket> brackets,
                                            const MinimumOverturningSettings& settings);

// The refinement at its start: `segments` every frequency's column_segments, in order; the
// midpoints budget applied.
MinimumRefinement start_minimum_refinement(std::uint64_t config_hash, std::int64_t frequencies,
                                           std::vector<MinimumSegment> segments,
                                           const MinimumOverturningSettings& settings);

// One round's end: every open segment, in order, with the point at its midpoint: an onset is
// narrowed (a standing midpoint also leaves a probe below it), a probe is halved (one that
// overturns becomes the frequency's new onset bracket, and everything above it goes), a failed
// midpoint fails its segment. Halves that are not near overturning or within the tolerance end
// there. Then the budget: the open segments past a frequency's max_midpoints, or past
// kMaxSpectrumPoints midpoints over the whole spectrum, are capped.
void refine_minimum(MinimumRefinement& refinement, std::span<const MinimumPoint> at_midpoints,
                    const MinimumOverturningSettings& settings);

// Codes of /minimum_overturning/state.
enum class MinimumState : std::int64_t {
  found = 1,       // bracketed to the tolerance, every near-overturning interval below probed to
                   // the resolution
  none = 2,        // nothing overturned in the grid's range
  below_grid = 3,  // the map's lowest amplitude overturns: the minimum lies below the grid
  failed = 4,      // a point below the minimum failed: a lower one may hide there
  capped = 5,      // max_midpoints ran out first: a lower one may hide in what is left
};

// One frequency's minimum, from its final segments.
struct FrequencyMinimum {
  double amplitude_ratio = std::numeric_limits<double>::quiet_NaN();  // the bracket's midpoint
  double low = std::numeric_limits<double>::quiet_NaN();   // stands (or NaN below the grid)
  double high = std::numeric_limits<double>::quiet_NaN();  // overturns
  std::int64_t verdict_high = -1;                          // -1 when nothing overturned
  std::int64_t state = static_cast<std::int64_t>(MinimumState::none);
  std::int64_t midpoints = 0;
};

// Every frequency's minimum, once no segment is open.
std::vector<FrequencyMinimum> frequency_minima(const MinimumRefinement& refinement);

}  // namespace blockfrag
