// An overturning spectrum's points and boundaries, without MPI or files: the verdict of a point's
// record, the brackets the map's columns give (every change of "overturned" between neighbouring
// amplitudes along one frequency), and one bisection step of a bracket. The runner
// (mpi_driver/parallel/spectrum_runner.hpp) evaluates the midpoints of all open brackets of a round
// in parallel; every bracket's sequence of midpoints depends only on the config, so the boundaries
// are the same for any number of ranks and any restart.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "mpi_driver/config/spectrum_config.hpp"
#include "mpi_driver/study/sample_evaluation.hpp"
#include "mpi_driver/study/study_record.hpp"

namespace blockfrag {

// The verdict of a point's record (mpi_driver/config/spectrum_config.hpp has the codes).
SpectrumVerdict spectrum_verdict(const SampleRecord& record);

// The record of the point (frequency_ratio, amplitude_ratio), with the given index: its scene
// simulated by `evaluate`, rejected when the engine refuses it (InvalidInput).
SampleRecord evaluate_spectrum_point(const SpectrumConfig& config, double frequency_ratio,
                                     double amplitude_ratio, std::int64_t index,
                                     const SceneEvaluator& evaluate);

enum class BracketState : std::int64_t {
  open = 0,       // wider than the tolerance: its midpoint is evaluated next round
  converged = 1,  // high - low <= tolerance * high
  failed = 2,     // a midpoint's scene failed (or was refused): the bracket stays as it was
  capped = 3,     // max_iterations midpoints and still wider than the tolerance
};

// One crossing of the boundary along a frequency: the verdict is overturned at one end and not at
// the other. direction +1: the onset of overturning (stands below, overturns above); -1: the end of
// an overturning band (overturns below, stands above: the lower edge of a safe island).
struct SpectrumBracket {
  std::int64_t frequency_index = 0;
  double low = 0.0, high = 0.0;  // amplitude ratios
  std::int64_t verdict_low = 0, verdict_high = 0;
  std::int64_t iterations = 0;  // midpoints evaluated
  std::int64_t state = static_cast<std::int64_t>(BracketState::open);

  int direction() const { return overturned(static_cast<SpectrumVerdict>(verdict_high)) ? +1 : -1; }
  double midpoint() const { return 0.5 * (low + high); }
  bool is_open() const { return state == static_cast<std::int64_t>(BracketState::open); }
};
static_assert(sizeof(SpectrumBracket) == 7 * 8,
              "brackets are stored as raw bytes: no padding allowed");

// The brackets of one frequency's column of verdicts (one per amplitude ratio, increasing): every
// pair of neighbours both decided (not failed) whose "overturned" differs, in increasing amplitude.
// Each starts open, or converged when it is already within the tolerance.
std::vector<SpectrumBracket> column_brackets(std::int64_t frequency_index,
                                             std::span<const double> amplitude_ratio,
                                             std::span<const SpectrumVerdict> verdicts,
                                             double tolerance);

// Narrows an open bracket with the verdict at its midpoint: the half whose ends still disagree,
// then converged or capped; a failed midpoint leaves it failed.
void narrow(SpectrumBracket& bracket, SpectrumVerdict at_midpoint, double tolerance,
            int max_iterations);

}  // namespace blockfrag
