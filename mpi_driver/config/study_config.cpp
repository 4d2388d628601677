#include "mpi_driver/config/study_config.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <type_traits>

#include "engine/contact/model_choice.hpp"
#include "engine/motion/ground_motion.hpp"
#include "engine/motion/intensity_measures.hpp"
#include "engine/scene/block_geometry.hpp"
#include "engine/scene/parameter_domains.hpp"
#include "engine/scene/seat.hpp"
#include "mpi_driver/config/config_reader.hpp"
#include "mpi_driver/config/distribution_json.hpp"
#include "mpi_driver/config/input_file.hpp"
#include "mpi_driver/config/output_name.hpp"
#include "mpi_driver/config/scene_json.hpp"
#include "mpi_driver/config/stripe_scale.hpp"
#include "mpi_driver/config/study_crest_check.hpp"
#include "mpi_driver/config/study_fields.hpp"
#include "mpi_driver/config/study_hash.hpp"
#include "mpi_driver/config/study_limit_states.hpp"
#include "sampling/validation.hpp"

namespace blockfrag {
namespace {

using nlohmann::json;

constexpr double infinity = std::numeric_limits<double>::infinity();

constexpr StudyInput all_inputs[] = {
    StudyInput::friction,   StudyInput::restitution, StudyInput::rocking_restitution,
    StudyInput::half_width, StudyInput::half_height, StudyInput::alpha,
    StudyInput::R,          StudyInput::period,      StudyInput::reservoir_level,
    StudyInput::direction};

// The domain every sample of an input must stay within: the scene parameter's it sets.
const Domain& input_domain(StudyInput input) {
  switch (input) {
    case StudyInput::friction: return domain::friction;
    case StudyInput::restitution: return domain::restitution;
    case StudyInput::rocking_restitution: return domain::rocking_restitution;
    case StudyInput::half_width:
    case StudyInput::half_height:
    case StudyInput::R: return domain::block_length;
    case StudyInput::alpha: return domain::alpha;
    case StudyInput::period: return domain::pulse_period;
    case StudyInput::reservoir_level: return domain::reservoir_level;
    case StudyInput::direction: break;
  }
  throw ContractViolation("a random sign has no domain");
}

// The distribution's support [low, high] inside the domain; an untruncated lognormal's support
// starts at 0 excluded: it meets a domain open at 0.
bool within(const Domain& domain, double low, double high, bool log_normal) {
  const bool open_at_zero = log_normal && low == 0.0 && domain.low == 0.0 && !domain.low_inclusive;
  return (domain.contains(low) || open_at_zero) && domain.contains(high);
}

// direction: {"distribution": "random_sign"} or {"distribution": "fixed", "value": 1 or -1}.
std::optional<Distribution> read_direction(ObjectReader reader) {
  DirectionLaw law;
  if (!read_fields<DirectionLaw>(reader, study_fields::direction_law, law).valid("distribution")) {
    return std::nullopt;
  }
  std::optional<Distribution> distribution;
  if (!law.fixed) {
    distribution = Uniform{-1.0, 1.0};
  } else if (read_fields<DirectionLaw>(reader, study_fields::fixed_direction, law).valid("value")) {
    distribution = Fixed{law.value};
  }
  reader.finish("for distribution \"" + std::string(direction_law_names.name(law.fixed)) + "\"");
  return distribution;
}

// A direction's random sign is drawn as Uniform{-1, 1}: its name says what it is.
json direction_to_json(const Distribution& distribution) {
  const auto* fixed = std::get_if<Fixed>(&distribution);
  const DirectionLaw law{fixed != nullptr, fixed ? fixed->value : 1.0};
  json out = json::object();
  write_fields<DirectionLaw>(law, study_fields::direction_law, out);
  if (law.fixed) write_fields<DirectionLaw>(law, study_fields::fixed_direction, out);
  return out;
}

// Why a study cannot draw the block's size, if it cannot: sampling draws a rectangle's sizes, so a
// polygon keeps its shape (friction, restitution, period and direction still vary), and so does a
// block on a seat, which fits one block at rest (another size would float above it or sink into
// it).
const char* fixed_geometry(const Scene& base) {
  if (base.polygon) {
    return "varies a rectangle's size, but /scene/block is a polygon (studies keep a polygon's "
           "shape)";
  }
  if (base.seat) {
    return "varies the block's size, but /scene/seat fixes the block's geometry (a seat fits one "
           "block at rest)";
  }
  return nullptr;
}

// A pool level needs a reservoir to set, at least as deep as the water any level puts against the
// block.
void check_reservoir_level(ObjectReader& reader, const Scene& base, const StudyConfig& config) {
  if (!base.reservoir) {
    reader.add_error("reservoir_level",
                     "sets the reservoir's level, but /scene has no reservoir: give one");
    return;
  }
  for (const auto& spec : config.inputs) {
    if (spec.input != StudyInput::reservoir_level) continue;
    const double highest = support_of(spec.distribution).second;
    const double wetted = highest - lowest_block_y(base);
    if (!(base.reservoir->depth >= wetted)) {
      reader.add_error("reservoir_level", "reaches " + format_number(highest) + ", which puts " +
                                              format_number(wetted) +
                                              " m of water against the block, more than "
                                              "/scene/reservoir/depth (" +
                                              format_number(base.reservoir->depth) + " m)");
    }
  }
}

void read_inputs(ObjectReader reader, const Scene& base, bool scene_valid, StudyConfig& config) {
  for (const StudyInput input : all_inputs) {
    const std::string key = input_key(input);
    if (!reader.has(key)) continue;
    ObjectReader spec = reader.required_object(key);
    if (!spec.valid()) continue;
    const auto distribution =
        input == StudyInput::direction ? read_direction(spec) : read_distribution(spec);
    if (!distribution) continue;
    const auto [low, high] = support_of(*distribution);
    if (input != StudyInput::direction &&
        !within(input_domain(input), low, high, std::holds_alternative<LogNormal>(*distribution))) {
      reader.add_error(key, "every value " + input_domain(input).rule() +
                                ", but this distribution reaches [" + format_number(low) + ", " +
                                format_number(high) +
                                "] (truncate it with \"lower\"/\"upper\" or narrow its range)");
    }
    config.inputs.push_back({input, *distribution});
  }
  reader.finish();

  const auto has = [&](StudyInput input) {
    for (const auto& spec : config.inputs) {
      if (spec.input == input) return true;
    }
    return false;
  };
  if ((has(StudyInput::alpha) || has(StudyInput::R)) &&
      (has(StudyInput::half_width) || has(StudyInput::half_height))) {
    reader.add_error(has(StudyInput::alpha) ? "alpha" : "R",
                     "give the geometry either as half_width/half_height or as alpha/R, not both");
  }
  if (!scene_valid) return;
  if (const char* fixed = fixed_geometry(base)) {
    for (const StudyInput input :
         {StudyInput::half_width, StudyInput::half_height, StudyInput::alpha, StudyInput::R}) {
      if (has(input)) reader.add_error(input_key(input), fixed);
    }
  }
  if (has(StudyInput::rocking_restitution) && !has_rocking_impacts(base.effects)) {
    reader.add_error("rocking_restitution",
                     "needs a model with rocking impacts: /scene/effects \"auto\", the full "
                     "model's or [\"rocking\", \"impact\"]");
  }
  const bool has_motion = config.suite || !std::holds_alternative<NoMotion>(base.ground_motion);
  const bool periodic = std::holds_alternative<CosinePulse>(base.ground_motion) ||
                        std::holds_alternative<SinePulse>(base.ground_motion);
  if (has(StudyInput::period) && !periodic) {
    reader.add_error("period", "needs a cosine_pulse or sine_pulse in /scene/ground_motion");
  }
  if (has(StudyInput::reservoir_level)) check_reservoir_level(reader, base, config);
  if (has(StudyInput::direction) && !has_motion) {
    reader.add_error("direction",
                     "needs a ground motion in /scene/ground_motion (its type is \"none\")");
  }
}

// A scene's errors come back with paths inside the scene; put them under /scene. A record suite
// (studies only) is read here; the scene reader sees no ground motion in its place.
void read_scene(const json& value, const std::string& source, ConfigErrors& errors,
                StudyConfig& config, bool& valid) {
  json scene = value;
  // Any other type, a number included, is the scene reader's to judge.
  const bool suite_given =
      value.is_object() && value.contains("ground_motion") && value["ground_motion"].is_object() &&
      value["ground_motion"].contains("type") && value["ground_motion"]["type"] == "record_suite";
  if (suite_given) {
    ObjectReader reader(value["ground_motion"], JsonPointer("/scene/ground_motion"), errors);
    reader.required_choice("type", {"record_suite"});
    config.suite = read_record_suite(reader, std::filesystem::path(source).parent_path());
    reader.finish("for type \"record_suite\"");
    scene["ground_motion"] = {{"type", "none"}};
  }
  try {
    config.base_scene = scene_from_json(scene, source);
    if (const auto* record = std::get_if<RecordedMotion>(&config.base_scene.ground_motion)) {
      // One record is a suite of one: samples run it scaled to their intensity.
      config.suite = RecordSuite{{SuiteRecord{record->file,
                                              record->record,
                                              {},
                                              nullptr,
                                              1.0,
                                              record_content_hash(*record->record),
                                              {}}}};
    }
    valid = !suite_given || config.suite.has_value();
  } catch (const ConfigError& error) {
    const std::string prefix = source + ": ";
    for (const auto& message : error.messages()) {
      if (message.rfind(prefix + "/", 0) == 0) {
        errors.add_message(prefix + "/scene" + message.substr(prefix.size()));
      } else if (message.rfind(prefix, 0) == 0) {
        errors.add_message(prefix + "/scene: " + message.substr(prefix.size()));
      } else {
        errors.add_message(message);
      }
    }
  }
}

// An adaptive study narrows one limit state's stripes fit: a limit state it has, of stripes, with a
// budget that holds its first batch.
void check_adaptive(ObjectReader& root, StudyConfig& config) {
  AdaptiveDesign& adaptive = *config.adaptive;
  const JsonPointer path = root.path_of("design") / "adaptive";
  if (adaptive.limit_state.empty() && !config.limit_states.empty()) {
    adaptive.limit_state = config.limit_states.front().name;
  }
  const bool known =
      std::any_of(config.limit_states.begin(), config.limit_states.end(),
                  [&](const LimitState& s) { return s.name == adaptive.limit_state; });
  if (!known && !config.limit_states.empty()) {
    std::string message = printable_excerpt(adaptive.limit_state);
    message.insert(message.begin(), '"');
    message += "\" is not a limit state";
    root.errors().add(path / "limit_state", message);
  }
  if (config.intensity.cloud) {
    root.errors().add(path, "places stripes: a cloud (\"scaling\": \"none\") has none to place");
  }
  const auto first_batch = static_cast<std::int64_t>(config.intensity.levels.size()) *
                           static_cast<std::int64_t>(config.samples_per_level);
  const std::int64_t batch = 2 * static_cast<std::int64_t>(config.samples_per_level);
  if (adaptive.max_samples > 0 && adaptive.max_samples < first_batch) {
    root.errors().add(path / "max_samples", "must hold the first batch, the intensity levels' " +
                                                std::to_string(first_batch) + " samples");
  } else if ((adaptive.max_samples - first_batch) / batch > kMaxAdaptiveBatches) {
    root.errors().add(path / "max_samples",
                      "allows " + std::to_string((adaptive.max_samples - first_batch) / batch) +
                          " batches of 2 levels x samples_per_level; at most " +
                          std::to_string(kMaxAdaptiveBatches) +
                          ": raise samples_per_level or lower max_samples");
  }
}

// A surface's second axis sets each cell's pulse period: the scene needs a pulse that has one, and
// nothing else may set it.
void check_surface(ObjectReader& root, const StudyConfig& config, bool scene_valid) {
  const JsonPointer path = JsonPointer("/intensity_measure/second");
  const bool periodic = std::holds_alternative<CosinePulse>(config.base_scene.ground_motion) ||
                        std::holds_alternative<SinePulse>(config.base_scene.ground_motion);
  if (config.suite) {
    root.errors().add(path,
                      "sets the pulse's period, but /scene/ground_motion is a record (a "
                      "record's periods are its own)");
  } else if (scene_valid && !periodic) {
    root.errors().add(path,
                      "sets the pulse's period: it needs a cosine_pulse or sine_pulse in "
                      "/scene/ground_motion");
  }
  for (const auto& spec : config.inputs) {
    if (spec.input == StudyInput::period) {
      root.errors().add(JsonPointer("/inputs/period"),
                        "draws the pulse's period, which /intensity_measure/second sets for each "
                        "cell of the grid: remove one of them");
    }
  }
  if (config.adaptive) {
    root.errors().add(root.path_of("design") / "adaptive",
                      "places stripes of one measure: a surface's grid "
                      "(/intensity_measure/second) is fixed");
  }
}

json canonical_json(const StudyConfig& config) {
  json inputs = json::object();
  for (const auto& spec : config.inputs)
    inputs[input_key(spec.input)] = spec.input == StudyInput::direction
                                        ? direction_to_json(spec.distribution)
                                        : distribution_to_json(spec.distribution);
  json limit_states = json::array();
  for (const auto& state : config.limit_states) limit_states.push_back(limit_state_to_json(state));
  json scene = scene_to_json(config.base_scene);
  if (config.suite && std::holds_alternative<NoMotion>(config.base_scene.ground_motion)) {
    scene["ground_motion"] = record_suite_to_json(*config.suite);
  } else if (config.suite) {  // one record: its content enters the study's identity too
    scene["ground_motion"]["content_hash"] =
        hash_to_hex(config.suite->records.front().content_hash);
  }
  json out = {{"scene", scene},
              {"inputs", inputs},
              {"intensity_measure", intensity_measure_to_json(config.intensity)},
              {"design", config.adaptive ? adaptive_design_to_json(*config.adaptive)
                                         : json(std::string(design_names.name(config.design)))},
              {"limit_states", limit_states}};
  write_fields<StudyConfig>(config, study_fields::run, out);
  write_fields<StudyConfig>(config, study_fields::samples, out);
  write_fields<StudyConfig>(config, study_fields::seed, out);
  write_fields<StudyConfig>(config, study_fields::output, out);
  return out;
}

// The scene, or the error that it is missing; whether it was read without errors.
bool read_study_scene(ObjectReader& root, const std::string& source, ConfigErrors& errors,
                      StudyConfig& config) {
  bool scene_valid = false;
  if (const json* scene = root.raw("scene")) {
    read_scene(*scene, source, errors, config, scene_valid);
  } else {
    root.required_object("scene");
  }
  return scene_valid;
}

// The measure the levels are of must be one the scene's ground motion has; a record suite is
// measured here, once its measure is known.
void read_study_intensity(ObjectReader& root, ConfigErrors& errors, bool scene_valid,
                          StudyConfig& config) {
  const bool pulse = !config.suite;
  // A pulse's level is its amplitude in g, but the Mavroeidis-Papageorgiou pulse is given by its
  // velocity: its levels are of its PGA, or of another measure when asked.
  const bool velocity_pulse =
      std::holds_alternative<MavroeidisPapageorgiouPulse>(config.base_scene.ground_motion);
  config.intensity =
      read_intensity_measure(root.required_object("intensity_measure"),
                             pulse && !velocity_pulse ? ImType::pulse_amplitude : ImType::pga);
  if (velocity_pulse && config.intensity.type == ImType::pulse_amplitude) {
    root.errors().add(JsonPointer("/intensity_measure/type"),
                      "a Mavroeidis-Papageorgiou pulse has no amplitude in g: use \"pga\" (the "
                      "default), \"pgv\", \"sa\" or \"pga_over_g_tan_alpha\"");
  }
  if (scene_valid && pulse && std::holds_alternative<NoMotion>(config.base_scene.ground_motion)) {
    root.add_error("intensity_measure",
                   "scales the ground motion, but /scene/ground_motion has type \"none\"");
  }
  if (!pulse && config.intensity.type == ImType::pulse_amplitude) {
    root.errors().add(JsonPointer("/intensity_measure/type"),
                      "a record has no pulse amplitude: use \"pga\", \"pgv\", \"sa\" or "
                      "\"pga_over_g_tan_alpha\"");
  } else if (!pulse && errors.empty()) {
    measure_suite(config, errors,
                  std::holds_alternative<RecordedMotion>(config.base_scene.ground_motion));
  }
  if (const auto* mp = std::get_if<MavroeidisPapageorgiouPulse>(&config.base_scene.ground_motion);
      scene_valid && mp && mp->velocity_amplitude == 0.0) {
    root.add_error("intensity_measure",
                   "scales the pulse's peak acceleration, but /scene/ground_motion has "
                   "velocity_amplitude 0");
  }
}

// --samples-per-level replaces the file's value; its error names the option, not a JSON path.
void read_samples_per_level(ObjectReader& root, const std::string& source, ConfigErrors& errors,
                            const StudyOverrides& overrides, StudyConfig& config) {
  read_fields<StudyConfig>(root, study_fields::samples, config);
  if (overrides.samples_per_level) {
    const Range samples_range = Range::of(domain::samples_per_level);
    if (!samples_range.contains(static_cast<double>(*overrides.samples_per_level))) {
      errors.add_message(source + ": --samples-per-level: " + samples_range.rule() + " (got " +
                         std::to_string(*overrides.samples_per_level) + ")");
    }
    config.samples_per_level = static_cast<std::uint32_t>(*overrides.samples_per_level);
  }
}

// "design" is a name, or an object that makes the study adaptive around a base design.
void read_study_design(ObjectReader& root, ConfigErrors& errors, StudyConfig& config) {
  if (const json* design = root.raw("design"); design && design->is_object()) {
    ObjectReader object(*design, root.path_of("design"), errors);
    config.adaptive = read_adaptive_design(object.required_object("adaptive"));
    object.finish();
    config.design = config.adaptive->base;
  } else {
    const auto name =
        root.has("design") ? root.required_choice("design", design_names.names) : std::nullopt;
    if (name) config.design = *design_names.value(*name);
  }
}

// --output replaces the file's value; its error names the option, not a JSON path.
void read_study_output(ObjectReader& root, const std::string& source, ConfigErrors& errors,
                       const StudyOverrides& overrides, StudyConfig& config) {
  const bool output = read_fields<StudyConfig>(root, study_fields::output, config).valid("output");
  if (output) {
    if (const auto problem = output_name_problem(config.output.string())) {
      root.add_error("output", *problem);
    }
  }
  if (overrides.output) {
    if (const auto problem = output_name_problem(overrides.output->string())) {
      errors.add_message(source + ": --output: " + *problem);
    }
    config.output = *overrides.output;
  } else if (!output) {
    // Without an output key the study writes STUDY.h5 in the working folder.
    config.output = std::filesystem::path(source).stem().string() + ".h5";
  }
}

// Limits that only a valid config can be measured against: what every rank or rank 0 must hold.
void check_study_size(ConfigErrors& errors, const StudyConfig& config) {
  if (errors.empty() && config.design == Design::latin_hypercube &&
      config.samples_per_level > kMaxLatinHypercubeLevel) {
    errors.add(JsonPointer("/samples_per_level"),
               "a Latin hypercube level of " + std::to_string(config.samples_per_level) +
                   " samples, more than the " + std::to_string(kMaxLatinHypercubeLevel) +
                   " whose permutations every rank holds; use \"design\": \"monte_carlo\" (as "
                   "good at this size) or fewer samples per level");
  }
  if (errors.empty() && config.intensity.cloud && config.total_samples() > kMaxCloudSamples) {
    errors.add(JsonPointer("/samples_per_level"),
               "a cloud of " + std::to_string(config.total_samples()) + " samples, more than the " +
                   std::to_string(kMaxCloudSamples) +
                   " whose per-sample fit rank 0 can hold; split it into several studies");
  }
}

// The hash leaves out the keys that change where and how a study runs, not what it computes.
void set_study_identity(StudyConfig& config) {
  config.canonical = canonical_json(config);
  json hashed = config.canonical;
  hashed.erase("output");
  hashed.erase("checkpoint_interval_s");
  hashed.erase("allowed_failed_fraction");
  config.hash = fnv1a64(canonical_text(hashed));
}

}  // namespace

std::pair<double, double> support_of(const Distribution& distribution) {
  return std::visit(
      [](const auto& d) -> std::pair<double, double> {
        using T = std::decay_t<decltype(d)>;
        if constexpr (std::is_same_v<T, Fixed>) return {d.value, d.value};
        if constexpr (std::is_same_v<T, Uniform>) return {d.min, d.max};
        if constexpr (std::is_same_v<T, Normal>)
          return {d.lower.value_or(-infinity), d.upper.value_or(infinity)};
        if constexpr (std::is_same_v<T, LogNormal>)
          return {d.lower.value_or(0.0), d.upper.value_or(infinity)};
      },
      distribution);
}

const char* input_key(StudyInput input) {
  switch (input) {
    case StudyInput::friction: return "friction";
    case StudyInput::restitution: return "restitution";
    case StudyInput::rocking_restitution: return "rocking_restitution";
    case StudyInput::half_width: return "half_width";
    case StudyInput::half_height: return "half_height";
    case StudyInput::alpha: return "alpha";
    case StudyInput::R: return "R";
    case StudyInput::period: return "period";
    case StudyInput::reservoir_level: return "reservoir_level";
    case StudyInput::direction: return "direction";
  }
  return "";
}

std::string canonical_text(const json& canonical) { return canonical.dump(); }

StudyConfig parse_study_config(const json& document, const std::string& source,
                               const StudyOverrides& overrides) {
  ConfigErrors errors(source);
  ObjectReader root(document, JsonPointer{}, errors);
  StudyConfig config;

  const bool scene_valid = read_study_scene(root, source, errors, config);
  if (root.has("inputs"))
    read_inputs(root.required_object("inputs"), config.base_scene, scene_valid, config);
  read_study_intensity(root, errors, scene_valid, config);
  read_samples_per_level(root, source, errors, overrides, config);
  read_study_design(root, errors, config);
  read_limit_states(root.required_array("limit_states"), root, config, scene_valid);
  if (config.adaptive) check_adaptive(root, config);
  if (config.intensity.surface()) check_surface(root, config, scene_valid);
  read_fields<StudyConfig>(root, study_fields::seed, config);
  read_study_output(root, source, errors, overrides, config);
  read_fields<StudyConfig>(root, study_fields::run, config);
  root.finish();
  check_study_size(errors, config);
  if (errors.empty()) check_study_crest(config, errors);
  errors.throw_if_any();

  set_study_identity(config);
  return config;
}

StudyConfig read_study_config(const std::filesystem::path& path, const StudyOverrides& overrides) {
  return parse_study_config(read_json_file(path), path.string(), overrides);
}

}  // namespace blockfrag
