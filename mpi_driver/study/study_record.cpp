#include "mpi_driver/study/study_record.hpp"

#include <algorithm>

namespace blockfrag {

SampleRecord make_record(std::int64_t index, const Summary& summary) {
  SampleRecord record;
  record.index = index;
  record.status = static_cast<std::int64_t>(summary.status == Status::ok ? SampleStatus::ok
                                                                         : SampleStatus::failed);
  record.overturned = summary.overturned ? 1 : 0;
  record.impacts = summary.impacts;
  record.steps = summary.steps;
  record.rhs_evaluations = summary.rhs_evaluations;
  record.max_abs_theta = summary.max_abs_theta;
  record.final_theta = summary.final_theta;
  record.final_slide = summary.final_slide;
  record.max_abs_slide = summary.max_abs_slide;
  if (summary.overturn_time) record.overturn_time = *summary.overturn_time;
  record.settled = summary.settled ? 1 : 0;
  if (summary.settle_time) record.settle_time = *summary.settle_time;
  record.fell = summary.fell ? 1 : 0;
  if (summary.fell_time) record.fell_time = *summary.fell_time;
  if (summary.post_earthquake && summary.post_earthquake->sliding_safety_factor) {
    record.post_earthquake_safety_factor =
        std::min(*summary.post_earthquake->sliding_safety_factor,
                 *summary.post_earthquake->overturning_safety_factor);
  }
  return record;
}

SampleRecord make_rejected_record(std::int64_t index) {
  SampleRecord record;
  record.index = index;
  record.status = static_cast<std::int64_t>(SampleStatus::rejected);
  return record;
}

}  // namespace blockfrag
