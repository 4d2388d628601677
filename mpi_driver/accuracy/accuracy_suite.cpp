#include "mpi_driver/accuracy/accuracy_suite.hpp"

#include <set>

#include "mpi_driver/config/config_reader.hpp"
#include "mpi_driver/config/scene_json.hpp"

namespace blockfrag {

namespace {

SuiteScene read_suite_scene(ObjectReader reader, std::set<std::string>& names,
                            const std::filesystem::path& base_folder) {
  SuiteScene entry;
  entry.name = reader.required_string("name").value_or("");
  if (reader.has("name") && entry.name.empty()) reader.add_error("name", "must not be empty");
  if (!entry.name.empty() && !names.insert(entry.name).second) {
    reader.add_error("name", "must be unique (\"" + entry.name + "\" is used twice)");
  }
  entry.category =
      reader
          .required_choice("category", {"rocking", "sliding", "slide_rock", "flight_bouncing",
                                        "overturning", "near_threshold", "mixed"})
          .value_or("");
  entry.description = reader.string_or("description", "");
  if (const nlohmann::json* scene = reader.raw("scene")) {
    if (scene->is_object() && scene->contains("solver")) {
      reader.errors().add(reader.path_of("scene") / "solver",
                          "must be absent: the accuracy study sets the solver of every scene");
    } else {
      entry.scene = scene_from_json(*scene, reader.path_of("scene"), reader.errors(), base_folder);
    }
  } else if (reader.valid()) {
    reader.add_error("scene", "is required");
  }
  reader.finish();
  return entry;
}

}  // namespace

AccuracySuite accuracy_suite_from_json(const nlohmann::json& document, const std::string& source) {
  ConfigErrors errors(source);
  ObjectReader root(document, JsonPointer{}, errors);
  ArrayReader scenes = root.required_array("scenes");
  if (scenes.valid() && scenes.size() == 0)
    root.add_error("scenes", "must have at least one scene");
  AccuracySuite suite;
  std::set<std::string> names;
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    suite.scenes.push_back(
        read_suite_scene(scenes.object(i), names, std::filesystem::path(source).parent_path()));
  }
  root.finish();
  errors.throw_if_any();
  return suite;
}

AccuracySuite read_accuracy_suite(const std::filesystem::path& path) {
  return accuracy_suite_from_json(read_json_file(path), path.string());
}

}  // namespace blockfrag
