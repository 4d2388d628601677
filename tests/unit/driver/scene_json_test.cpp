// Scenes from JSON: every rule of the public form is refused with its path and rule, defaults are
// the documented ones, the canonical form reads back to the same bits, and every file of the
// bad-scene corpus gives the messages its .expected file lists.
#include "mpi_driver/config/scene_json.hpp"

#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "mpi_driver/config/config_reader.hpp"
#include "tests/support/scene_json_errors.hpp"

namespace blockfrag {
namespace {

using nlohmann::json;
using ::testing::HasSubstr;

const std::filesystem::path source_dir = BLOCKFRAG_SOURCE_DIR;

// The paper's section 3 example, written out independently of configs/paper_example.json.
json paper_scene() {
  return json::parse(R"({
    "block": {"half_width": 0.5, "half_height": 1.0},
    "contact": {"friction": 0.6, "restitution": 0.6},
    "ground_motion": {"type": "cosine_pulse", "amplitude_g": 1.0, "period": 2.0, "cycles": 1},
    "duration": 4.0,
    "solver": {"method": "adaptive", "tolerance": 1e-8}})");
}

json with(json document, const std::string& pointer, const json& value) {
  document[JsonPointer(pointer)] = value;
  return document;
}

json without(json document, const std::string& pointer) {
  const JsonPointer path(pointer);
  document[path.parent_pointer()].erase(path.back());
  return document;
}

using testing::scene_errors;

std::uint64_t bits(double x) { return std::bit_cast<std::uint64_t>(x); }

TEST(SceneJson, ReadsThePaperExampleFile) {
  const Scene scene = read_scene_file(source_dir / "configs/paper_example.json");
  EXPECT_EQ(scene.block.half_width, 0.5);
  EXPECT_EQ(scene.block.half_height, 1.0);
  EXPECT_EQ(scene.contact.friction, 0.6);
  EXPECT_EQ(scene.contact.restitution, 0.6);
  const auto* pulse = std::get_if<CosinePulse>(&scene.ground_motion);
  ASSERT_NE(pulse, nullptr);
  EXPECT_EQ(pulse->amplitude_g, 1.0);
  EXPECT_EQ(pulse->period, 2.0);  // lambda = cos(pi t): 2 pi / T = pi
  EXPECT_EQ(pulse->cycles, 1.0);
  EXPECT_EQ(scene.duration, 4.0);
  EXPECT_EQ(scene.solver.method, Method::adaptive);
  EXPECT_EQ(scene.solver.tolerance, 1e-8);
}

TEST(SceneJson, OmittedKeysTakeTheDocumentedDefaults) {
  const json minimal = json::parse(R"({
    "block": {"half_width": 0.25, "half_height": 2},
    "contact": {"friction": 0.8, "restitution": 0},
    "ground_motion": {"type": "sine_pulse", "amplitude_g": -0.4, "period": 0.5},
    "duration": 3})");
  const Scene scene = scene_from_json(minimal, "scene.json");
  EXPECT_EQ(scene.block.mass, 1.0);
  EXPECT_EQ(scene.g, 9.81);
  EXPECT_EQ(std::get<SinePulse>(scene.ground_motion).cycles, 1.0);
  EXPECT_EQ(std::get<SinePulse>(scene.ground_motion).amplitude_g, -0.4);
  EXPECT_EQ(scene.solver.method, Method::adaptive);
  EXPECT_EQ(scene.solver.tolerance, 1e-8);
  EXPECT_EQ(scene.solver.dt, 0.00025);
  EXPECT_EQ(scene.initial.theta, 0.0);
  const SolverSettings contract;  // the budgets' defaults live in engine/scene/scene.hpp
  EXPECT_EQ(scene.solver.max_steps, contract.max_steps);
  EXPECT_EQ(scene.solver.max_events, contract.max_events);
}

TEST(SceneJson, ReadsEveryGroundMotionTypeAndRk4) {
  json rectangular =
      with(paper_scene(), "/ground_motion",
           json{{"type", "rectangular_pulse"}, {"amplitude_g", 0.7}, {"duration", 0.3}});
  rectangular["solver"] = {
      {"method", "rk4"}, {"dt", 0.001}, {"max_steps", 1e6}, {"max_events", 10}};
  const Scene scene = scene_from_json(rectangular, "scene.json");
  EXPECT_EQ(std::get<RectangularPulse>(scene.ground_motion).amplitude_g, 0.7);
  EXPECT_EQ(std::get<RectangularPulse>(scene.ground_motion).duration, 0.3);
  EXPECT_EQ(scene.solver.method, Method::rk4);
  EXPECT_EQ(scene.solver.dt, 0.001);
  EXPECT_EQ(scene.solver.max_steps, 1000000);
  EXPECT_EQ(scene.solver.max_events, 10);

  const Scene still =
      scene_from_json(with(paper_scene(), "/ground_motion", json{{"type", "none"}}), "scene.json");
  EXPECT_TRUE(std::holds_alternative<NoMotion>(still.ground_motion));
}

struct RuleCase {
  const char* pointer;
  json value;
  const char* message;  // "path: rule (got value)"
};

class SceneRule : public ::testing::TestWithParam<RuleCase> {};

TEST_P(SceneRule, IsRefusedWithPathAndRule) {
  const RuleCase& rule = GetParam();
  json document = paper_scene();
  if (std::string(rule.pointer).rfind("/solver/dt", 0) == 0)
    document["solver"] = {{"method", "rk4"}};
  EXPECT_EQ(scene_errors(with(document, rule.pointer, rule.value)),
            std::string("scene.json: ") + rule.message);
}

INSTANTIATE_TEST_SUITE_P(
    EveryRule, SceneRule,
    ::testing::Values(
        RuleCase{"/block/half_width", 0, "/block/half_width: must be in [1e-04, 10000] (got 0)"},
        RuleCase{"/block/half_height", -1.5,
                 "/block/half_height: must be in [1e-04, 10000] (got -1.5)"},
        RuleCase{"/block/half_height", 1e5,
                 "/block/half_height: must be in [1e-04, 10000] (got 1e+05)"},
        RuleCase{"/block/mass", 0.0, "/block/mass: must be > 0 (got 0)"},
        RuleCase{"/contact/friction", -0.3, "/contact/friction: must be in [0, 10000] (got -0.3)"},
        RuleCase{"/contact/friction", 1e308,
                 "/contact/friction: must be in [0, 10000] (got 1e+308)"},
        RuleCase{"/contact/restitution", 1.2, "/contact/restitution: must be in [0, 1] (got 1.2)"},
        RuleCase{"/contact/restitution", -0.1,
                 "/contact/restitution: must be in [0, 1] (got -0.1)"},
        RuleCase{"/ground_motion/period", 0,
                 "/ground_motion/period: must be in [0.001, 1000] (got 0)"},
        RuleCase{"/ground_motion/period", 5e-324,
                 "/ground_motion/period: must be in [0.001, 1000] (got 5e-324)"},
        RuleCase{"/ground_motion/cycles", -1,
                 "/ground_motion/cycles: must be in (0, 10000] (got -1)"},
        RuleCase{"/ground_motion/cycles", 1e9,
                 "/ground_motion/cycles: must be in (0, 10000] (got 1e+09)"},
        RuleCase{"/ground_motion/amplitude_g", 1e308,
                 "/ground_motion/amplitude_g: must be in [-1000, 1000] (got 1e+308)"},
        RuleCase{"/ground_motion/amplitude_g", "NaN",
                 "/ground_motion/amplitude_g: must be a finite number (got \"NaN\"; JSON has no "
                 "NaN or Infinity)"},
        RuleCase{"/ground_motion/type", "cosine",
                 "/ground_motion/type: must be one of \"none\", \"cosine_pulse\", \"sine_pulse\", "
                 "\"rectangular_pulse\", \"record\", \"makris_a\", \"makris_b\", \"makris_c\", "
                 "\"ricker\", "
                 "\"mavroeidis_papageorgiou\" (got \"cosine\")"},
        RuleCase{"/ground_motion/type", "sine_puls",
                 "/ground_motion/type: must be one of \"none\", \"cosine_pulse\", \"sine_pulse\", "
                 "\"rectangular_pulse\", \"record\", \"makris_a\", \"makris_b\", \"makris_c\", "
                 "\"ricker\", "
                 "\"mavroeidis_papageorgiou\" (got \"sine_puls\"; did you mean \"sine_pulse\"?)"},
        RuleCase{"/duration", 0, "/duration: must be in (0, 1e+05] (got 0)"},
        RuleCase{"/duration", "4", "/duration: must be a number, not a string (got \"4\")"},
        RuleCase{"/g", -9.81, "/g: must be in [0.01, 1000] (got -9.81)"},
        RuleCase{"/solver/tolerance", 0, "/solver/tolerance: must be in [1e-14, 0.1] (got 0)"},
        RuleCase{"/solver/tolerance", 1e-300,
                 "/solver/tolerance: must be in [1e-14, 0.1] (got 1e-300)"},
        RuleCase{"/solver/tolerance", 0.2, "/solver/tolerance: must be in [1e-14, 0.1] (got 0.2)"},
        RuleCase{"/solver/method", "euler",
                 "/solver/method: must be one of \"adaptive\", \"rk4\", \"gsl_rkf45\", "
                 "\"gsl_rk8pd\" (got \"euler\")"},
        RuleCase{"/solver/dt", 0, "/solver/dt: must be in [1e-07, 10] (got 0)"},
        RuleCase{"/solver/dt", 1e-300, "/solver/dt: must be in [1e-07, 10] (got 1e-300)"},
        RuleCase{"/solver/dt", 4.5, "/solver/dt: must be <= duration (4) (got 4.5)"},
        RuleCase{"/solver/max_steps", 0, "/solver/max_steps: must be in [1, 1e+10] (got 0)"},
        RuleCase{"/solver/max_steps", 2.5, "/solver/max_steps: must be an integer (got 2.5)"},
        RuleCase{"/solver/max_events", -1, "/solver/max_events: must be in [1, 1e+09] (got -1)"},
        RuleCase{"/initial/theta", 1.6, "/initial/theta: must be in (-pi/2, pi/2) (got 1.6)"},
        RuleCase{"/initial/theta", -1.6, "/initial/theta: must be in (-pi/2, pi/2) (got -1.6)"},
        RuleCase{"/initial/omega", 1e4, "/initial/omega: must be in [-1000, 1000] (got 10000)"},
        RuleCase{"/block", 1, "/block: must be an object (got 1)"},
        RuleCase{"/contact/frction", 0.6,
                 "/contact/frction: unknown key; did you mean \"friction\"?"},
        RuleCase{"/ground_motion/duration", 1.0,
                 "/ground_motion/duration: unknown key for type \"cosine_pulse\" (known keys: "
                 "amplitude_g cycles "
                 "period type)"},
        RuleCase{"/solver/dt", json{{"nested", 1}}, "/solver/dt: must be a number (got an object)"},
        RuleCase{"/durration", 4, "/durration: unknown key; did you mean \"duration\"?"},
        RuleCase{"/effects", "all", "/effects: must be \"auto\" or a list of effects"},
        RuleCase{"/effects", json::array(),
                 "/effects: must be \"auto\" or a non-empty list of effects"},
        RuleCase{"/effects", json{"rocking", "rocking"}, "/effects/1: \"rocking\" is listed twice"},
        RuleCase{"/effects", json{"rockin"},
                 "/effects/0: must be one of \"rocking\", \"sliding\", \"impact\", \"flight\", "
                 "\"vertical\" "
                 "(got \"rockin\"; did you mean \"rocking\"?)"},
        RuleCase{"/effects", json{"sliding", "impact"},
                 "/effects: effects name no model: use [\"rocking\"] or [\"rocking\", \"impact\"] "
                 "(Housner), "
                 "[\"sliding\"] (Newmark), all of rocking, sliding, impact, flight (full), or "
                 "\"auto\""}));

TEST(SceneJson, EffectsNameAModelAndRoundTrip) {
  const Scene housner =
      scene_from_json(with(paper_scene(), "/effects", json{"impact", "rocking"}), "scene.json");
  EXPECT_FALSE(housner.effects.automatic);
  EXPECT_TRUE(housner.effects.rocking && housner.effects.impact);
  EXPECT_FALSE(housner.effects.sliding || housner.effects.flight);
  EXPECT_EQ(scene_to_json(housner)["effects"], json({"rocking", "impact"}));
  const Scene newmark =
      scene_from_json(with(paper_scene(), "/effects", json{"sliding"}), "scene.json");
  EXPECT_EQ(scene_to_json(newmark)["effects"], json({"sliding"}));
  EXPECT_TRUE(
      scene_from_json(with(paper_scene(), "/effects", "auto"), "scene.json").effects.automatic);
  EXPECT_EQ(
      scene_errors(with(paper_scene(), "/effects", json{"rocking", "vertical"})),
      "scene.json: /effects: effects: vertical ground motion needs the full model (rocking, "
      "sliding, impact, flight)\nscene.json: /effects: lists \"vertical\" exactly when the scene "
      "has a vertical_motion");
}

TEST(SceneJson, VerticalMotionTakesAnyGroundMotionTypeAndTheFullModel) {
  const json vertical = {{"type", "rectangular_pulse"}, {"amplitude_g", -0.5}, {"duration", 0.3}};
  const json document = with(paper_scene(), "/vertical_motion", vertical);
  const Scene automatic = scene_from_json(document, "scene.json");
  ASSERT_TRUE(std::holds_alternative<RectangularPulse>(automatic.vertical_motion));
  EXPECT_EQ(std::get<RectangularPulse>(automatic.vertical_motion).amplitude_g, -0.5);
  EXPECT_EQ(scene_to_json(automatic)["vertical_motion"], vertical);
  const json all = {"rocking", "sliding", "impact", "flight", "vertical"};
  EXPECT_EQ(
      scene_to_json(scene_from_json(with(document, "/effects", all), "scene.json"))["effects"],
      all);
  EXPECT_EQ(
      scene_errors(with(document, "/effects", json{"rocking", "sliding", "impact", "flight"})),
      "scene.json: /effects: lists \"vertical\" exactly when the scene has a vertical_motion");
  EXPECT_EQ(scene_errors(with(document, "/vertical_motion/duration", 0)),
            "scene.json: /vertical_motion/duration: must be in [1e-04, 10000] (got 0)");
  EXPECT_FALSE(
      scene_to_json(scene_from_json(paper_scene(), "scene.json")).contains("vertical_motion"));
}

TEST(SceneJson, KeysOfAnotherMethodOrTypeAreUnknown) {
  EXPECT_EQ(scene_errors(with(paper_scene(), "/solver/dt", 0.001)),
            "scene.json: /solver/dt: unknown key for method \"adaptive\" (known keys: max_events "
            "max_steps "
            "method tolerance)");
  EXPECT_THAT(scene_errors(with(paper_scene(), "/ground_motion",
                                json{{"type", "none"}, {"amplitude_g", 1}})),
              HasSubstr("/ground_motion/amplitude_g: unknown key for type \"none\""));
}

TEST(SceneJson, RequiredKeysAreNamed) {
  for (const char* pointer :
       {"/block", "/contact", "/ground_motion", "/block/half_width", "/block/half_height",
        "/contact/friction", "/contact/restitution", "/ground_motion/type",
        "/ground_motion/amplitude_g", "/ground_motion/period"}) {
    EXPECT_EQ(scene_errors(without(paper_scene(), pointer)),
              "scene.json: " + std::string(pointer) + ": is required");
  }
  EXPECT_EQ(scene_errors(with(paper_scene(), "/ground_motion",
                              json{{"type", "rectangular_pulse"}, {"amplitude_g", 1}})),
            "scene.json: /ground_motion/duration: is required");
}

// Without a duration the run settles (at most max_duration); the two are exclusive, and the
// canonical form keeps whichever was given.
TEST(SceneJson, DurationIsOptionalAndExclusiveWithMaxDuration) {
  const Scene settling = scene_from_json(without(paper_scene(), "/duration"), "scene.json");
  EXPECT_FALSE(settling.duration.has_value());
  EXPECT_FALSE(settling.max_duration.has_value());
  const json canonical = scene_to_json(settling);
  EXPECT_FALSE(canonical.contains("duration"));
  EXPECT_FALSE(canonical.contains("max_duration"));

  const Scene capped = scene_from_json(
      with(without(paper_scene(), "/duration"), "/max_duration", 30.0), "scene.json");
  EXPECT_EQ(capped.max_duration, 30.0);
  EXPECT_EQ(scene_to_json(capped).at("max_duration"), 30.0);
  EXPECT_EQ(scene_from_json(scene_to_json(capped), "canonical.json").max_duration, 30.0);

  EXPECT_EQ(scene_errors(with(paper_scene(), "/max_duration", 30.0)),
            "scene.json: /max_duration: give duration (a fixed run) or max_duration (a run to "
            "settle), not both");
  EXPECT_EQ(scene_errors(with(without(paper_scene(), "/duration"), "/max_duration", 0.0)),
            "scene.json: /max_duration: must be in (0, 1e+05] (got 0)");
}

TEST(SceneJson, BoundaryValuesAreAccepted) {
  json document = paper_scene();
  document["contact"] = {{"friction", 0}, {"restitution", 0}};
  document["solver"]["tolerance"] = 0.1;
  document["ground_motion"]["amplitude_g"] = -2.0;  // a reversed pulse
  document["initial"] = {{"theta", -1.5}};
  EXPECT_EQ(scene_errors(document), "(accepted)");
  document["contact"]["restitution"] = 1;
  document["solver"] = {{"method", "rk4"}, {"dt", 4.0}};  // dt == duration
  EXPECT_EQ(scene_errors(document), "(accepted)");
}

TEST(SceneJson, EveryErrorIsReportedTogether) {
  json document = paper_scene();
  document["block"]["half_width"] = -1;
  document["contact"]["restitution"] = 2;
  document["contact"]["frictoin"] = 0.5;
  document["g"] = "9.81";
  document.erase("duration");
  EXPECT_EQ(scene_errors(document),
            "scene.json: /block/half_width: must be in [1e-04, 10000] (got -1)\n"
            "scene.json: /contact/restitution: must be in [0, 1] (got 2)\n"
            "scene.json: /contact/frictoin: unknown key; did you mean \"friction\"?\n"
            "scene.json: /g: must be a number, not a string (got \"9.81\")");
}

TEST(SceneJson, EmbeddedSceneReportsFullPathsIntoTheCallersErrors) {
  const json study = {{"seed", 1}, {"scene", with(paper_scene(), "/contact/friction", -1)}};
  ConfigErrors errors("study.json");
  errors.add(JsonPointer("/seed"), "an earlier error");
  scene_from_json(study["scene"], JsonPointer("/scene"), errors, "");
  try {
    errors.throw_if_any();
    FAIL() << "accepted";
  } catch (const ConfigError& error) {
    EXPECT_EQ(std::string(error.what()),
              "study.json: /seed: an earlier error\n"
              "study.json: /scene/contact/friction: must be in [0, 10000] (got -1)");
  }
}

TEST(SceneJson, RootMustBeAnObject) {
  EXPECT_EQ(scene_errors(json::array()), "scene.json: must be an object (got an array)");
}

TEST(SceneJson, CanonicalFormHasEveryKeyWithDefaults) {
  const json canonical = scene_to_json(scene_from_json(paper_scene(), "scene.json"));
  const json expected = json::parse(R"({
    "effects": "auto",
    "block": {"half_width": 0.5, "half_height": 1.0, "mass": 1.0},
    "contact": {"friction": 0.6, "restitution": 0.6},
    "ground_motion": {"type": "cosine_pulse", "amplitude_g": 1.0, "period": 2.0, "cycles": 1.0},
    "duration": 4.0, "g": 9.81, "initial": {"theta": 0.0},
    "solver": {"method": "adaptive", "tolerance": 1e-8, "max_steps": 50000000, "max_events": 1000000}})");
  EXPECT_EQ(canonical, expected);
}

TEST(SceneJson, AnInitialOmegaIsReadAndWrittenOnlyWhereGiven) {
  json document = paper_scene();
  document["initial"] = {{"theta", 0.1}, {"omega", -0.75}};
  const Scene scene = scene_from_json(document, "scene.json");
  EXPECT_EQ(scene.initial.omega, -0.75);
  EXPECT_EQ(scene_to_json(scene)["initial"], (json{{"theta", 0.1}, {"omega", -0.75}}));
  EXPECT_FALSE(
      scene_to_json(scene_from_json(paper_scene(), "scene.json"))["initial"].contains("omega"));
}

TEST(SceneJson, CanonicalRoundTripIsExact) {
  // Values with no short decimal form, denormals and negative zero must come back bit for bit.
  json document = paper_scene();
  document["block"] = {{"half_width", 1.0 / 3.0}, {"half_height", 0.1 + 0.2}, {"mass", 5e-324}};
  document["contact"] = {{"friction", std::numbers::pi / 7}, {"restitution", 1.0 - 1e-16}};
  document["ground_motion"] = {{"type", "sine_pulse"},
                               {"amplitude_g", -0.0},
                               {"period", std::nextafter(1000.0, 0.0)},
                               {"cycles", 2.5}};
  document["g"] = std::nextafter(9.81, 10.0);
  document["initial"] = {{"theta", std::nextafter(-std::numbers::pi / 2, 0.0)}};
  document["solver"] = {
      {"method", "rk4"}, {"dt", std::nextafter(1e-7, 1.0)}, {"max_steps", 9876543210}};
  const Scene first = scene_from_json(document, "scene.json");
  const json canonical = scene_to_json(first);
  const Scene second = scene_from_json(json::parse(canonical.dump()), "canonical.json");
  EXPECT_EQ(bits(second.block.half_width), bits(1.0 / 3.0));
  EXPECT_EQ(bits(second.block.half_height), bits(0.1 + 0.2));
  EXPECT_EQ(bits(second.block.mass), bits(5e-324));
  EXPECT_EQ(bits(second.contact.friction), bits(std::numbers::pi / 7));
  EXPECT_EQ(bits(second.contact.restitution), bits(1.0 - 1e-16));
  const auto& pulse = std::get<SinePulse>(second.ground_motion);
  EXPECT_EQ(bits(pulse.amplitude_g), bits(-0.0));
  EXPECT_EQ(bits(pulse.period), bits(std::nextafter(1000.0, 0.0)));
  EXPECT_EQ(pulse.cycles, 2.5);
  EXPECT_EQ(bits(second.g), bits(std::nextafter(9.81, 10.0)));
  EXPECT_EQ(bits(second.initial.theta), bits(std::nextafter(-std::numbers::pi / 2, 0.0)));
  EXPECT_EQ(second.solver.method, Method::rk4);
  EXPECT_EQ(bits(second.solver.dt), bits(std::nextafter(1e-7, 1.0)));
  EXPECT_EQ(second.solver.max_steps, 9876543210);
  EXPECT_EQ(scene_to_json(second).dump(), canonical.dump());
}

TEST(SceneJson, GslMethodsTakeATolerance) {
  for (const char* name : {"gsl_rkf45", "gsl_rk8pd"}) {
    const json solver = {{"method", name}, {"tolerance", 1e-6}};
    const Scene scene = scene_from_json(with(paper_scene(), "/solver", solver), "scene.json");
    EXPECT_EQ(scene.solver.method,
              std::string(name) == "gsl_rkf45" ? Method::gsl_rkf45 : Method::gsl_rk8pd);
    EXPECT_EQ(scene.solver.tolerance, 1e-6);
    const json canonical = scene_to_json(scene);
    EXPECT_EQ(canonical["solver"]["method"], name);
    EXPECT_EQ(canonical["solver"]["tolerance"], 1e-6);
    EXPECT_FALSE(canonical["solver"].contains("dt"));
    EXPECT_EQ(scene_to_json(scene_from_json(canonical, "canonical.json")), canonical);
    EXPECT_THAT(scene_errors(with(with(paper_scene(), "/solver", solver), "/solver/dt", 0.01)),
                HasSubstr("/solver/dt: unknown key for method \"" + std::string(name) + "\""));
  }
}

TEST(SceneJson, EveryTypeRoundTrips) {
  for (const json& motion :
       {json{{"type", "none"}},
        json{{"type", "cosine_pulse"}, {"amplitude_g", 0.3}, {"period", 0.7}, {"cycles", 3}},
        json{{"type", "rectangular_pulse"}, {"amplitude_g", -1.1}, {"duration", 0.25}}}) {
    const json canonical =
        scene_to_json(scene_from_json(with(paper_scene(), "/ground_motion", motion), "scene.json"));
    EXPECT_EQ(canonical["ground_motion"], motion);
    EXPECT_EQ(scene_to_json(scene_from_json(canonical, "canonical.json")), canonical);
  }
}

// Each tests/data/bad_scenes/NAME.json is refused with every line of NAME.expected in the message.
TEST(BadScenes, EachGivesItsExpectedMessages) {
  const auto corpus = source_dir / "tests/data/bad_scenes";
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(corpus)) {
    if (entry.path().extension() != ".json") continue;
    ++files;
    auto expected_path = entry.path();
    expected_path.replace_extension(".expected");
    std::ifstream expected(expected_path);
    ASSERT_TRUE(expected) << "no " << expected_path;
    std::string message = "(accepted)";
    try {
      read_scene_file(entry.path());
    } catch (const ConfigError& error) {
      message = error.what();
    }
    int fragments = 0;
    for (std::string fragment; std::getline(expected, fragment);) {
      if (fragment.empty()) continue;
      ++fragments;
      EXPECT_THAT(message, HasSubstr(fragment)) << entry.path();
    }
    EXPECT_GT(fragments, 0) << expected_path;
  }
  EXPECT_GE(files, 15);
}

}  // namespace
}  // namespace blockfrag
