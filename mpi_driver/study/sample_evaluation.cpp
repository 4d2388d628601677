#include "mpi_driver/study/sample_evaluation.hpp"

#include "engine/errors.hpp"

namespace blockfrag {

SampleRecord evaluate_sample(StudySampler& sampler, std::int64_t index,
                             const SceneEvaluator& evaluate) {
  const StudySample sample = sampler.draw(index);
  try {
    return make_record(index, evaluate(sample.scene));
  } catch (const InvalidInput&) {
    return make_rejected_record(index);
  }
}

}  // namespace blockfrag
