// The fixed scene suite of the work-precision study (configs/accuracy_suite.json):
//   {"scenes": [{"name": "rock_free_release", "category": "rocking",
//                "description": "why this scene is here", "scene": {...}}, ...]}
// Each "scene" is a scene in the public form of scene_json.hpp without "solver": the study sets the
// solver, so a suite that names one would mislead its reader and is refused.
#pragma once

#include <array>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/scene/scene.hpp"

namespace blockfrag {

// What a scene exercises; every category must be covered by the full suite.
// (The reader's list of choices repeats these names.)
inline constexpr std::array<std::string_view, 7> accuracy_categories = {
    "rocking",     "sliding",        "slide_rock", "flight_bouncing",
    "overturning", "near_threshold", "mixed"};

struct SuiteScene {
  std::string name;
  std::string category;
  std::string description;
  Scene scene;
};

struct AccuracySuite {
  std::vector<SuiteScene> scenes;
};

// Throws ConfigError listing every problem (paths like /scenes/3/scene/contact/friction); names
// must be unique and non-empty, and the suite must have at least one scene.
AccuracySuite accuracy_suite_from_json(const nlohmann::json& document, const std::string& source);

AccuracySuite read_accuracy_suite(const std::filesystem::path& path);

}  // namespace blockfrag
