// The work-precision study's results: an HDF5 file for plots and a markdown table for people.
//
// HDF5 layout (h5py: f["summary/median_seconds"][...], f["summary"].attrs["labels"].split("\n")):
//   /                  attrs reference_method, reference_tolerance, check_method,
//   min_batch_seconds,
//                      scene_count, setting_count, suite (the suite file's name)
//   /scenes            attrs names, categories (newline-separated); columns, one row per scene:
//                      reference_{max_abs_theta,final_theta,final_slide,first_impact_time (NaN:
//                      none)}, reference_overturned, reference_impacts,
//                      check_error_{max_abs_theta,final_theta, final_slide,first_impact_time},
//                      check_wrong_verdict
//   /settings/NN       one group per setting, in study order; attrs label, method, parameter;
//   columns,
//                      one row per scene: error_{max_abs_theta,final_theta,final_slide,
//                      first_impact_time} (inf: failed, or an impact only one run has),
//                      wrong_verdict, failed, seconds_per_run, repeats, steps, rhs_evaluations
//   /summary           attrs labels, methods (newline-separated, one per setting); columns, one row
//                      per setting: parameter, max_error_* and median_error_* of the four outputs,
//                      scenes_over_target (error in max |theta| > 1e-6 rad), wrong_verdicts,
//                      wrong_verdict_rate, failures, median_seconds, p95_seconds,
//                      median_rhs_evaluations, mean_rhs_evaluations, median_steps
#pragma once

#include <filesystem>
#include <ostream>
#include <string>

#include "mpi_driver/accuracy/accuracy_study.hpp"

namespace blockfrag {

// Written to PATH.tmp and renamed over path (a killed run leaves no half-written file).
void write_accuracy_hdf5(const std::filesystem::path& path, const AccuracyStudy& study,
                         const std::string& suite_name);

// Markdown tables: the reference check, then one row per setting (errors are the maxima over the
// suite; times and RHS evaluations per scene).
void write_accuracy_table(std::ostream& out, const AccuracyStudy& study);

}  // namespace blockfrag
