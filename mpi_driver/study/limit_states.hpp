// A limit state's fragility from a study's records: per intensity level the trials (samples whose
// simulation succeeded: failed and rejected ones are excluded) and the exceedances, from which
// postproc/fragility builds the curve and its fit.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "mpi_driver/config/study_config.hpp"
#include "mpi_driver/study/study_record.hpp"
#include "postproc/fragility/fragility_curve.hpp"

namespace blockfrag {

// Whether one successful sample exceeds the limit state; alpha = atan(a / b) of its block. A
// block lost from its seat, overturned or fallen off the seat's end, exceeds the overturning state
// and every other (it lies on its side or below the crest: past any rotation, and its slide is no
// longer a sliding block's), unless the state counts only its raw measure (overturned_exceeds
// false).
bool exceeds(const LimitState& state, const SampleRecord& record, double alpha);

// The bootstrap's uniforms: a Philox stream of the study's seed named after the limit state, so
// the intervals are a pure function of the config, whatever ran the study (and `blockfrag risk`
// draws the same resamples again from the output's counts).
UniformDraw bootstrap_uniforms(std::uint64_t seed, const std::string& limit_state);

// The curve of per-level counts (stripes), with its bootstrap.
FragilityCurve stripe_curve(const StudyConfig& config, const LimitState& state,
                            std::vector<std::int64_t> trials,
                            std::vector<std::int64_t> exceedances);
// The curve of a cloud's successful samples, each at its own intensity, with its bootstrap.
FragilityCurve cloud_curve(const StudyConfig& config, const LimitState& state,
                           const std::vector<double>& im, const std::vector<bool>& exceeded);

// records[i], alphas[i] and ims[i] belong to sample i (all samples of the study). Stripes count
// trials and exceedances per level (a surface per level of its first measure, over every
// period); a cloud fits each sample at its own intensity
// (postproc/fragility/cloud_fragility.hpp).
FragilityCurve fragility_curve(const StudyConfig& config, const LimitState& state,
                               const std::vector<SampleRecord>& records,
                               const std::vector<double>& alphas,
                               const std::vector<double>& ims = {});

}  // namespace blockfrag
