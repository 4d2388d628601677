// A study's fragility gathered one sample at a time, as the output streams the records from disk:
// stripes keep per-level counts only (per cell for a surface: its curves in the first measure sum
// each level's cells over the second measure); a cloud keeps each successful sample's intensity and
// verdicts (9 bytes per sample and limit state at most), which its per-sample fit needs.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "mpi_driver/config/study_config.hpp"
#include "mpi_driver/study/study_record.hpp"
#include "postproc/fragility/fragility_curve.hpp"
#include "postproc/fragility/nested_fit.hpp"
#include "postproc/fragility/surface_grid.hpp"

namespace blockfrag {

struct StudyFragility {
  std::vector<FragilityCurve> curves;  // curves[k] is config.limit_states[k]'s
  std::vector<std::size_t> severity;   // limit state indices, least severe first
  // Pairs (i < j) of limit states whose fitted curves cross between the smallest and the largest
  // intensity of the study: they cannot be damage states of one component.
  std::vector<std::pair<std::size_t, std::size_t>> crossings;
  // surfaces[k] is config.limit_states[k]'s; none unless the study has a second measure.
  std::vector<SurfaceGrid> surfaces;
  // The fitted limit states fitted again with one common beta (postproc/fragility/nested_fit.hpp):
  // nested.median[i] is limit state nested_states[i]'s. Stripes only: a cloud's status says so.
  NestedFit nested;
  std::vector<std::size_t> nested_states;
};

class FragilityTally {
 public:
  explicit FragilityTally(const StudyConfig& config);
  // Sample record.index's record, its block's alpha = atan(a / b) and its intensity.
  void add(const SampleRecord& record, double alpha, double im);
  // The curves (with their bootstrap), their order of severity and their crossings.
  StudyFragility finish() const;

 private:
  const StudyConfig& config_;
  std::vector<std::vector<std::int64_t>> trials_, exceedances_;  // [limit state][level or cell]
  std::vector<double> cloud_im_;
  std::vector<std::vector<bool>> cloud_exceeded_;  // [limit state][successful sample]
  double im_low_, im_high_;
};

}  // namespace blockfrag
