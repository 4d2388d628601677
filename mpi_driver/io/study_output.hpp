// The study's HDF5 output, written by rank 0 once every sample is done, through a fresh temporary
// file, fsync, rename and fsync of the folder (atomic_file.hpp: a finished file is never modified
// in place). docs/studies.md documents every group, dataset and attribute; in short:
//
//   /            attributes config (canonical JSON), config_hash, blockfrag_version,
//                total_samples, samples_per_level, design
//   /samples     one float64 column per input, and level, im, scale, pga_g, pgv_m_s (record when
//                the motion is a record suite): what each sample was
//   /records     a record suite's records: file, vertical, weight, pga_g, pgv_m_s, duration_s
//                (sa_g with an Sa measure)
//   /results     status, overturned, impacts, steps, rhs_evaluations, max_abs_theta, final_theta,
//                final_slide, max_abs_slide, overturn_time, settled, settle_time, fell,
//                fell_time, and with a reservoir post_earthquake_safety_factor: what it did
//   /fragility   attributes of the measure, severity_order and crossing_pairs; one group per
//                limit state with its points (im, trials, exceedances, probability, ci_low,
//                ci_high), its fit and the fit's diagnostics as attributes, and the bootstrap's
//                band (band_im, band_low, band_high)
//
// Everything in /samples, /records, /results and /fragility depends only on the config.
#pragma once

#include <filesystem>
#include <vector>

#include "mpi_driver/config/study_config.hpp"
#include "mpi_driver/io/record_spool.hpp"
#include "mpi_driver/study/adaptive_levels.hpp"
#include "mpi_driver/study/failure_report.hpp"
#include "mpi_driver/study/fragility_tally.hpp"

namespace blockfrag {

// What the output's pass over the records gathered on the way.
struct StudyTallies {
  StudyFragility fragility;
  FailureTally failures;
};

// The spool holds every sample's record. One pass over it, a block of samples at a time: rank 0's
// memory does not grow with the study's size (but for a cloud's fit: fragility_tally.hpp).
// An adaptive study also writes its batches (`adaptive`, /adaptive).
StudyTallies write_study_output(const std::filesystem::path& path, const StudyConfig& config,
                                const RecordSpool& spool,
                                const AdaptiveHistory* adaptive = nullptr);

// The config_hash attribute of an existing output, or an empty string when path is not a readable
// blockfrag output.
std::string output_config_hash(const std::filesystem::path& path);

}  // namespace blockfrag
