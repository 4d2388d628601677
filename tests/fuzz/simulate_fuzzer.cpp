// Fuzzes a whole scene through the engine: a scene scene_from_json accepts is simulated, with its
// duration clamped to kMaxDuration and its step and event budgets to kMaxBudget so that no input
// takes long. A status "failed" is an answer; an exception other than InvalidInput is a finding.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "engine/simulate.hpp"
#include "mpi_driver/config/config_reader.hpp"
#include "mpi_driver/config/scene_json.hpp"
#include "tests/fuzz/fuzz_support.hpp"

namespace {
constexpr double kMaxDuration = 1.0;  // s
constexpr long kMaxBudget = 200'000;  // steps, events
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace blockfrag;
  static const std::string source = (fuzz::folder() / "scene.json").string();
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  return fuzz::run([&] {
    const nlohmann::json document = parse_json_text(text, source);
    if (!fuzz::files_stay_inside(document)) return -1;  // not kept in the corpus
    Scene scene = scene_from_json(document, source);
    // A scene without a duration runs until it settles: cap it like the others.
    scene.duration = std::min(scene.duration.value_or(kMaxDuration), kMaxDuration);
    scene.solver.max_steps = std::min(scene.solver.max_steps, kMaxBudget);
    scene.solver.max_events = std::min(scene.solver.max_events, kMaxBudget);
    simulate(scene);
    return 0;
  });
}
