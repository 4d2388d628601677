// A batch study: the base scene, its random inputs, the intensity measure and its levels, the
// limit states and how the run is kept (seed, output, checkpoint interval). The form
// (configs/example_study.json; every key in docs/studies.md):
//   {"scene": {...a scene file's content, or a record suite as its ground motion...},
//    "inputs": {"friction": {"distribution": "uniform", "min": 0.55, "max": 0.9}, ...,
//               "direction": {"distribution": "random_sign"}},
//    "intensity_measure": {"type": "pga", "from": 0.2, "to": 2.0, "count": 10},
//      with an optional "second": {"type": "pulse_period", "levels": [...]} (a surface's grid),
//    "samples_per_level": 40,
//    "design": "monte_carlo" | "latin_hypercube" | {"adaptive": {...}},
//    "limit_states": [{"name": "overturn", "type": "overturning"},
//                     {"name": "...", "type": "max_rotation", "theta_over_alpha": 0.5},
//                     {"name": "...", "type": "residual_slide", "threshold_m": 0.05}],
//    "seed": 1, "output": "study.h5", "checkpoint_interval_s": 60}
// Each input's distribution must lie inside its parameter's domain
// (engine/scene/parameter_domains.hpp) or be truncated to it; the direction input (default +1)
// gives the motion's sign.
//
// Every error points at its value (`study.json: /intensity_measure/levels/0: must be in (0, 1000]
// (got -0.1)`), all are reported at once, and every cross-field rule is checked before any work.
//
// The canonical config is the document with defaults filled and keys sorted; its hash ties
// checkpoints and outputs to the study. The hash leaves out the keys that change no sample
// ("output", "checkpoint_interval_s", "allowed_failed_fraction"), so a study may be resumed with
// other values of them.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/scene/scene.hpp"
#include "mpi_driver/config/adaptive_design.hpp"
#include "mpi_driver/config/intensity_measure.hpp"
#include "mpi_driver/config/record_suite.hpp"
#include "sampling/designs.hpp"
#include "sampling/distributions.hpp"

namespace blockfrag {

// The scene values a study can draw. Geometry is given either as half_width/half_height or as
// alpha/R (alpha = atan(a / b) in rad, R = sqrt(a^2 + b^2) in m), never both.
enum class StudyInput {
  friction,
  restitution,
  rocking_restitution,  // a given r (engine/contact/rocking_restitution.hpp)
  half_width,
  half_height,
  alpha,
  R,
  period,
  direction
};

// The config key (and the /samples column name) of an input: the enumerator's name ("friction",
// "rocking_restitution", "half_width", "alpha", "R", "period" (s, as in the scene), "direction").
const char* input_key(StudyInput input);

struct StudyInputSpec {
  StudyInput input;
  // For direction: Fixed{+1 or -1}, or Uniform{-1, 1} for a random sign (the sign of the value).
  Distribution distribution;
};

// The interval [low, high] the distribution's values can take: an untruncated normal's is
// unbounded, an untruncated lognormal's starts at 0.
std::pair<double, double> support_of(const Distribution& distribution);

enum class LimitStateKind {
  overturning,     // the block overturned
  max_rotation,    // max |theta| / alpha > threshold, or overturned
  residual_slide,  // |final_slide| > threshold (m)
};

struct LimitState {
  std::string name;
  LimitStateKind kind = LimitStateKind::overturning;
  double threshold = 0.0;  // unused for overturning
  // A block on its side has exceeded every rotation and slide limit: limit states nest, and their
  // curves can be damage states of one component. False counts only the raw measure.
  bool overturned_exceeds = true;
};

const char* limit_state_kind_name(LimitStateKind kind);
// The rule of a limit state's name (it names the HDF5 group /fragility/<name>): a letter, digit
// or '_', then letters, digits, '_', '-' and '.'.
bool valid_limit_state_name(const std::string& name);

struct StudyConfig {
  // Its ground motion is a pulse, or a recorded motion; with a record suite, `suite` holds the
  // records and the base scene's ground motion is none.
  Scene base_scene;
  // The records samples run: the base scene's record_suite, or its one record.
  std::optional<RecordSuite> suite;
  std::vector<StudyInputSpec> inputs;  // in StudyInput order: the /samples columns
  IntensityMeasure intensity;
  std::uint32_t samples_per_level = 1;
  Design design = Design::monte_carlo;  // within a level (an adaptive study's base design)
  // Adaptive stripes (adaptive_design.hpp): the levels above are the first batch.
  std::optional<AdaptiveDesign> adaptive;
  std::vector<LimitState> limit_states;
  std::uint64_t seed = 0;
  std::filesystem::path output;
  double checkpoint_interval_s = 60.0;
  // The fraction of samples that may fail or be rejected before the run's exit code says so (3).
  double allowed_failed_fraction = 0.0;
  // Resamples of the fit's bootstrap (0: none).
  int bootstrap_resamples = 1000;

  nlohmann::json canonical;  // defaults filled, keys sorted
  // Of canonical without "output", "checkpoint_interval_s" and "allowed_failed_fraction": what
  // does not change a sample's result does not change the study's identity.
  std::uint64_t hash = 0;

  std::int64_t total_samples() const {
    return static_cast<std::int64_t>(intensity.level_count()) * samples_per_level;
  }
};

// The largest cloud: its per-sample fit keeps each sample's intensity and verdicts in memory (about
// 9 bytes a sample; a study of stripes streams its records and has no such limit).
inline constexpr std::int64_t kMaxCloudSamples = 100'000'000;
// The largest level of a Latin hypercube: every rank holds the level's permutation of each input
// (4 bytes a sample and input). Monte Carlo draws need no memory and have no such limit.
inline constexpr std::int64_t kMaxLatinHypercubeLevel = 20'000'000;

// The command line's options that replace config values (before canonicalisation and hashing).
struct StudyOverrides {
  std::optional<std::filesystem::path> output;
  std::optional<long> samples_per_level;
};

// Throws ConfigError listing every problem, each as "source: /json/pointer: rule".
StudyConfig parse_study_config(const nlohmann::json& document, const std::string& source,
                               const StudyOverrides& overrides = {});
StudyConfig read_study_config(const std::filesystem::path& path,
                              const StudyOverrides& overrides = {});

// The canonical text (nlohmann's dump of the canonical config: sorted keys, shortest round-trip
// numbers) that is hashed and stored in outputs.
std::string canonical_text(const nlohmann::json& canonical);

}  // namespace blockfrag
