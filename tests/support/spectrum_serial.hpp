// An overturning spectrum computed in one process, without MPI or files: the map point by point,
// then each bracket bisected to its end, and on demand the minimum refinement's rounds. Each
// bracket's and segment's midpoints depend only on the config, so this gives the brackets and
// minima `blockfrag spectrum` gives on any number of ranks; the physics tests use it.
#pragma once

#include <cstdint>
#include <vector>

#include "engine/simulate.hpp"
#include "mpi_driver/config/spectrum_config.hpp"
#include "mpi_driver/study/minimum_overturning.hpp"
#include "mpi_driver/study/spectrum_bisection.hpp"

namespace blockfrag::testing {

struct SerialSpectrum {
  std::vector<SpectrumVerdict> map;       // [frequency index][amplitude index], row by row
  std::vector<MinimumPoint> points;       // the same points, as the minimum's refinement sees them
  std::vector<SpectrumBracket> brackets;  // in order of frequency, then amplitude

  SpectrumVerdict at(const SpectrumConfig& config, std::size_t i, std::size_t j) const {
    return map[i * config.amplitude_ratio.size() + j];
  }
};

inline SerialSpectrum serial_spectrum(const SpectrumConfig& config) {
  const SceneEvaluator engine = [](const Scene& scene) { return simulate(scene); };
  SerialSpectrum out;
  std::int64_t index = 0;
  for (std::size_t i = 0; i < config.frequency_ratio.size(); ++i) {
    std::vector<SpectrumVerdict> column;
    for (const double a : config.amplitude_ratio) {
      const SampleRecord record =
          evaluate_spectrum_point(config, config.frequency_ratio[i], a, index++, engine);
      column.push_back(spectrum_verdict(record));
      out.points.push_back(minimum_point(record, config.alpha()));
    }
    out.map.insert(out.map.end(), column.begin(), column.end());
    for (SpectrumBracket bracket :
         column_brackets(static_cast<std::int64_t>(i), config.amplitude_ratio, column,
                         config.bisection_tolerance)) {
      while (bracket.is_open()) {
        const SampleRecord record = evaluate_spectrum_point(config, config.frequency_ratio[i],
                                                            bracket.midpoint(), 0, engine);
        narrow(bracket, spectrum_verdict(record), config.bisection_tolerance,
               config.max_iterations);
      }
      out.brackets.push_back(bracket);
    }
  }
  return out;
}

// Every frequency's minimum overturning amplitude, refined from the spectrum's map and brackets.
inline std::vector<FrequencyMinimum> serial_minima(const SpectrumConfig& config,
                                                   const SerialSpectrum& spectrum) {
  const SceneEvaluator engine = [](const Scene& scene) { return simulate(scene); };
  const std::size_t na = config.amplitude_ratio.size();
  std::vector<MinimumSegment> segments;
  auto bracket = spectrum.brackets.begin();
  for (std::size_t i = 0; i < config.frequency_ratio.size(); ++i) {
    const auto first = bracket;
    while (bracket != spectrum.brackets.end() &&
           bracket->frequency_index == static_cast<std::int64_t>(i)) {
      ++bracket;
    }
    const auto found = column_segments(
        static_cast<std::int64_t>(i), config.amplitude_ratio,
        std::span<const MinimumPoint>(spectrum.points).subspan(i * na, na),
        std::span<const SpectrumBracket>(first, bracket), config.minimum_overturning);
    segments.insert(segments.end(), found.begin(), found.end());
  }
  MinimumRefinement refinement = start_minimum_refinement(
      config.hash, static_cast<std::int64_t>(config.frequency_ratio.size()), std::move(segments),
      config.minimum_overturning);
  for (;;) {
    std::vector<MinimumPoint> points;
    for (const MinimumSegment& s : refinement.segments) {
      if (!s.is_open()) continue;
      points.push_back(minimum_point(
          evaluate_spectrum_point(
              config, config.frequency_ratio[static_cast<std::size_t>(s.frequency_index)],
              s.midpoint(), 0, engine),
          config.alpha()));
    }
    if (points.empty()) return frequency_minima(refinement);
    refine_minimum(refinement, points, config.minimum_overturning);
  }
}

}  // namespace blockfrag::testing
