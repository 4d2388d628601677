// What a study keeps of one sample's simulation: a fixed-size record of 8-byte fields, so it
// travels between ranks and into checkpoints as plain bytes (all ranks of a job share one
// architecture) and its columns map one to one onto the output's /results datasets.
#pragma once

#include <cstdint>
#include <limits>
#include <type_traits>

#include "engine/summary.hpp"

namespace blockfrag {

// Values of the status column. Failed and rejected samples are excluded from fragility trials.
enum class SampleStatus : std::int64_t {
  ok = 0,
  failed = 1,    // the engine gave up (Summary::status failed: a budget exceeded)
  rejected = 2,  // the engine refused the sampled scene as invalid (InvalidInput)
};

struct SampleRecord {
  std::int64_t index = -1;
  std::int64_t status = static_cast<std::int64_t>(SampleStatus::ok);
  std::int64_t overturned = 0;
  std::int64_t impacts = 0;
  std::int64_t steps = 0;
  std::int64_t rhs_evaluations = 0;
  double max_abs_theta = 0.0;
  double final_theta = 0.0;
  double final_slide = 0.0;
  double max_abs_slide = 0.0;
  double overturn_time = std::numeric_limits<double>::quiet_NaN();  // NaN when it did not overturn
  std::int64_t settled = 0;  // the block's fate was final at the end (engine/summary.hpp)
  double settle_time = std::numeric_limits<double>::quiet_NaN();  // NaN when not settled
  std::int64_t fell = 0;  // went off a seat's end (never on the flat ground)
  double fell_time = std::numeric_limits<double>::quiet_NaN();  // NaN when it did not fall
  // With a reservoir, the smaller of the post-earthquake sliding and overturning safety factors
  // (engine/summary.hpp; +inf when nothing drives it); NaN without a reservoir or when the block
  // does not stand at rest at the end.
  double post_earthquake_safety_factor = std::numeric_limits<double>::quiet_NaN();
};
static_assert(std::is_trivially_copyable_v<SampleRecord>);
static_assert(sizeof(SampleRecord) == 16 * 8, "records travel as raw bytes: no padding allowed");

SampleRecord make_record(std::int64_t index, const Summary& summary);
SampleRecord make_rejected_record(std::int64_t index);

}  // namespace blockfrag
