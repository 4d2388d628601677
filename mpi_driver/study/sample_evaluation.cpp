#include "mpi_driver/study/sample_evaluation.hpp"

#include <stdexcept>

namespace blockfrag {

SampleRecord evaluate_sample(StudySampler& sampler, std::int64_t index, const SceneEvaluator& evaluate) {
  const StudySample sample = sampler.draw(index);
  try {
    return make_record(index, evaluate(sample.scene));
  } catch (const std::invalid_argument&) {
    return make_rejected_record(index);
  }
}

}  // namespace blockfrag
