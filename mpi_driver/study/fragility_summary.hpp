// A study's fragility as a whole: every limit state's curve, their order of severity and the pairs
// whose fitted curves cross inside the studied range, and the lines a run prints about them.
#pragma once

#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "mpi_driver/config/study_config.hpp"
#include "mpi_driver/study/study_record.hpp"
#include "postproc/fragility/fragility_curve.hpp"

namespace blockfrag {

struct StudyFragility {
  std::vector<FragilityCurve> curves;  // curves[k] is config.limit_states[k]'s
  std::vector<std::size_t> severity;   // limit state indices, least severe first
  // Pairs (i < j) of limit states whose fitted curves cross between the smallest and the largest
  // intensity of the study: they cannot be damage states of one component.
  std::vector<std::pair<std::size_t, std::size_t>> crossings;
};

// ims[i] is sample i's intensity and alphas[i] its block's atan(a / b), for every sample.
StudyFragility study_fragility(const StudyConfig& config, const std::vector<SampleRecord>& records,
                               const std::vector<double>& alphas, const std::vector<double>& ims);

// One line per limit state: median and beta with their 95 % intervals, the goodness of fit; then a
// warning for each rejected fit (p < 0.05) and each crossing pair.
void print_fragility_summary(std::ostream& out, const StudyConfig& config,
                             const StudyFragility& fragility);

}  // namespace blockfrag
