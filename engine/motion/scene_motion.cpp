#include "engine/motion/scene_motion.hpp"

#include <algorithm>

#include "engine/motion/dam_crest.hpp"
#include "engine/tolerances.hpp"

namespace blockfrag {

namespace {

// Every sample of a record is a piece boundary, and the fixed-step rk4 cuts its step at each one:
// a record whose step does not fit the solver's would make rk4 take a short step per sample (and so
// not be the method it claims to be). Such a record is resampled, linearly, onto the dt grid; the
// adaptive methods take the record as it is.
GroundMotion fitted_to_solver(const GroundMotion& motion, const SolverSettings& solver) {
  const auto* recorded = std::get_if<RecordedMotion>(&motion);
  if (!recorded || solver.method != Method::rk4 || on_step_grid(*recorded->record, solver.dt))
    return motion;
  RecordedMotion resampled = *recorded;
  resampled.record = std::make_shared<const Accelerogram>(resample(*recorded->record, solver.dt));
  return resampled;
}

// Read as lambda_v, the ground's upward acceleration over g. Pulses given by their lambda are that
// as they are; a record's a(t) and a velocity pulse's dv/dt are the ground's acceleration, which
// the horizontal reading turns into lambda = -a/g and the vertical one must keep as +a/g.
GroundMotion upward(GroundMotion motion) {
  if (auto* recorded = std::get_if<RecordedMotion>(&motion)) recorded->scale = -recorded->scale;
  if (auto* pulse = std::get_if<MavroeidisPapageorgiouPulse>(&motion)) {
    pulse->velocity_amplitude = -pulse->velocity_amplitude;
  }
  return motion;
}

// How far the crest is followed: the scene's duration, or a settling run's cap.
double crest_horizon(const Scene& scene, const GroundMotionPieces& foundation) {
  if (scene.duration) return *scene.duration;
  return scene.max_duration.value_or(foundation.end_of_motion() + kSettleAllowance);
}

}  // namespace

GroundMotionPieces scene_motion(const Scene& scene) {
  GroundMotionPieces foundation(fitted_to_solver(scene.ground_motion, scene.solver), scene.g);
  if (!scene.dam) return foundation;
  // Settling: the crest is followed until its ringing dies out, within the run's cap.
  return dam_crest_motion(foundation, *scene.dam, crest_horizon(scene, foundation), scene.g,
                          !scene.duration);
}

CrestExtent scene_crest_extent(const Scene& scene) {
  if (!scene.dam) return {};
  const GroundMotionPieces foundation(fitted_to_solver(scene.ground_motion, scene.solver), scene.g);
  const double horizon = crest_horizon(scene, foundation);
  return {dam_crest_nodes(foundation, dam_mode(*scene.dam).period, horizon), horizon};
}

double run_end_time(const Scene& scene, const GroundMotionPieces& motion,
                    const GroundMotionPieces& vertical) {
  if (scene.duration) return *scene.duration;
  if (scene.max_duration) return *scene.max_duration;
  return std::max(motion.end_of_motion(), vertical.end_of_motion()) + kSettleAllowance;
}

GroundMotionPieces scene_vertical_motion(const Scene& scene) {
  return GroundMotionPieces(upward(fitted_to_solver(scene.vertical_motion, scene.solver)), scene.g);
}

}  // namespace blockfrag
