#include "mpi_driver/config/scene_json.hpp"

#include <cmath>
#include <filesystem>
#include <optional>

#include "engine/contact/model_choice.hpp"
#include "engine/scene/block_geometry.hpp"
#include "engine/scene/polygon_properties.hpp"
#include "engine/scene/seat.hpp"
#include "engine/tolerances.hpp"
#include "mpi_driver/config/config_reader.hpp"
#include "mpi_driver/config/dam_json.hpp"
#include "mpi_driver/config/effects_json.hpp"
#include "mpi_driver/config/field_table.hpp"
#include "mpi_driver/config/ground_motion_json.hpp"
#include "mpi_driver/config/input_file.hpp"
#include "mpi_driver/config/polygon_json.hpp"
#include "mpi_driver/config/reservoir_json.hpp"
#include "mpi_driver/config/scene_fields.hpp"
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
    read_fields<PolygonBlock>(reader, scene_fields::polygon_block, polygon);
    scene.polygon = std::move(polygon);
  } else {
    read_fields<RectangularBlock>(reader, scene_fields::rectangle, block);
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
  read_fields<Contact>(reader, scene_fields::contact, contact);
  if (const json* rocking = reader.raw("rocking_restitution")) {
    contact.rocking_restitution =
        read_rocking_restitution(*rocking, reader.path_of("rocking_restitution"), reader.errors());
  }
  reader.finish();
  return contact;
}

SolverSettings read_solver(ObjectReader reader, std::optional<double> duration) {
  SolverSettings solver;
  const bool method_valid =
      read_fields<SolverSettings>(reader, scene_fields::solver_method, solver).valid("method") ||
      !reader.has("method");
  // Without a valid method nobody knows which step's key belongs here.
  const std::optional<Method> method = method_valid ? std::optional(solver.method) : std::nullopt;
  if (method == Method::rk4) {
    const FieldsRead read = read_fields<SolverSettings>(reader, scene_fields::rk4_step, solver);
    if (read.valid("dt") && duration && solver.dt > *duration) {
      reader.add_error("dt", "must be <= duration (" + format_number(*duration) + ") (got " +
                                 format_number(solver.dt) + ")");
    }
  } else if (method) {  // the step-size-controlled methods
    read_fields<SolverSettings>(reader, scene_fields::step_control, solver);
  }
  read_fields<SolverSettings>(reader, scene_fields::budgets, solver);
  // A fixed step needs duration / dt steps at least: refused now rather than failing at the budget.
  if (method == Method::rk4 && duration &&
      *duration / solver.dt > static_cast<double>(solver.max_steps)) {
    reader.add_error("dt", "needs " + format_number(std::ceil(*duration / solver.dt)) +
                               " steps for the duration, more than max_steps (" +
                               std::to_string(solver.max_steps) + ")");
  }
  if (method) reader.finish("for method \"" + std::string(method_names.name(*method)) + "\"");
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
  read_fields<InitialState>(reader, scene_fields::initial, initial);
  reader.finish();
  return initial;
}

json solver_to_json(const SolverSettings& solver) {
  json out = json::object();
  write_fields<SolverSettings>(solver, scene_fields::solver_method, out);
  write_fields<SolverSettings>(solver, scene_fields::budgets, out);
  if (solver.method == Method::rk4) {
    write_fields<SolverSettings>(solver, scene_fields::rk4_step, out);
  } else {
    write_fields<SolverSettings>(solver, scene_fields::step_control, out);
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
  read_fields<Scene>(root, scene_fields::run, scene);
  if (scene.duration && scene.max_duration) {
    root.add_error("max_duration",
                   "give duration (a fixed run) or max_duration (a run to settle), not both");
  }
  scene.solver =
      read_solver(root.object("solver"), scene.duration ? scene.duration : scene.max_duration);
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
  json block = json::object(), contact = json::object(), initial = json::object();
  if (scene.polygon) {
    block = polygon_to_json(*scene.polygon);
  } else {
    write_fields<RectangularBlock>(scene.block, scene_fields::rectangle, block);
  }
  write_fields<Contact>(scene.contact, scene_fields::contact, contact);
  write_fields<InitialState>(scene.initial, scene_fields::initial, initial);
  json out = {{"effects", effects_to_json(scene.effects)},
              {"block", block},
              {"contact", contact},
              {"ground_motion", ground_motion_to_json(scene.ground_motion)},
              {"solver", solver_to_json(scene.solver)},
              {"initial", initial}};
  // A settling run has no duration, and a max_duration only when the scene gives one.
  write_fields<Scene>(scene, scene_fields::run, out);
  // Written only where given, so that a config without it keeps its hash.
  if (scene.contact.rocking_restitution) {
    out["contact"]["rocking_restitution"] =
        rocking_restitution_to_json(*scene.contact.rocking_restitution);
  }
  if (scene.dam) out["dam"] = dam_to_json(*scene.dam);
  if (scene.reservoir) out["reservoir"] = reservoir_to_json(*scene.reservoir);
  if (scene.seat) out["seat"] = scene.seat->points;
  if (!std::holds_alternative<NoMotion>(scene.vertical_motion)) {
    out["vertical_motion"] = ground_motion_to_json(scene.vertical_motion);
  }
  return out;
}

}  // namespace blockfrag
