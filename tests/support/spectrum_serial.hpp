// An overturning spectrum computed in one process, without MPI or files: the map point by point,
// then each bracket bisected to its end. Each bracket's midpoints depend only on the config, so
// this gives the brackets `blockfrag spectrum` gives on any number of ranks; the physics tests use
// it.
#pragma once

#include <cstdint>
#include <vector>

#include "engine/simulate.hpp"
#include "mpi_driver/config/spectrum_config.hpp"
#include "mpi_driver/study/spectrum_bisection.hpp"

namespace blockfrag::testing {

struct SerialSpectrum {
  std::vector<SpectrumVerdict> map;       // [frequency index][amplitude index], row by row
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
      column.push_back(spectrum_verdict(
          evaluate_spectrum_point(config, config.frequency_ratio[i], a, index++, engine)));
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

}  // namespace blockfrag::testing
