// One study sample from its index to its record: the pure function every rank, every schedule and
// every restart computes the same way.
#pragma once

#include <cstdint>
#include <functional>

#include "engine/scene/scene.hpp"
#include "engine/summary.hpp"
#include "mpi_driver/study/study_record.hpp"
#include "mpi_driver/study/study_sample.hpp"

namespace blockfrag {

// The evaluation of one scene: blockfrag::simulate in production, a stand-in in tests.
using SceneEvaluator = std::function<Summary(const Scene&)>;

// The record of `scene` under this index: evaluated, or a rejected record when the engine refuses
// the scene (InvalidInput). A simulation failure is the record's status "failed"; a broken
// contract (ContractViolation) propagates.
SampleRecord evaluate_scene_record(std::int64_t index, const Scene& scene,
                                   const SceneEvaluator& evaluate);

// The record of sample `index` (pure): its scene evaluated, or a rejected record when the engine
// refuses the scene (InvalidInput). A simulation failure is the record's status "failed"; a broken
// contract (ContractViolation) propagates: it is a bug, and the study stops.
SampleRecord evaluate_sample(StudySampler& sampler, std::int64_t index,
                             const SceneEvaluator& evaluate);

}  // namespace blockfrag
