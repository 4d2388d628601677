// The near-fault pulses in scene JSON: each type reads into its struct, writes back with its
// defaults filled in, and each rule is refused at its path.
#include <string>
#include <variant>

#include <gtest/gtest.h>

#include "engine/errors.hpp"
#include "engine/scene/scene_validation.hpp"
#include "mpi_driver/config/config_reader.hpp"
#include "mpi_driver/config/scene_json.hpp"
#include "tests/support/scene_json_errors.hpp"

namespace blockfrag {
namespace {

using nlohmann::json;

json scene_with(const json& motion) {
  return {{"block", {{"half_width", 0.2}, {"half_height", 0.8}}},
          {"contact", {{"friction", 0.7}, {"restitution", 0.8}}},
          {"ground_motion", motion},
          {"duration", 3.0}};
}

std::string motion_errors(const json& motion) { return testing::scene_errors(scene_with(motion)); }

TEST(PulseJson, EachTypeReadsIntoItsPulse) {
  const auto c = scene_from_json(
      scene_with({{"type", "makris_c"}, {"amplitude_g", -0.4}, {"period", 0.6}, {"n", 3}}),
      "scene.json");
  const auto& pulse = std::get<MakrisPulseC>(c.ground_motion);
  EXPECT_EQ(pulse.amplitude_g, -0.4);
  EXPECT_EQ(pulse.period, 0.6);
  EXPECT_EQ(pulse.n, 3);

  const auto mp = scene_from_json(scene_with({{"type", "mavroeidis_papageorgiou"},
                                              {"velocity_amplitude", 0.9},
                                              {"period", 1.2},
                                              {"gamma", 2.5}}),
                                  "scene.json");
  const auto& m = std::get<MavroeidisPapageorgiouPulse>(mp.ground_motion);
  EXPECT_EQ(m.velocity_amplitude, 0.9);
  EXPECT_EQ(m.phase, 0.0);     // default
  EXPECT_EQ(m.center(), 1.5);  // default gamma Tp / 2
  EXPECT_EQ(
      std::get<RickerWavelet>(
          scene_from_json(scene_with({{"type", "ricker"}, {"amplitude_g", 1}, {"period", 0.4}}),
                          "scene.json")
              .ground_motion)
          .center(),
      0.4 * 1.5);
}

TEST(PulseJson, CanonicalFormFillsTheCentresAndReadsBack) {
  const json cases[][2] = {
      {{{"type", "makris_a"}, {"amplitude_g", 0.5}, {"period", 0.3}}, {}},
      {{{"type", "makris_b"}, {"amplitude_g", -0.5}, {"period", 0.3}}, {}},
      {{{"type", "makris_c"}, {"amplitude_g", 0.5}, {"period", 0.3}, {"n", 2}}, {}},
      {{{"type", "ricker"}, {"amplitude_g", 0.5}, {"period", 0.4}},
       {{"type", "ricker"}, {"amplitude_g", 0.5}, {"period", 0.4}, {"t0", 0.4 * 1.5}}},
      {{{"type", "mavroeidis_papageorgiou"},
        {"velocity_amplitude", 0.7},
        {"period", 0.5},
        {"gamma", 2.0},
        {"phase", 1.0},
        {"t0", 2.0}},
       {}},
  };
  for (const auto& [motion, expected] : cases) {
    const json canonical = scene_to_json(scene_from_json(scene_with(motion), "scene.json"));
    EXPECT_EQ(canonical["ground_motion"], expected.is_null() ? motion : expected);
    EXPECT_EQ(scene_to_json(scene_from_json(canonical, "canonical.json")), canonical);
  }
}

TEST(PulseJson, RulesAreRefusedAtTheirPath) {
  const json c = {{"type", "makris_c"}, {"amplitude_g", 0.5}, {"period", 0.3}};
  EXPECT_EQ(motion_errors(c), "scene.json: /ground_motion/n: is required");
  json bad = c;
  bad["n"] = 0;
  EXPECT_EQ(motion_errors(bad), "scene.json: /ground_motion/n: must be in [1, 1000] (got 0)");
  bad["n"] = 1.5;
  EXPECT_EQ(motion_errors(bad), "scene.json: /ground_motion/n: must be an integer (got 1.5)");

  const json mp = {{"type", "mavroeidis_papageorgiou"},
                   {"velocity_amplitude", 0.7},
                   {"period", 0.5},
                   {"gamma", 2.0}};
  bad = mp;
  bad["gamma"] = 1.0;
  EXPECT_EQ(motion_errors(bad), "scene.json: /ground_motion/gamma: must be in (1, 100] (got 1)");
  bad = mp;
  bad["t0"] = 0.4;
  EXPECT_EQ(motion_errors(bad),
            "scene.json: /ground_motion/t0: must be >= gamma period / 2 = 0.5 (the pulse starts at "
            "t >= 0) (got 0.4)");
  bad = mp;
  bad["amplitude_g"] = 1.0;  // this pulse is given by its velocity
  EXPECT_EQ(motion_errors(bad),
            "scene.json: /ground_motion/amplitude_g: unknown key for type "
            "\"mavroeidis_papageorgiou\" (known keys: gamma "
            "period phase t0 type velocity_amplitude)");

  EXPECT_EQ(motion_errors({{"type", "ricker"}, {"amplitude_g", 0.5}, {"period", 0.4}, {"t0", 0.0}}),
            "scene.json: /ground_motion/t0: must be in (0, 1e+05] (got 0)");
  EXPECT_EQ(motion_errors({{"type", "makris_a"}, {"amplitude_g", 0.5}, {"period", -1}}),
            "scene.json: /ground_motion/period: must be in [0.001, 1000] (got -1)");
}

TEST(PulseJson, TheEngineRefusesWhatTheReaderRefuses) {
  Scene scene;
  scene.ground_motion = MavroeidisPapageorgiouPulse{0.5, 1.0, 0.9, 0.0, {}};
  EXPECT_THROW(validate_scene(scene), InvalidInput);
  scene.ground_motion = MavroeidisPapageorgiouPulse{0.5, 1.0, 2.0, 0.0, 0.99};
  EXPECT_THROW(validate_scene(scene), InvalidInput);
  scene.ground_motion = MavroeidisPapageorgiouPulse{0.5, 1.0, 2.0, 0.0, 1.0};
  EXPECT_NO_THROW(validate_scene(scene));
  scene.ground_motion = MakrisPulseC{0.5, 1.0, 0};
  EXPECT_THROW(validate_scene(scene), InvalidInput);
  scene.ground_motion = RickerWavelet{0.5, 1.0, -1.0};
  EXPECT_THROW(validate_scene(scene), InvalidInput);
}

}  // namespace
}  // namespace blockfrag
