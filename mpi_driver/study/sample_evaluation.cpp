#include "mpi_driver/study/sample_evaluation.hpp"

#include "engine/errors.hpp"

namespace blockfrag {

SampleRecord evaluate_scene_record(std::int64_t index, const Scene& scene,
                                   const SceneEvaluator& evaluate) {
  try {
    return make_record(index, evaluate(scene));
  } catch (const InvalidInput&) {
    return make_rejected_record(index);
  }
}

SampleRecord evaluate_sample(StudySampler& sampler, std::int64_t index,
                             const SceneEvaluator& evaluate) {
  return evaluate_scene_record(index, sampler.draw(index).scene, evaluate);
}

}  // namespace blockfrag
