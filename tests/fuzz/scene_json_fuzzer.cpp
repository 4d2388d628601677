// Fuzzes the scene reader: JSON text -> parse_json_text -> scene_from_json. A scene it accepts
// must survive the canonical round trip: scene_to_json's form reads back to the same form.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "mpi_driver/config/config_reader.hpp"
#include "mpi_driver/config/scene_json.hpp"
#include "tests/fuzz/fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace blockfrag;
  // A record's relative "file" is taken from this (never written) file's folder.
  static const std::string source = (fuzz::folder() / "scene.json").string();
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  return fuzz::run([&] {
    const nlohmann::json document = parse_json_text(text, source);
    if (!fuzz::files_stay_inside(document)) return -1;  // not kept in the corpus
    const Scene scene = scene_from_json(document, source);
    const nlohmann::json canonical = scene_to_json(scene);
    Scene again;
    try {
      again = scene_from_json(canonical, source);
    } catch (const InvalidInput& error) {
      fuzz::finding("scene_from_json refuses scene_to_json's form of a scene it accepted", &error);
    }
    if (scene_to_json(again) != canonical) {
      fuzz::finding("scene_to_json(scene_from_json(canonical)) differs from canonical: " +
                    canonical.dump());
    }
    return 0;
  });
}
