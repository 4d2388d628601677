#include "engine/scene/scene_validation.hpp"

#include <cmath>
#include <string>
#include <string_view>
#include <type_traits>

#include "engine/contact/model_choice.hpp"
#include "engine/errors.hpp"
#include "engine/motion/dam_crest.hpp"
#include "engine/number_text.hpp"
#include "engine/scene/block_geometry.hpp"
#include "engine/scene/parameter_domains.hpp"
#include "engine/scene/polygon_properties.hpp"
#include "engine/scene/seat.hpp"
#include "engine/tolerances.hpp"

namespace blockfrag {

namespace {

[[noreturn]] void refuse(const std::string& rule) { throw InvalidInput("invalid scene: " + rule); }

// The rule's text is made only when it is broken: a study validates every sample's scene, and
// building the messages of the rules it keeps was half of what a sample at rest cost.
void require(bool ok, std::string_view rule) {
  if (!ok) refuse(std::string(rule));
}

// "invalid scene: friction must be in [0, 10000] (got -1)"
void require_in(const Domain& domain, double value, const char* name) {
  if (!domain.contains(value)) {
    refuse(std::string(name) + " " + domain.rule() + " (got " + format_number(value) + ")");
  }
}

// The block's shape, and an initial tilt that leaves it on one of its base corners.
void validate_block(const Scene& scene) {
  const double theta = scene.initial.theta;
  require_in(domain::initial_theta, theta, "initial theta");
  require_in(domain::initial_omega, scene.initial.omega, "initial omega");
  require(scene.initial.omega == 0.0 || model_named_by(scene.effects) != Model::newmark_sliding,
          "initial omega needs a model that rocks: Newmark's sliding block never turns");
  if (!scene.polygon) {
    require_in(domain::block_length, scene.block.half_width, "block half_width");
    require_in(domain::block_length, scene.block.half_height, "block half_height");
    require_in(domain::mass, scene.block.mass, "block mass");
    return;
  }
  const auto& vertices = scene.polygon->vertices;
  if (static_cast<double>(vertices.size()) > domain::kMaxPolygonVertices) {
    refuse("block polygon has " + std::to_string(vertices.size()) + " vertices, more than " +
           format_number(domain::kMaxPolygonVertices));
  }
  for (const Vertex& v : vertices) {
    for (const double coordinate : v) {
      require_in(domain::polygon_coordinate, coordinate, "block polygon coordinate");
    }
  }
  if (const auto defect = polygon_defect(vertices)) {
    const std::string where =
        defect->vertex < 0 ? "" : " vertex " + std::to_string(defect->vertex) + ":";
    throw InvalidInput("invalid scene: block polygon:" + where + " " + defect->rule);
  }
  require_in(domain::mass, scene.polygon->mass, "block mass");
  const BlockGeometry geometry(*scene.polygon);
  require_in(domain::block_length, geometry.size(),
             "block polygon size (its farthest corner from the centre of mass)");
  require(theta > -geometry.overturn_angle(Corner::right) &&
              theta < geometry.overturn_angle(Corner::left),
          "initial theta must be within the tilts that lay the polygon on the faces next to its "
          "base");
}

// The seat's points, its fit with the block at rest (engine/scene/seat.hpp), a block released
// tilted clear of it, and few enough vertices and points for the seat's guards (one each).
void validate_seat(const Scene& scene) {
  const auto& points = scene.seat->points;
  if (static_cast<double>(points.size()) > domain::kMaxSeatPoints) {
    refuse("seat has " + std::to_string(points.size()) + " points, more than " +
           format_number(domain::kMaxSeatPoints));
  }
  for (const Vertex& p : points) {
    for (const double coordinate : p) {
      require_in(domain::polygon_coordinate, coordinate, "seat coordinate");
    }
  }
  const BlockGeometry geometry = scene_geometry(scene);
  if (const auto defect =
          seat_defect(points, scene_block_vertices(scene), kContactHeight * geometry.size())) {
    const std::string where =
        defect->point < 0 ? "" : " point " + std::to_string(defect->point) + ":";
    throw InvalidInput("invalid scene: seat:" + where + " " + defect->rule);
  }
  if (scene.initial.theta != 0.0) {
    if (const auto rule = tilt_defect(points, scene_block_vertices(scene), scene.initial.theta,
                                      kContactHeight * geometry.size())) {
      refuse("initial theta: " + *rule);
    }
  }
  require(model_named_by(scene.effects) == Model::full,
          "effects on a seat must be \"auto\" or the full model's (rocking, sliding, impact, "
          "flight): a seat's simulation has no reduced models");
  const std::size_t watched = points.size() + scene_block_vertices(scene).size();
  if (watched > static_cast<std::size_t>(kMaxSeatClearances)) {
    refuse("seat: the block's vertices and the seat's points number " + std::to_string(watched) +
           ", more than the " + std::to_string(kMaxSeatClearances) +
           " a seat's simulation watches");
  }
}

void validate_pulse(double amplitude_g, double period) {
  require_in(domain::amplitude_g, amplitude_g, "pulse amplitude_g");
  require_in(domain::pulse_period, period, "pulse period");
}

// The near-fault pulses (engine/motion/near_fault_pulses.hpp).
void require_valid(const MakrisPulseA& m) { validate_pulse(m.amplitude_g, m.period); }
void require_valid(const MakrisPulseB& m) { validate_pulse(m.amplitude_g, m.period); }
void require_valid(const MakrisPulseC& m) {
  validate_pulse(m.amplitude_g, m.period);
  require(m.n >= 1 && m.n <= 1000, "Makris type C pulse n must be in [1, 1000]");
}
void require_valid(const RickerWavelet& m) {
  validate_pulse(m.amplitude_g, m.period);
  if (m.t0) require_in(domain::motion_time, *m.t0, "Ricker wavelet t0");
}
void require_valid(const MavroeidisPapageorgiouPulse& m) {
  require_in(domain::velocity_amplitude, m.velocity_amplitude, "pulse velocity_amplitude");
  require_in(domain::pulse_period, m.period, "pulse period");
  require_in(domain::mp_gamma, m.gamma, "Mavroeidis-Papageorgiou gamma");
  require_in(domain::mp_phase, m.phase, "Mavroeidis-Papageorgiou phase");
  if (m.t0) require_in(domain::motion_time, *m.t0, "Mavroeidis-Papageorgiou t0");
  // The pulse must start at t >= 0: a block at rest on a ground already moving is another problem.
  require(!m.t0 || *m.t0 >= (1.0 - kGridRounding) * m.half_width(),
          "Mavroeidis-Papageorgiou t0 must be >= gamma period / 2 (the pulse starts at t >= 0)");
}

void validate_motion(const GroundMotion& motion) {
  std::visit(
      [](const auto& m) {
        using M = std::decay_t<decltype(m)>;
        if constexpr (std::is_same_v<M, RectangularPulse>) {
          require_in(domain::amplitude_g, m.amplitude_g, "pulse amplitude_g");
          require_in(domain::pulse_duration, m.duration, "rectangular pulse duration");
        } else if constexpr (std::is_same_v<M, RecordedMotion>) {
          require(m.record != nullptr, "a recorded motion needs its samples");
          require_in(domain::record_scale, m.scale, "record scale");
          require(m.record->times.size() <= domain::kMaxRecordSamples,
                  "a record has at most " + std::to_string(domain::kMaxRecordSamples) + " samples");
          check_accelerogram(*m.record);
          require_in(domain::record_time, m.record->times.back(), "record's last sample time");
        } else if constexpr (std::is_same_v<M, CosinePulse> || std::is_same_v<M, SinePulse>) {
          validate_pulse(m.amplitude_g, m.period);
          require_in(domain::pulse_cycles, m.cycles, "pulse cycles");
        } else if constexpr (!std::is_same_v<M, NoMotion>) {
          require_valid(m);
        }
      },
      motion);
}

void validate_dam(const DamCrest& dam) {
  if (const auto* given = std::get_if<DamPeriod>(&dam.stiffness)) {
    require_in(domain::dam_period, given->period, "dam period");
  } else {
    const auto& size = std::get<DamSize>(dam.stiffness);
    require_in(domain::dam_height, size.height, "dam height");
    require_in(domain::elastic_modulus, size.elastic_modulus, "dam elastic_modulus");
  }
  // The filter is the underdamped oscillator's closed form.
  require_in(domain::dam_damping, dam.damping, "dam damping");
  require_in(domain::participation, dam.participation, "dam participation");
  require_in(domain::dam_period_ratio, dam.reservoir_period_ratio, "dam reservoir_period_ratio");
  require_in(domain::dam_added_damping, dam.reservoir_damping, "dam reservoir_damping");
  require_in(domain::dam_period_ratio, dam.foundation_period_ratio, "dam foundation_period_ratio");
  require_in(domain::dam_added_damping, dam.foundation_damping, "dam foundation_damping");
  require(dam_mode(dam).damping < 1.0, "dam damping with its reservoir and foundation must be < 1");
}

// The reservoir must be at least as deep as the water against the block at rest: Westergaard's
// pressure is a reservoir's of depth H, whose bottom is not above the block's base.
void validate_reservoir(const Scene& scene) {
  const Reservoir& water = *scene.reservoir;
  require_in(domain::reservoir_level, water.level, "reservoir level");
  require_in(domain::reservoir_depth, water.depth, "reservoir depth");
  require_in(domain::water_density, water.density, "reservoir density");
  require_in(domain::uplift_area_factor, water.uplift_area_factor, "reservoir uplift_area_factor");
  const double wetted = water.level - lowest_block_y(scene);
  // Water against the block runs the full model on the seat's engine (engine/water/
  // reservoir_load.hpp), with the water's pressures in g alone.
  if (wetted > 0.0) {
    require(model_named_by(scene.effects) == Model::full,
            "effects with a reservoir must be \"auto\" or the full model's (rocking, sliding, "
            "impact, flight)");
    require(std::holds_alternative<NoMotion>(scene.vertical_motion),
            "a reservoir takes no vertical_motion (its pressures are in g alone)");
    // The rocking rule turns the block alone about its new corner; the water's added mass would
    // take part in the impact.
    require(!scene.contact.rocking_restitution || water.hydrodynamic == Hydrodynamic::none,
            "contact rocking_restitution is not taken with a reservoir's westergaard added mass");
  }
  if (!(water.depth >= wetted)) {
    refuse(
        "reservoir depth must be >= the water's depth at the block, level minus the block's "
        "lowest y (" +
        format_number(wetted) + " m) (got " + format_number(water.depth) + ")");
  }
}

void validate_solver(const SolverSettings& solver, std::optional<double> longest_run) {
  require_in(domain::rk4_step, solver.dt, "solver dt");
  require(solver.method != Method::rk4 || !longest_run ||
              *longest_run / solver.dt <= static_cast<double>(solver.max_steps),
          "solver dt needs more steps for the duration than max_steps");
  require_in(domain::tolerance, solver.tolerance, "solver tolerance");
  require_in(domain::max_steps, static_cast<double>(solver.max_steps), "solver max_steps");
  require_in(domain::max_events, static_cast<double>(solver.max_events), "solver max_events");
}

}  // namespace

void validate_scene(const Scene& scene) {
  validate_block(scene);
  if (scene.seat) validate_seat(scene);
  require_in(domain::friction, scene.contact.friction, "friction");
  require_in(domain::restitution, scene.contact.restitution, "restitution");
  if (const auto& rocking = scene.contact.rocking_restitution) {
    if (!rocking->housner) {
      require_in(domain::rocking_restitution, rocking->ratio, "rocking_restitution");
    }
    require(has_rocking_impacts(scene.effects),
            "rocking_restitution needs a model with rocking impacts: effects \"auto\", the full "
            "model's or [\"rocking\", \"impact\"]");
  }
  if (scene.duration) require_in(domain::duration, *scene.duration, "duration");
  if (scene.max_duration) require_in(domain::duration, *scene.max_duration, "max_duration");
  require(!(scene.duration && scene.max_duration),
          "give duration (a fixed run) or max_duration (a run to settle), not both");
  require_in(domain::g, scene.g, "g");
  model_named_by(scene.effects);
  const bool has_vertical = !std::holds_alternative<NoMotion>(scene.vertical_motion);
  require(scene.effects.automatic || has_vertical == scene.effects.vertical,
          "effects list \"vertical\" exactly when the scene has a vertical_motion");
  validate_solver(scene.solver, scene.duration ? scene.duration : scene.max_duration);
  validate_motion(scene.ground_motion);
  validate_motion(scene.vertical_motion);
  if (scene.dam) validate_dam(*scene.dam);
  if (scene.reservoir) validate_reservoir(scene);
}

}  // namespace blockfrag
