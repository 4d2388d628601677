// The scale a study's stripes need: each record's measures and the largest level a stripe may
// ask of a record or a pulse. Fixed levels past it are refused; an adaptive study's batches stop
// there.
#pragma once

#include <string>

#include "mpi_driver/config/config_reader.hpp"
#include "mpi_driver/config/study_config.hpp"

namespace blockfrag {

// A record is scaled by at most this much to reach a stripe: beyond, the motion is no longer the
// record's character at another intensity but a different earthquake.
inline constexpr double kMaxRecordScale = 100.0;

// Every record's measures (as recorded) into the suite; stripes must reach every level with a scale
// of at most kMaxRecordScale, and a record whose measure is 0 cannot be scaled at all: each refusal
// goes to errors at the record's path (/scene/ground_motion/file for a single record).
void measure_suite(StudyConfig& config, ConfigErrors& errors, bool single_record);

// The largest level a stripe of the study may have, and what sets it: the measure's own largest
// (intensity_measure.hpp); with records, the level the record of the smallest measure reaches
// with the largest scale a record may have (fixed levels past it are refused); with a pulse, the
// level it reaches at the end of its amplitude's domain (samples past it are refused, status 2),
// unless a sampled period makes that differ between samples. An adaptive study's batches stop
// there.
struct StripeCap {
  double level;
  std::string reason;  // "the measure's largest level", or the level and what reaches it there
};
StripeCap stripe_cap(const StudyConfig& config);

}  // namespace blockfrag
