#include "mpi_driver/config/spectrum_config.hpp"

#include <cmath>
#include <numbers>
#include <optional>
#include <span>
#include <string>

#include "engine/motion/ground_motion.hpp"
#include "engine/scene/scene_validation.hpp"
#include "mpi_driver/config/config_reader.hpp"
#include "mpi_driver/config/field_table.hpp"
#include "mpi_driver/config/output_name.hpp"
#include "mpi_driver/config/scene_json.hpp"
#include "mpi_driver/config/spectrum_fields.hpp"
#include "mpi_driver/config/study_hash.hpp"

namespace blockfrag {
namespace {

using nlohmann::json;

// The keys a spectrum shares with a scene: read by the scene reader, at the same JSON paths.
constexpr const char* kSceneKeys[] = {"block", "contact", "effects", "g", "solver"};

// One axis of the grid, its values and where its smallest and largest value were given (for the
// messages of the rules the grid must keep).
struct Axis {
  std::vector<double> values;
  json canonical;
  JsonPointer first_path, last_path;
};

// {"values": [...]} (increasing) or {"from": A, "to": B, "count": N, "spacing": "linear"|"log"};
// `values_fields` is the axis's table of its values.
Axis read_axis(ObjectReader reader, std::span<const Field<AxisValues>> values_fields) {
  Axis axis;
  if (!reader.valid()) return axis;
  static_assert(domain::spectrum_axis_count.high == static_cast<double>(kMaxSpectrumAxis));
  if (reader.has("values")) {
    for (const Field<AxisRange>& field : spectrum_fields::axis_range) {
      if (reader.has(field.key)) {
        reader.add_error(field.key, "give either values or from/to/count, not both");
      }
    }
    AxisValues given;
    if (read_fields<AxisValues>(reader, values_fields, given).valid("values")) {
      axis.values = given.values;
      axis.first_path = reader.path_of("values") / 0;
      axis.last_path = reader.path_of("values") / (given.values.size() - 1);
      axis.canonical = json::object();
      write_fields<AxisValues>(given, values_fields, axis.canonical);
    }
    reader.finish();
    return axis;
  }
  AxisRange range;
  const FieldsRead read = read_fields<AxisRange>(reader, spectrum_fields::axis_range, range);
  reader.finish();
  if (!read.valid("from") || !read.valid("to") || !read.valid("count")) return axis;
  const double from = range.from, to = range.to;
  if (to <= from) {
    reader.add_error("to", "must be greater than from (" + format_number(from) + ")");
    return axis;
  }
  const double n = static_cast<double>(range.count - 1);
  for (long k = 0; k < range.count; ++k) {
    const double x = static_cast<double>(k) / n;
    double value =
        range.log ? std::exp(std::log(from) + x * std::log(to / from)) : from + x * (to - from);
    if (k == 0) value = from;
    if (k == range.count - 1) value = to;
    if (!axis.values.empty() && value <= axis.values.back()) {
      reader.add_error("count", "is too large for the range: its values do not increase");
      axis.values.clear();
      return axis;
    }
    axis.values.push_back(value);
  }
  axis.first_path = reader.path_of("from");
  axis.last_path = reader.path_of("to");
  axis.canonical = json::object();
  write_fields<AxisRange>(range, spectrum_fields::axis_range, axis.canonical);
  return axis;
}

// The block as a scene reads it: half_width/half_height (or a polygon, refused later) as given,
// or alpha and R turned into them; none, after their errors, for alpha and R that cannot be used.
std::optional<json> read_block(const json& document, ConfigErrors& errors) {
  if (!document.is_object() || !document.contains("block")) return std::nullopt;
  const json& block = document["block"];
  if (!block.is_object() || !(block.contains("alpha") || block.contains("R"))) return block;
  ObjectReader reader(block, JsonPointer("/block"), errors);
  for (const char* key : {"half_width", "half_height", "polygon"}) {
    if (reader.has(key)) {
      reader.add_error(key,
                       "give the block as alpha and R, or as half_width and half_height, "
                       "not both");
    }
  }
  BlockShape shape;
  const FieldsRead read = read_fields<BlockShape>(reader, spectrum_fields::block_shape, shape);
  reader.finish();
  if (!read.valid("alpha") || !read.valid("R")) return std::nullopt;
  const double a = shape.R * std::sin(shape.alpha), b = shape.R * std::cos(shape.alpha);
  bool sizes_valid = true;
  for (const auto& [name, value] : {std::pair{"half_width", a}, std::pair{"half_height", b}}) {
    if (!domain::block_length.contains(value)) {
      reader.add_error("R", std::string("with this alpha gives the ") + name + " " +
                                format_number(value) + " m, which " + domain::block_length.rule() +
                                " m");
      sizes_valid = false;
    }
  }
  // Sizes out of their domain are reported here, at the keys the file has: the scene reader would
  // report them again at /block/half_width, a key the file does not have.
  if (!sizes_valid) return std::nullopt;
  return json{{"half_width", a}, {"half_height", b}, {"mass", shape.mass}};
}

std::span<const Field<PulseFamily>> family_shape_fields(SpectrumPulse pulse) {
  if (pulse == SpectrumPulse::cosine || pulse == SpectrumPulse::sine) {
    return spectrum_fields::periodic_family;
  }
  if (pulse == SpectrumPulse::makris_c) return spectrum_fields::makris_c_family;
  return {};
}

std::optional<PulseFamily> read_pulse(ObjectReader reader) {
  if (!reader.valid()) return std::nullopt;
  PulseFamily family;
  const bool typed =
      read_fields<PulseFamily>(reader, spectrum_fields::pulse_type, family).valid("type");
  for (const char* key : {"amplitude_g", "period", "duration", "t0"}) {
    if (reader.has(key)) {
      reader.add_error(key,
                       "is set at each point of the grid (amplitude_ratio, frequency_ratio): "
                       "leave it out");
    }
  }
  if (typed) read_fields<PulseFamily>(reader, family_shape_fields(family.pulse), family);
  reader.finish(typed ? "for type \"" + std::string(spectrum_pulse_name(family.pulse)) + "\""
                      : std::string{});
  if (!typed) return std::nullopt;
  return family;
}

json pulse_to_json(const PulseFamily& family) {
  json out = json::object();
  write_fields<PulseFamily>(family, spectrum_fields::pulse_type, out);
  write_fields<PulseFamily>(family, family_shape_fields(family.pulse), out);
  return out;
}

// The grid's extreme points must give scenes inside the scene domains: the shortest and longest
// pulse, the largest amplitude, the longest run.
void check_grid(const SpectrumConfig& config, const Axis& frequency, const Axis& amplitude,
                ConfigErrors& errors) {
  if (config.map_points() > kMaxSpectrumPoints) {
    errors.add(JsonPointer("/amplitude_ratio"),
               "the grid has " + std::to_string(config.map_points()) + " points (" +
                   std::to_string(frequency.values.size()) + " x " +
                   std::to_string(amplitude.values.size()) + "), more than " +
                   std::to_string(kMaxSpectrumPoints));
  }
  const bool rectangular = config.pulse == SpectrumPulse::rectangular;
  const Domain& time_domain = rectangular ? domain::pulse_duration : domain::pulse_period;
  const std::string time_name = rectangular ? "a pulse length" : "a pulse period";
  const std::string block_note = " for this block (p = " + format_number(config.p()) + " rad/s)";
  const double longest = spectrum_pulse_time(config, config.frequency_ratio.front());
  const double shortest = spectrum_pulse_time(config, config.frequency_ratio.back());
  if (!time_domain.contains(longest)) {
    errors.add(frequency.first_path, "gives " + time_name + " of " + format_number(longest) + " s" +
                                         block_note + ", but it " + time_domain.rule() + " s");
  }
  if (!time_domain.contains(shortest)) {
    errors.add(frequency.last_path, "gives " + time_name + " of " + format_number(shortest) + " s" +
                                        block_note + ", but it " + time_domain.rule() + " s");
  }
  const double top_g = config.amplitude_ratio.back() * config.tan_alpha();
  if (!domain::amplitude_g.contains(top_g)) {
    errors.add(amplitude.last_path, "gives an amplitude of " + format_number(top_g) +
                                        " g (tan alpha = " + format_number(config.tan_alpha()) +
                                        "), but it " + domain::amplitude_g.rule() + " g");
  }
  if (!errors.empty()) return;
  const Scene longest_run = spectrum_scene(config, config.frequency_ratio.front(), 1.0);
  if (!domain::duration.contains(*longest_run.max_duration)) {
    errors.add(frequency.first_path, "with settle_allowance_tau, the longest run would last " +
                                         format_number(*longest_run.max_duration) + " s" +
                                         block_note + ", but it " + domain::duration.rule() + " s");
    return;
  }
  // What the engine itself checks (a fixed RK4 step over the longest run, say), at the corners.
  for (const double f : {config.frequency_ratio.front(), config.frequency_ratio.back()}) {
    for (const double a : {config.amplitude_ratio.front(), config.amplitude_ratio.back()}) {
      try {
        validate_scene(spectrum_scene(config, f, a));
      } catch (const InvalidInput& error) {
        errors.add(JsonPointer(""), "the scene at frequency ratio " + format_number(f) +
                                        " and amplitude ratio " + format_number(a) +
                                        " is invalid: " + error.what());
        return;
      }
    }
  }
}

// The scene's keys go through the scene reader, so their rules and messages are a scene's;
// whether the scene was read without errors and is of a rectangle.
bool read_spectrum_scene(ObjectReader& root, const json& document, const std::string& source,
                         ConfigErrors& errors, SpectrumConfig& config) {
  json scene = json::object();
  if (root.valid()) {
    for (const char* key : kSceneKeys) {
      if (const json* value = root.raw(key)) scene[key] = *value;
    }
  }
  const std::size_t errors_before = errors.size();
  if (const auto block = read_block(document, errors)) {
    scene["block"] = *block;
  } else if (scene.contains("block")) {
    // alpha and R that cannot be used (reported): a stand-in lets the other keys be checked.
    scene["block"] = {{"half_width", 0.5}, {"half_height", 1.0}};
  }
  scene["ground_motion"] = {{"type", "none"}};
  bool scene_valid = false;
  if (root.valid()) {
    config.base_scene =
        scene_from_json(scene, JsonPointer{}, errors, std::filesystem::path(source).parent_path());
    scene_valid = errors.size() == errors_before;
  }
  if (scene_valid && config.base_scene.polygon) {
    root.add_error("block",
                   "a spectrum is of a rectangular block (its alpha and p): give half_width and "
                   "half_height, or alpha and R");
    scene_valid = false;
  }
  return scene_valid;
}

// --output replaces the file's value; its error names the option, not a JSON path.
void read_spectrum_output(ObjectReader& root, const std::string& source, ConfigErrors& errors,
                          const std::optional<std::filesystem::path>& output,
                          SpectrumConfig& config) {
  if (read_fields<SpectrumConfig>(root, spectrum_fields::output, config).valid("output")) {
    if (const auto problem = output_name_problem(config.output.string())) {
      root.add_error("output", *problem);
    }
  } else {
    config.output = std::filesystem::path(source).stem().string() + ".h5";
  }
  if (output) {
    if (const auto problem = output_name_problem(output->string()))
      errors.add_message(source + ": --output: " + *problem);
    config.output = *output;
  }
}

// The hash leaves out the keys that change where a spectrum is written and how often it is saved,
// not what it computes.
void set_spectrum_identity(const PulseFamily& family, const Axis& frequency, const Axis& amplitude,
                           SpectrumConfig& config) {
  const json scene_form = scene_to_json(config.base_scene);
  config.canonical = json::object();
  for (const char* key : kSceneKeys) config.canonical[key] = scene_form[key];
  config.canonical["pulse"] = pulse_to_json(family);
  config.canonical["frequency_ratio"] = frequency.canonical;
  config.canonical["amplitude_ratio"] = amplitude.canonical;
  config.canonical["bisection"] = json::object();
  write_fields<SpectrumConfig>(config, spectrum_fields::bisection, config.canonical["bisection"]);
  config.canonical["minimum_overturning"] = minimum_overturning_to_json(config.minimum_overturning);
  write_fields<SpectrumConfig>(config, spectrum_fields::settle, config.canonical);
  write_fields<SpectrumConfig>(config, spectrum_fields::output, config.canonical);
  write_fields<SpectrumConfig>(config, spectrum_fields::checkpoint, config.canonical);
  json hashed = config.canonical;
  hashed.erase("output");
  hashed.erase("checkpoint_interval_s");
  // The refinement only adds to the map and the bisection: a spec without the key hashes as it
  // did before the key existed, so that its checkpoints and bisection state resume.
  if (hashed["minimum_overturning"] == minimum_overturning_to_json({}))
    hashed.erase("minimum_overturning");
  config.hash = fnv1a64("spectrum " + hashed.dump());
}

}  // namespace

const char* spectrum_pulse_name(SpectrumPulse pulse) {
  return spectrum_pulse_names.name(pulse).data();
}

std::string spectrum_verdict_meaning() {
  return "0 stands (at rest at the end, never overturned), 1 overturns with no impact, "
         "2 overturns after one impact, 3 overturns after two or more impacts, 4 still moving "
         "when the run stopped at its cap (not overturned), 5 failed (engine budget exceeded), "
         "6 rejected (invalid scene)";
}

double SpectrumConfig::tan_alpha() const {
  return base_scene.block.half_width / base_scene.block.half_height;
}
double SpectrumConfig::alpha() const {
  return std::atan2(base_scene.block.half_width, base_scene.block.half_height);
}
double SpectrumConfig::R() const {
  return std::hypot(base_scene.block.half_width, base_scene.block.half_height);
}
double SpectrumConfig::p() const { return std::sqrt(3.0 * base_scene.g / (4.0 * R())); }

double spectrum_pulse_time(const SpectrumConfig& config, double frequency_ratio) {
  const double omega = frequency_ratio * config.p();
  return config.pulse == SpectrumPulse::rectangular ? std::numbers::pi / omega
                                                    : 2.0 * std::numbers::pi / omega;
}

GroundMotion spectrum_pulse(const SpectrumConfig& config, double frequency_ratio,
                            double amplitude_ratio) {
  const double amplitude = amplitude_ratio * config.tan_alpha();
  const double time = spectrum_pulse_time(config, frequency_ratio);
  switch (config.pulse) {
    case SpectrumPulse::cosine: return CosinePulse{amplitude, time, config.cycles};
    case SpectrumPulse::sine: return SinePulse{amplitude, time, config.cycles};
    case SpectrumPulse::rectangular: return RectangularPulse{amplitude, time};
    case SpectrumPulse::makris_a: return MakrisPulseA{amplitude, time};
    case SpectrumPulse::makris_b: return MakrisPulseB{amplitude, time};
    case SpectrumPulse::makris_c: return MakrisPulseC{amplitude, time, config.makris_n};
    case SpectrumPulse::ricker: return RickerWavelet{amplitude, time, std::nullopt};
  }
  throw ContractViolation("spectrum_pulse: unknown pulse family");
}

Scene spectrum_scene(const SpectrumConfig& config, double frequency_ratio, double amplitude_ratio) {
  Scene scene = config.base_scene;
  scene.ground_motion = spectrum_pulse(config, frequency_ratio, amplitude_ratio);
  scene.duration.reset();
  scene.max_duration = GroundMotionPieces(scene.ground_motion, scene.g).end_of_motion() +
                       config.settle_allowance_tau / config.p();
  return scene;
}

SpectrumConfig parse_spectrum_config(const json& document, const std::string& source,
                                     const std::optional<std::filesystem::path>& output) {
  ConfigErrors errors(source);
  ObjectReader root(document, JsonPointer{}, errors);
  SpectrumConfig config;

  const bool scene_valid = read_spectrum_scene(root, document, source, errors, config);
  const auto family = read_pulse(root.required_object("pulse"));
  const Axis frequency =
      read_axis(root.required_object("frequency_ratio"), spectrum_fields::frequency_values);
  const Axis amplitude =
      read_axis(root.required_object("amplitude_ratio"), spectrum_fields::amplitude_values);
  ObjectReader bisection = root.object("bisection");
  read_fields<SpectrumConfig>(bisection, spectrum_fields::bisection, config);
  bisection.finish();
  config.minimum_overturning = read_minimum_overturning(root.object("minimum_overturning"));
  read_fields<SpectrumConfig>(root, spectrum_fields::settle, config);
  read_spectrum_output(root, source, errors, output, config);
  read_fields<SpectrumConfig>(root, spectrum_fields::checkpoint, config);
  root.finish();

  if (family) {
    config.pulse = family->pulse;
    config.cycles = family->cycles;
    config.makris_n = family->n;
  }
  config.frequency_ratio = frequency.values;
  config.amplitude_ratio = amplitude.values;
  if (errors.empty() && scene_valid) check_grid(config, frequency, amplitude, errors);
  errors.throw_if_any();

  set_spectrum_identity(*family, frequency, amplitude, config);
  return config;
}

SpectrumConfig read_spectrum_config(const std::filesystem::path& path,
                                    const std::optional<std::filesystem::path>& output) {
  return parse_spectrum_config(read_json_file(path), path.string(), output);
}

}  // namespace blockfrag
