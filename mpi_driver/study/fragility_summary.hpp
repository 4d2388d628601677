// The lines a run prints about its fragility: each limit state's fit and its uncertainty, and
// warnings for rejected fits and crossing curves.
#pragma once

#include <ostream>

#include "mpi_driver/config/study_config.hpp"
#include "mpi_driver/study/fragility_tally.hpp"

namespace blockfrag {

// One line per limit state: median and beta with their 95 % intervals, the goodness of fit; then a
// warning for each rejected fit (p < 0.05); a surface study's fitted surfaces in their median
// form; a warning for each crossing pair.
void print_fragility_summary(std::ostream& out, const StudyConfig& config,
                             const StudyFragility& fragility);

}  // namespace blockfrag
