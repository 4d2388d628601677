#include "mpi_driver/config/scene_json.hpp"

#include <cmath>
#include <filesystem>
#include <memory>
#include <optional>
#include <type_traits>

#include "engine/contact/model_choice.hpp"
#include "engine/scene/block_geometry.hpp"
#include "engine/scene/polygon_properties.hpp"
#include "engine/scene/seat.hpp"
#include "engine/tolerances.hpp"
#include "mpi_driver/config/config_reader.hpp"
#include "mpi_driver/config/dam_json.hpp"
#include "mpi_driver/config/effects_json.hpp"
#include "mpi_driver/config/input_file.hpp"
#include "mpi_driver/config/polygon_json.hpp"
#include "mpi_driver/config/pulse_json.hpp"
#include "mpi_driver/config/record_file.hpp"
#include "mpi_driver/config/reservoir_json.hpp"
#include "mpi_driver/config/seat_json.hpp"
#include "sampling/validation.hpp"  // format_number

namespace blockfrag {

namespace {

using nlohmann::json;

// A rectangle (half_width, half_height) or a polygon (mpi_driver/config/polygon_json.hpp).
void read_block(ObjectReader reader, Scene& scene) {
  RectangularBlock& block = scene.block;
  if (reader.has("polygon")) {
    PolygonBlock polygon;
    polygon.vertices =
        read_polygon(*reader.raw("polygon"), reader.path_of("polygon"), reader.errors());
    for (const char* key : {"half_width", "half_height"}) {
      if (reader.has(key))
        reader.add_error(key, "give either polygon or half_width and half_height, not both");
    }
    polygon.mass = reader.number_or("mass", polygon.mass, Range::of(domain::mass));
    scene.polygon = std::move(polygon);
  } else {
    block.half_width = reader.required_number("half_width", Range::of(domain::block_length))
                           .value_or(block.half_width);
    block.half_height = reader.required_number("half_height", Range::of(domain::block_length))
                            .value_or(block.half_height);
    block.mass = reader.number_or("mass", block.mass, Range::of(domain::mass));
  }
  reader.finish();
}

// A number in (0, 1] or "housner" (engine/contact/rocking_restitution.hpp).
std::optional<RockingRestitution> read_rocking_restitution(const json& value,
                                                           const JsonPointer& path,
                                                           ConfigErrors& errors) {
  if (value == "housner") return RockingRestitution{true, 1.0};
  if (!value.is_number()) {
    errors.add(path,
               "must be a number in (0, 1] or \"housner\" (got " +
                   printable_excerpt(value.dump(-1, ' ', false, json::error_handler_t::replace)) +
                   ")");
    return std::nullopt;
  }
  const auto ratio = read_number(value, path, errors, Range::of(domain::rocking_restitution));
  if (!ratio) return std::nullopt;
  return RockingRestitution{false, *ratio};
}

json rocking_restitution_to_json(const RockingRestitution& rocking) {
  if (rocking.housner) return "housner";
  return rocking.ratio;
}

Contact read_contact(ObjectReader reader) {
  Contact contact;
  contact.friction =
      reader.required_number("friction", Range::of(domain::friction)).value_or(contact.friction);
  contact.restitution = reader.required_number("restitution", Range::of(domain::restitution))
                            .value_or(contact.restitution);
  if (const json* rocking = reader.raw("rocking_restitution")) {
    contact.rocking_restitution =
        read_rocking_restitution(*rocking, reader.path_of("rocking_restitution"), reader.errors());
  }
  reader.finish();
  return contact;
}

// Cosine and sine pulses share their parameters.
template <class Pulse>
Pulse read_periodic_pulse(ObjectReader& reader) {
  Pulse pulse;
  pulse.amplitude_g = reader.required_number("amplitude_g", Range::of(domain::amplitude_g))
                          .value_or(pulse.amplitude_g);
  pulse.period =
      reader.required_number("period", Range::of(domain::pulse_period)).value_or(pulse.period);
  pulse.cycles = reader.number_or("cycles", 1.0, Range::of(domain::pulse_cycles));
  return pulse;
}

RectangularPulse read_rectangular_pulse(ObjectReader& reader) {
  RectangularPulse pulse;
  pulse.amplitude_g = reader.required_number("amplitude_g", Range::of(domain::amplitude_g))
                          .value_or(pulse.amplitude_g);
  pulse.duration = reader.required_number("duration", Range::of(domain::pulse_duration))
                       .value_or(pulse.duration);
  return pulse;
}

// The samples are read here, so a record that cannot be used is refused with the scene, at
// /ground_motion/file, with the reader's "<file>:<line>: <reason>".
RecordedMotion read_record(ObjectReader& reader, const std::filesystem::path& base_folder) {
  RecordedMotion motion;
  const auto file = reader.required_string("file");
  const auto scale = reader.number("scale", Range::of(domain::record_scale));
  const auto target_pga = reader.number("target_pga_g", Range::of(domain::target_pga_g));
  if (scale && target_pga)
    reader.add_error("target_pga_g", "give either scale or target_pga_g, not both");
  if (file && file->empty()) reader.add_error("file", "must not be empty");
  if (!file || file->empty()) return motion;
  motion.file = *file;
  const std::filesystem::path path = base_folder / *file;  // an absolute file replaces the folder
  try {
    motion.record = std::make_shared<const Accelerogram>(read_accelerogram(path));
  } catch (const RecordError& error) {
    reader.add_error("file", error.what());
    return motion;
  }
  motion.scale = scale.value_or(1.0);
  if (target_pga) {
    const double peak = peak_acceleration_g(*motion.record);
    if (peak > 0) {
      motion.scale = *target_pga / peak;
    } else {
      reader.add_error("target_pga_g",
                       "cannot scale " + path.string() + " to a peak: its accelerations are all 0");
    }
  }
  return motion;
}

GroundMotion read_ground_motion(ObjectReader reader, const std::filesystem::path& base_folder) {
  const auto type = reader.required_choice(
      "type", {"none", "cosine_pulse", "sine_pulse", "rectangular_pulse", "record", makris_a_type,
               makris_b_type, makris_c_type, ricker_type, mavroeidis_papageorgiou_type});
  // Without a valid type nobody knows which keys belong here: report nothing more.
  if (!type) return NoMotion{};
  GroundMotion motion = NoMotion{};
  if (*type == "cosine_pulse") motion = read_periodic_pulse<CosinePulse>(reader);
  if (*type == "sine_pulse") motion = read_periodic_pulse<SinePulse>(reader);
  if (*type == "rectangular_pulse") motion = read_rectangular_pulse(reader);
  if (*type == "record") motion = read_record(reader, base_folder);
  if (auto pulse = read_near_fault_pulse(*type, reader)) motion = *pulse;
  reader.finish("for type \"" + *type + "\"");
  return motion;
}

std::optional<Method> method_named(const std::optional<std::string>& name) {
  if (name == "adaptive") return Method::adaptive;
  if (name == "rk4") return Method::rk4;
  if (name == "gsl_rkf45") return Method::gsl_rkf45;
  if (name == "gsl_rk8pd") return Method::gsl_rk8pd;
  return std::nullopt;
}

const char* method_name(Method method) {
  switch (method) {
    case Method::adaptive: return "adaptive";
    case Method::rk4: return "rk4";
    case Method::gsl_rkf45: return "gsl_rkf45";
    case Method::gsl_rk8pd: return "gsl_rk8pd";
  }
  return "unknown";
}

SolverSettings read_solver(ObjectReader reader, std::optional<double> duration) {
  SolverSettings solver;
  const auto method = reader.has("method")
                          ? method_named(reader.required_choice(
                                "method", {"adaptive", "rk4", "gsl_rkf45", "gsl_rk8pd"}))
                          : std::optional<Method>(solver.method);
  if (method == Method::rk4) {
    const auto dt = reader.number("dt", Range::of(domain::rk4_step));
    if (dt) solver.dt = *dt;
    if (dt && duration && *dt > *duration) {
      reader.add_error("dt", "must be <= duration (" + format_number(*duration) + ") (got " +
                                 format_number(*dt) + ")");
    }
  } else if (method) {  // the step-size-controlled methods
    solver.tolerance =
        reader.number_or("tolerance", solver.tolerance, Range::of(domain::tolerance));
  }
  if (method) solver.method = *method;
  solver.max_steps = reader.integer_or("max_steps", solver.max_steps, Range::of(domain::max_steps));
  solver.max_events =
      reader.integer_or("max_events", solver.max_events, Range::of(domain::max_events));
  // A fixed step needs duration / dt steps at least: refused now rather than failing at the budget.
  if (method == Method::rk4 && duration &&
      *duration / solver.dt > static_cast<double>(solver.max_steps)) {
    reader.add_error("dt", "needs " + format_number(std::ceil(*duration / solver.dt)) +
                               " steps for the duration, more than max_steps (" +
                               std::to_string(solver.max_steps) + ")");
  }
  if (method) reader.finish("for method \"" + std::string(method_name(*method)) + "\"");
  return solver;
}

// A polygon may lay a face next to its base on the ground before pi/2: the tilt must stop short.
void check_polygon_tilt(const PolygonBlock& polygon, double theta, const JsonPointer& path,
                        ConfigErrors& errors) {
  if (polygon_defect(polygon.vertices)) return;  // reported at the polygon
  const BlockGeometry geometry(polygon);
  const double low = -geometry.overturn_angle(Corner::right),
               high = geometry.overturn_angle(Corner::left);
  if (!(theta > low && theta < high)) {
    errors.add(
        path,
        "must be in (" + format_number(low) + ", " + format_number(high) +
            ") for this polygon, the tilts that lay a face next to its base on the ground (got " +
            format_number(theta) + ")");
  }
}

// The seat (mpi_driver/config/seat_json.hpp), and the block released on it, clear of it if tilted.
void read_scene_seat(ObjectReader& root, bool block_valid, const JsonPointer& path,
                     ConfigErrors& errors, Scene& scene) {
  const std::vector<Vertex> block = scene_block_vertices(scene);
  const std::size_t errors_before = errors.size();
  scene.seat = Seat{
      read_seat(*root.raw("seat"), root.path_of("seat"), errors, block_valid ? &block : nullptr)};
  // A tilt is checked against a seat the block fits at rest: turned about its pivot, it must stay
  // clear of the seat.
  if (scene.initial.theta != 0.0 && block_valid && errors.size() == errors_before) {
    const double tolerance = kContactHeight * BlockGeometry(PolygonBlock{block, 1.0}).size();
    if (const auto rule = tilt_defect(scene.seat->points, block, scene.initial.theta, tolerance)) {
      errors.add(path / "initial" / "theta", *rule);
    }
  }
  const Effects& e = scene.effects;
  if (!e.automatic && !(e.rocking && e.sliding && e.impact && e.flight)) {
    errors.add(path / "effects",
               "must be \"auto\" or the full model's (rocking, sliding, impact, flight) with a "
               "seat: a seat's simulation has no reduced models");
  }
}

InitialState read_initial(ObjectReader reader) {
  InitialState initial;
  initial.theta = reader.number_or("theta", initial.theta, Range::of(domain::initial_theta));
  initial.omega = reader.number_or("omega", initial.omega, Range::of(domain::initial_omega));
  reader.finish();
  return initial;
}

json ground_motion_to_json(const GroundMotion& motion) {
  return std::visit(
      [](const auto& pulse) -> json {
        using Pulse = std::decay_t<decltype(pulse)>;
        if constexpr (std::is_same_v<Pulse, NoMotion>) {
          return {{"type", "none"}};
        } else if constexpr (std::is_same_v<Pulse, CosinePulse> ||
                             std::is_same_v<Pulse, SinePulse>) {
          return {{"type", std::is_same_v<Pulse, CosinePulse> ? "cosine_pulse" : "sine_pulse"},
                  {"amplitude_g", pulse.amplitude_g},
                  {"period", pulse.period},
                  {"cycles", pulse.cycles}};
        } else if constexpr (std::is_same_v<Pulse, RecordedMotion>) {
          return {{"type", "record"}, {"file", pulse.file}, {"scale", pulse.scale}};
        } else if constexpr (std::is_same_v<Pulse, MakrisPulseA> ||
                             std::is_same_v<Pulse, MakrisPulseB> ||
                             std::is_same_v<Pulse, MakrisPulseC> ||
                             std::is_same_v<Pulse, RickerWavelet> ||
                             std::is_same_v<Pulse, MavroeidisPapageorgiouPulse>) {
          return pulse_to_json(pulse);
        } else {
          static_assert(std::is_same_v<Pulse, RectangularPulse>);
          return {{"type", "rectangular_pulse"},
                  {"amplitude_g", pulse.amplitude_g},
                  {"duration", pulse.duration}};
        }
      },
      motion);
}

json solver_to_json(const SolverSettings& solver) {
  json out = {{"method", method_name(solver.method)},
              {"max_steps", solver.max_steps},
              {"max_events", solver.max_events}};
  if (solver.method == Method::rk4) {
    out["dt"] = solver.dt;
  } else {
    out["tolerance"] = solver.tolerance;
  }
  return out;
}

}  // namespace

Scene scene_from_json(const json& document, const std::string& source) {
  ConfigErrors errors(source);
  Scene scene =
      scene_from_json(document, JsonPointer{}, errors, std::filesystem::path(source).parent_path());
  errors.throw_if_any();
  return scene;
}

Scene scene_from_json(const json& value, const JsonPointer& path, ConfigErrors& errors,
                      const std::filesystem::path& base_folder) {
  const std::size_t errors_before = errors.size();
  ObjectReader root(value, path, errors);
  Scene scene;
  scene.effects = read_effects(root.raw("effects"), root.path_of("effects"), errors);
  const std::size_t errors_before_block = errors.size();
  read_block(root.required_object("block"), scene);
  const bool block_valid = errors.size() == errors_before_block;
  scene.contact = read_contact(root.required_object("contact"));
  if (scene.contact.rocking_restitution && !has_rocking_impacts(scene.effects)) {
    errors.add(path / "contact" / "rocking_restitution",
               "needs a model with rocking impacts: effects \"auto\", the full model's or "
               "[\"rocking\", \"impact\"]");
  }
  scene.ground_motion = read_ground_motion(root.required_object("ground_motion"), base_folder);
  if (root.has("vertical_motion")) {
    scene.vertical_motion = read_ground_motion(root.object("vertical_motion"), base_folder);
  }
  if (!scene.effects.automatic &&
      scene.effects.vertical == std::holds_alternative<NoMotion>(scene.vertical_motion)) {
    errors.add(path / "effects", "lists \"vertical\" exactly when the scene has a vertical_motion");
  }
  scene.dam = read_dam(root.object("dam"));
  scene.reservoir =
      read_reservoir(root.object("reservoir"),
                     block_valid ? std::optional<double>(lowest_block_y(scene)) : std::nullopt);
  // Without a duration the run settles (engine/scene/scene.hpp), at most max_duration.
  const auto duration = root.number("duration", Range::of(domain::duration));
  scene.duration = duration;
  scene.max_duration = root.number("max_duration", Range::of(domain::duration));
  if (duration && scene.max_duration) {
    root.add_error("max_duration",
                   "give duration (a fixed run) or max_duration (a run to settle), not both");
  }
  scene.g = root.number_or("g", scene.g, Range::of(domain::g));
  scene.solver = read_solver(root.object("solver"), duration ? duration : scene.max_duration);
  scene.initial = read_initial(root.object("initial"));
  if (scene.polygon)
    check_polygon_tilt(*scene.polygon, scene.initial.theta, path / "initial" / "theta", errors);
  if (root.has("seat")) read_scene_seat(root, block_valid, path, errors, scene);
  root.finish();
  // The dam's crest history is counted only for a scene that is otherwise valid.
  if (errors.size() == errors_before) {
    if (const auto problem = crest_history_problem(scene)) errors.add(path / "dam", *problem);
  }
  return scene;
}

Scene read_scene_file(const std::filesystem::path& path) {
  return scene_from_json(read_json_file(path), path.string());
}

json scene_to_json(const Scene& scene) {
  json out = {{"effects", effects_to_json(scene.effects)},
              {"block", scene.polygon ? polygon_to_json(*scene.polygon)
                                      : json{{"half_width", scene.block.half_width},
                                             {"half_height", scene.block.half_height},
                                             {"mass", scene.block.mass}}},
              {"contact",
               {{"friction", scene.contact.friction}, {"restitution", scene.contact.restitution}}},
              {"ground_motion", ground_motion_to_json(scene.ground_motion)},
              {"g", scene.g},
              {"solver", solver_to_json(scene.solver)},
              {"initial", {{"theta", scene.initial.theta}}}};
  // Written only where given, so that a config without them keeps its hash.
  if (scene.initial.omega != 0.0) out["initial"]["omega"] = scene.initial.omega;
  if (scene.contact.rocking_restitution) {
    out["contact"]["rocking_restitution"] =
        rocking_restitution_to_json(*scene.contact.rocking_restitution);
  }
  // A settling run has no duration, and a max_duration only when the scene gives one.
  if (scene.duration) out["duration"] = *scene.duration;
  if (scene.max_duration) out["max_duration"] = *scene.max_duration;
  if (scene.dam) out["dam"] = dam_to_json(*scene.dam);
  if (scene.reservoir) out["reservoir"] = reservoir_to_json(*scene.reservoir);
  if (scene.seat) out["seat"] = scene.seat->points;
  if (!std::holds_alternative<NoMotion>(scene.vertical_motion)) {
    out["vertical_motion"] = ground_motion_to_json(scene.vertical_motion);
  }
  return out;
}

}  // namespace blockfrag
