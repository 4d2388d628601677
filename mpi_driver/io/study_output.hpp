// The study's HDF5 output, written by rank 0 once every sample is done, through a fresh temporary
// file, fsync, rename and fsync of the folder (atomic_file.hpp: a finished file is never modified
// in place). Layout:
//
//   /                 attributes: config (canonical JSON), config_hash (16 hex digits, FNV-1a 64
//                     of the canonical config without output, checkpoint_interval_s and
//                     allowed_failed_fraction),
//                     blockfrag_version, total_samples, samples_per_level, design
//   /samples/<input>  float64[total]: one column per input of the config (direction as +1/-1)
//   /samples/level    int64[total]: intensity level index, i / samples_per_level
//   /samples/im       float64[total]: the level's pulse amplitude (g, positive)
//   /results/status   int64[total]: 0 ok, 1 failed (engine budget), 2 rejected (invalid scene)
//   /results/overturned, impacts, steps, rhs_evaluations           int64[total]
//   /results/max_abs_theta, final_theta, final_slide, max_abs_slide float64[total] (rad, m)
//   /results/overturn_time                                          float64[total], NaN when none
//   /results/settled                                                int64[total]: 1 the fate is
//   final /results/settle_time                                            float64[total], NaN when
//   not settled /fragility        attributes: im_name, im_units, trials_exclude /fragility/<name>
//   datasets im, trials, exceedances, probability, ci_low, ci_high (one entry per
//                     level); attributes type, threshold, interval, median, beta, log_likelihood
//                     (NaN when the fit does not exist), fit_status ("ok" or why there is no fit),
//                     median_low/median_high (where the data place the median)
// Everything in /samples, /results and /fragility depends only on the config.
#pragma once

#include <filesystem>
#include <vector>

#include "mpi_driver/config/study_config.hpp"
#include "mpi_driver/study/study_record.hpp"

namespace blockfrag {

// records[i] is sample i's record, for every sample.
void write_study_output(const std::filesystem::path& path, const StudyConfig& config,
                        const std::vector<SampleRecord>& records);

// The config_hash attribute of an existing output, or an empty string when path is not a readable
// blockfrag output.
std::string output_config_hash(const std::filesystem::path& path);

}  // namespace blockfrag
