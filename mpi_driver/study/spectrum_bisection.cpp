#include "mpi_driver/study/spectrum_bisection.hpp"

#include "engine/errors.hpp"

namespace blockfrag {
namespace {

bool within_tolerance(const SpectrumBracket& bracket, double tolerance) {
  return bracket.high - bracket.low <= tolerance * bracket.high;
}

}  // namespace

SpectrumVerdict spectrum_verdict(const SampleRecord& record) {
  if (record.status == static_cast<std::int64_t>(SampleStatus::failed))
    return SpectrumVerdict::failed;
  if (record.status == static_cast<std::int64_t>(SampleStatus::rejected))
    return SpectrumVerdict::rejected;
  if (record.overturned) {
    if (record.impacts == 0) return SpectrumVerdict::overturns_no_impact;
    return record.impacts == 1 ? SpectrumVerdict::overturns_one_impact
                               : SpectrumVerdict::overturns_more_impacts;
  }
  return record.settled ? SpectrumVerdict::stands : SpectrumVerdict::still_moving;
}

SampleRecord evaluate_spectrum_point(const SpectrumConfig& config, double frequency_ratio,
                                     double amplitude_ratio, std::int64_t index,
                                     const SceneEvaluator& evaluate) {
  return evaluate_scene_record(index, spectrum_scene(config, frequency_ratio, amplitude_ratio),
                               evaluate);
}

std::vector<SpectrumBracket> column_brackets(std::int64_t frequency_index,
                                             std::span<const double> amplitude_ratio,
                                             std::span<const SpectrumVerdict> verdicts,
                                             double tolerance) {
  if (amplitude_ratio.size() != verdicts.size())
    throw ContractViolation("column_brackets: one verdict per amplitude ratio");
  std::vector<SpectrumBracket> brackets;
  for (std::size_t j = 1; j < verdicts.size(); ++j) {
    const SpectrumVerdict below = verdicts[j - 1], above = verdicts[j];
    if (!decided(below) || !decided(above) || overturned(below) == overturned(above)) continue;
    SpectrumBracket bracket;
    bracket.frequency_index = frequency_index;
    bracket.low = amplitude_ratio[j - 1];
    bracket.high = amplitude_ratio[j];
    bracket.verdict_low = static_cast<std::int64_t>(below);
    bracket.verdict_high = static_cast<std::int64_t>(above);
    if (within_tolerance(bracket, tolerance))
      bracket.state = static_cast<std::int64_t>(BracketState::converged);
    brackets.push_back(bracket);
  }
  return brackets;
}

void narrow(SpectrumBracket& bracket, SpectrumVerdict at_midpoint, double tolerance,
            int max_iterations) {
  if (!bracket.is_open()) throw ContractViolation("narrow: the bracket is not open");
  ++bracket.iterations;
  if (!decided(at_midpoint)) {
    bracket.state = static_cast<std::int64_t>(BracketState::failed);
    return;
  }
  const double middle = bracket.midpoint();
  const bool low_overturned = overturned(static_cast<SpectrumVerdict>(bracket.verdict_low));
  if (overturned(at_midpoint) == low_overturned) {
    bracket.low = middle;
    bracket.verdict_low = static_cast<std::int64_t>(at_midpoint);
  } else {
    bracket.high = middle;
    bracket.verdict_high = static_cast<std::int64_t>(at_midpoint);
  }
  if (within_tolerance(bracket, tolerance)) {
    bracket.state = static_cast<std::int64_t>(BracketState::converged);
  } else if (bracket.iterations >= max_iterations) {
    bracket.state = static_cast<std::int64_t>(BracketState::capped);
  }
}

}  // namespace blockfrag
