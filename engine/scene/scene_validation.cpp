#include "engine/scene/scene_validation.hpp"

#include "engine/scene/block_geometry.hpp"
#include "engine/contact/model_choice.hpp"
#include "engine/scene/polygon_properties.hpp"

#include <cmath>
#include <numbers>
#include <string>
#include <type_traits>

#include "engine/errors.hpp"
#include "engine/tolerances.hpp"

namespace blockfrag {

namespace {

void require(bool ok, const char* rule) {
  if (!ok) throw InvalidInput(std::string("invalid scene: ") + rule);
}

bool positive(double v) { return std::isfinite(v) && v > 0; }

// The block's shape and mass, and an initial tilt that leaves it on one of its base corners.
void validate_block(const Scene& scene) {
  const double theta = scene.initial.theta;
  if (!scene.polygon) {
    require(positive(scene.block.half_width), "block half_width must be > 0");
    require(positive(scene.block.half_height), "block half_height must be > 0");
    require(positive(scene.block.mass), "block mass must be > 0");
    require(std::isfinite(theta) && std::abs(theta) < std::numbers::pi / 2,
            "initial theta must be within (-pi/2, pi/2)");
    return;
  }
  if (const auto defect = polygon_defect(scene.polygon->vertices)) {
    const std::string where =
        defect->vertex < 0 ? "" : " vertex " + std::to_string(defect->vertex) + ":";
    throw InvalidInput("invalid scene: block polygon:" + where + " " + defect->rule);
  }
  require(positive(scene.polygon->mass), "block mass must be > 0");
  const BlockGeometry geometry(*scene.polygon);
  require(std::isfinite(theta) && theta > -geometry.overturn_angle(Corner::right) &&
              theta < geometry.overturn_angle(Corner::left),
          "initial theta must be within the tilts that lay the polygon on the faces next to its "
          "base");
}

// The near-fault pulses (engine/motion/near_fault_pulses.hpp).
void require_valid(const MakrisPulseA& m) {
  require(std::isfinite(m.amplitude_g), "pulse amplitude must be finite");
  require(positive(m.period), "pulse period must be > 0");
}
void require_valid(const MakrisPulseB& m) { require_valid(MakrisPulseA{m.amplitude_g, m.period}); }
void require_valid(const MakrisPulseC& m) {
  require_valid(MakrisPulseA{m.amplitude_g, m.period});
  require(m.n >= 1, "Makris type C pulse n must be >= 1");
}
void require_valid(const RickerWavelet& m) {
  require_valid(MakrisPulseA{m.amplitude_g, m.period});
  require(!m.t0 || positive(*m.t0), "Ricker wavelet t0 must be > 0");
}
void require_valid(const MavroeidisPapageorgiouPulse& m) {
  require(std::isfinite(m.velocity_amplitude), "pulse velocity amplitude must be finite");
  require(positive(m.period), "pulse period must be > 0");
  require(std::isfinite(m.gamma) && m.gamma > 1, "Mavroeidis-Papageorgiou gamma must be > 1");
  require(std::isfinite(m.phase), "Mavroeidis-Papageorgiou phase must be finite");
  // The pulse must start at t >= 0: a block at rest on a ground already moving is another problem.
  require(!m.t0 || (std::isfinite(*m.t0) && *m.t0 >= (1.0 - kGridRounding) * m.half_width()),
          "Mavroeidis-Papageorgiou t0 must be >= gamma period / 2 (the pulse starts at t >= 0)");
}

void validate_dam(const DamCrest& dam) {
  if (const auto* given = std::get_if<DamPeriod>(&dam.stiffness)) {
    require(positive(given->period), "dam period must be > 0");
  } else {
    const auto& size = std::get<DamSize>(dam.stiffness);
    require(positive(size.height), "dam height must be > 0");
    require(positive(size.elastic_modulus), "dam elastic_modulus must be > 0");
  }
  // The filter is the underdamped oscillator's closed form.
  require(dam.damping >= 0 && dam.damping < 1, "dam damping must be in [0, 1)");
  require(positive(dam.participation), "dam participation must be > 0");
}

}  // namespace

void validate_scene(const Scene& scene) {
  validate_block(scene);
  require(std::isfinite(scene.contact.friction) && scene.contact.friction >= 0,
          "friction must be >= 0");
  require(scene.contact.restitution >= 0 && scene.contact.restitution <= 1,
          "restitution must be in [0, 1]");
  require(positive(scene.duration), "duration must be > 0");
  require(positive(scene.g), "g must be > 0");
  model_named_by(scene.effects);
  const bool has_vertical = !std::holds_alternative<NoMotion>(scene.vertical_motion);
  require(scene.effects.automatic || has_vertical == scene.effects.vertical,
          "effects list \"vertical\" exactly when the scene has a vertical_motion");
  const SolverSettings& solver = scene.solver;
  require(positive(solver.dt), "solver dt must be > 0");
  require(positive(solver.tolerance) && solver.tolerance <= 0.1,
          "solver tolerance must be in (0, 0.1]");
  require(solver.max_steps > 0 && solver.max_events > 0,
          "solver budgets must be > 0");
  const auto validate_motion = [](const GroundMotion& motion) {
    std::visit(
      [](const auto& m) {
        using M = std::decay_t<decltype(m)>;
        if constexpr (std::is_same_v<M, RectangularPulse>) {
          require(std::isfinite(m.amplitude_g), "pulse amplitude must be finite");
          require(positive(m.duration), "pulse duration must be > 0");
        } else if constexpr (std::is_same_v<M, RecordedMotion>) {
          require(m.record != nullptr, "a recorded motion needs its samples");
          require(std::isfinite(m.scale), "record scale must be finite");
          check_accelerogram(*m.record);
        } else if constexpr (std::is_same_v<M, MakrisPulseA> || std::is_same_v<M, MakrisPulseB> ||
                             std::is_same_v<M, MakrisPulseC> || std::is_same_v<M, RickerWavelet> ||
                             std::is_same_v<M, MavroeidisPapageorgiouPulse>) {
          require_valid(m);
        } else if constexpr (!std::is_same_v<M, NoMotion>) {
          require(std::isfinite(m.amplitude_g), "pulse amplitude must be finite");
          require(positive(m.period), "pulse period must be > 0");
          require(positive(m.cycles), "pulse cycles must be > 0");
        }
      },
      motion);
  };
  validate_motion(scene.ground_motion);
  validate_motion(scene.vertical_motion);
  if (scene.dam) validate_dam(*scene.dam);
}

}  // namespace blockfrag
