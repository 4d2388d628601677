#include "mpi_driver/config/scene_fields.hpp"

#include "mpi_driver/config/study_fields.hpp"

namespace blockfrag {

std::vector<KeyTable> scene_key_tables() {
  return {{"block.", describe_fields<RectangularBlock>(scene_fields::rectangle)},
          {"block.", describe_fields<PolygonBlock>(scene_fields::polygon_block)},
          {"contact.", describe_fields<Contact>(scene_fields::contact)},
          {"", describe_fields<Scene>(scene_fields::run)},
          {"initial.", describe_fields<InitialState>(scene_fields::initial)},
          {"solver.", describe_fields<SolverSettings>(scene_fields::solver_method)},
          {"solver.", describe_fields<SolverSettings>(scene_fields::rk4_step)},
          {"solver.", describe_fields<SolverSettings>(scene_fields::step_control)},
          {"solver.", describe_fields<SolverSettings>(scene_fields::budgets)},
          {"dam.", describe_fields<DamPeriod>(scene_fields::dam_period)},
          {"dam.", describe_fields<DamSize>(scene_fields::dam_size)},
          {"dam.", describe_fields<DamCrest>(scene_fields::dam)},
          {"reservoir.", describe_fields<Reservoir>(scene_fields::reservoir)},
          {"", describe_alternatives<GroundMotion, MotionKeys>()},
          {"", describe_fields<RecordTarget>(scene_fields::record_target)},
          {"", describe_fields<StudyConfig>(study_fields::run)}};
}

}  // namespace blockfrag
