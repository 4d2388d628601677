// Fuzzes the adaptive level chooser: the input's text up to its first NUL byte is a study
// (parse_json_text, parse_study_config); one the reader accepts with an adaptive design runs up to
// kFuzzBatches batches of the chooser, each level's exceedances the fraction byte / 255 of its
// samples from the bytes after the NUL, one a level. Without such bytes the limit state is a step
// (none below the geometric middle of the first levels, all from it on), whose gap the chooser must
// close and stop within kFuzzBatches batches. Every batch checks the chooser's promises: two
// levels, finite, positive and within the study's level bounds; without a fit none repeats a level
// that told nothing (all or none of its samples exceeded); never a batch past the budget.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "engine/number_text.hpp"
#include "mpi_driver/config/config_reader.hpp"
#include "mpi_driver/config/study_config.hpp"
#include "mpi_driver/study/adaptive_levels.hpp"
#include "postproc/fragility/fragility_curve.hpp"
#include "tests/fuzz/fuzz_support.hpp"

namespace {

using namespace blockfrag;

// Enough for the step's gap between any two levels of the measure's domain to close in doubles
// (its logarithm, at most about 710, shrinks by 3 a batch), and few enough for a fast input.
constexpr int kFuzzBatches = 48;

// Whether the level ran before with all or none of its samples (of every batch that ran it)
// exceeding.
bool told_nothing(const FragilityCurve& curve, double level) {
  std::int64_t trials = 0, exceedances = 0;
  for (std::size_t k = 0; k < curve.im.size(); ++k) {
    if (curve.im[k] != level) continue;
    trials += curve.trials[k];
    exceedances += curve.exceedances[k];
  }
  return trials > 0 && (exceedances == 0 || exceedances == trials);
}

void check_next_levels(const BatchDecision& next, const FragilityCurve& curve,
                       const LevelBounds& bounds) {
  if (next.next_levels.size() != 2) fuzz::finding("a batch without two levels");
  for (const double level : next.next_levels) {
    if (!std::isfinite(level) || !(level > 0.0)) {
      fuzz::finding("a level that is not finite and positive: " + format_number(level));
    }
    if (level < bounds.smallest || level > bounds.largest) {
      fuzz::finding("a level " + format_number(level) + " outside the bounds [" +
                    format_number(bounds.smallest) + ", " + format_number(bounds.largest) + "]");
    }
    if (curve.fit_status != "ok" && told_nothing(curve, level)) {
      fuzz::finding("without a fit (" + curve.fit_status + "), the level " + format_number(level) +
                    " repeats one that told nothing");
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::string source = (fuzz::folder() / "study.json").string();
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  const std::size_t end = std::min(input.find('\0'), input.size());
  const std::string_view text = input.substr(0, end);
  const std::string_view counts = end < input.size() ? input.substr(end + 1) : std::string_view{};
  return fuzz::run([&] {
    const nlohmann::json document = parse_json_text(text, source);
    if (!fuzz::files_stay_inside(document)) return -1;  // not kept in the corpus
    const StudyConfig config = parse_study_config(document, source);
    if (!config.adaptive) return 0;
    const AdaptiveDesign& design = *config.adaptive;
    const LevelBounds bounds = adaptive_level_bounds(config);
    const auto per_level = static_cast<std::int64_t>(config.samples_per_level);
    std::vector<double> levels = config.intensity.levels;
    const double step = std::sqrt(levels.front() * levels.back());
    std::vector<std::int64_t> exceedances;
    std::size_t next_count = 0;
    for (int batch = 0; batch < kFuzzBatches; ++batch) {
      while (exceedances.size() < levels.size()) {
        const double level = levels[exceedances.size()];
        if (counts.empty()) {
          exceedances.push_back(level < step ? 0 : per_level);
        } else {
          const auto byte = static_cast<unsigned char>(counts[next_count++ % counts.size()]);
          exceedances.push_back(std::llround(static_cast<double>(per_level) * byte / 255.0));
        }
      }
      const FragilityCurve curve = fragility_from_counts(
          levels, std::vector<std::int64_t>(levels.size(), per_level), exceedances);
      const auto samples = static_cast<std::int64_t>(levels.size()) * per_level;
      const BatchDecision next =
          decide_next_batch(design, curve, levels, samples, 2 * per_level, bounds);
      if (next.stop) return 0;
      if (samples + 2 * per_level > design.max_samples) fuzz::finding("a batch past the budget");
      check_next_levels(next, curve, bounds);
      levels.insert(levels.end(), next.next_levels.begin(), next.next_levels.end());
    }
    if (counts.empty()) {
      fuzz::finding("a step's batches did not stop within " + std::to_string(kFuzzBatches) +
                    " batches; the last levels " + format_number(levels[levels.size() - 2]) +
                    " and " + format_number(levels.back()));
    }
    return 0;
  });
}
