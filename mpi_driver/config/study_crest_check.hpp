// A study on a dam crest whose every sample the engine would refuse for its crest history (a dam
// period far shorter than every sample's run, engine/motion/dam_crest.hpp): refused from the
// config, before any work, rather than run to a study of rejected samples.
#pragma once

#include "mpi_driver/config/config_reader.hpp"
#include "mpi_driver/config/study_config.hpp"

namespace blockfrag {

// Records at /scene/dam that no sample's crest history fits, when the samples' motions differ
// from the base scene's (a record suite's records, a drawn period's range, a surface's periods);
// the base scene's own motion is the scene reader's to check. For a config without other errors.
void check_study_crest(const StudyConfig& config, ConfigErrors& errors);

}  // namespace blockfrag
