// The key tables (mpi_driver/config/field_table.hpp) of a study's and a spectrum's own settings.
#pragma once

#include "engine/scene/parameter_domains.hpp"
#include "mpi_driver/config/field_table.hpp"
#include "mpi_driver/config/minimum_overturning_json.hpp"
#include "mpi_driver/config/study_config.hpp"

namespace blockfrag::study_fields {

// What changes no sample's result (output, checkpoints, the failures allowed) is not hashed: the
// study's reader takes those keys out of the hashed form.
inline constexpr Field<StudyConfig> run[] = {
    {"checkpoint_interval_s", &StudyConfig::checkpoint_interval_s, &domain::checkpoint_interval_s},
    {"allowed_failed_fraction", &StudyConfig::allowed_failed_fraction,
     &domain::allowed_failed_fraction},
    {"bootstrap_resamples", &StudyConfig::bootstrap_resamples, &domain::bootstrap_resamples}};

inline constexpr Field<MinimumOverturningSettings> minimum_overturning[] = {
    {"tolerance", &MinimumOverturningSettings::tolerance, &domain::minimum_tolerance},
    {"resolution", &MinimumOverturningSettings::resolution, &domain::minimum_resolution},
    {"near_overturning", &MinimumOverturningSettings::near_overturning, &domain::near_overturning},
    {"max_midpoints", &MinimumOverturningSettings::max_midpoints, &domain::minimum_midpoints}};

}  // namespace blockfrag::study_fields
