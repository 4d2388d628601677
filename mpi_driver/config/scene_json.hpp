// A Scene to and from JSON (the keys read through a table: mpi_driver/config/scene_fields.hpp):
//   {"block": {"half_width": 0.5, "half_height": 1.0, "mass": 1.0},
//    "contact": {"friction": 0.6, "restitution": 0.6},
//    "ground_motion": {"type": "cosine_pulse", "amplitude_g": 1.0, "period": 2.0, "cycles": 1},
//    "duration": 4.0,
//    "solver": {"method": "adaptive", "tolerance": 1e-8, "max_steps": ..., "max_events": ...},
//    "g": 9.81, "initial": {"theta": 0.0}}
// and optionally "reservoir" (mpi_driver/config/reservoir_json.hpp), "dam", "seat",
// "vertical_motion", "effects".
// block, contact, ground_motion and duration are required; everything else has the defaults of
// engine/scene/scene.hpp. Ground motion types: "none"; "cosine_pulse" and "sine_pulse"
// (amplitude_g, period, optional cycles); "rectangular_pulse" (amplitude_g, duration); "record"
// (file, optional scale or target_pga_g; see mpi_driver/config/record_file.hpp for the formats).
// Solver methods: "adaptive", "gsl_rkf45" and "gsl_rk8pd" (optional tolerance), and "rk4" (optional
// dt). A key of another type or method is an unknown key.
#pragma once

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "engine/scene/scene.hpp"
#include "mpi_driver/config/config_reader.hpp"

namespace blockfrag {

// Throws ConfigError listing every rule the document breaks; `source` is the document's file: it
// names it in the messages, and a record's relative "file" is taken from its folder.
Scene scene_from_json(const nlohmann::json& document, const std::string& source);

// Reads a scene embedded at `path` in a larger document (an accuracy suite's scene), adding its
// errors, with their full paths, to the caller's `errors`; a record's relative "file" is taken from
// base_folder (the document's folder). The Scene means something only if no errors were added.
Scene scene_from_json(const nlohmann::json& value, const JsonPointer& path, ConfigErrors& errors,
                      const std::filesystem::path& base_folder);

// Reads and checks a scene file (ConfigError for a malformed or invalid one, InputFileError if
// it cannot be read).
Scene read_scene_file(const std::filesystem::path& path);

// The canonical form: every key written, defaults included, keys sorted, doubles exact, only the
// keys of the scene's ground-motion type and solver method. scene_from_json reads it back to the
// same Scene, except the parameter of the solver method not in use, which keeps its default.
nlohmann::json scene_to_json(const Scene& scene);

}  // namespace blockfrag
