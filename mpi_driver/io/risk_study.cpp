#include "mpi_driver/io/risk_study.hpp"

#include <cmath>
#include <string>

#include <nlohmann/json.hpp>

#include "engine/errors.hpp"
#include "mpi_driver/config/adaptive_design.hpp"
#include "mpi_driver/io/hdf5_reader.hpp"
#include "mpi_driver/io/isolated_fits.hpp"
#include "mpi_driver/io/read_in_child.hpp"

namespace blockfrag {
namespace {

// As fragility_fits.cpp: a study's levels, at most 1,000,000 and two per adaptive batch.
constexpr std::size_t kMaxRiskLevels =
    1'000'000 + 2 * static_cast<std::size_t>(kMaxAdaptiveBatches);
// The canonical config of a record suite lists its records: far below this.
constexpr std::size_t kMaxConfigText = std::size_t{16} << 20;
// The config's cap on bootstrap_resamples (mpi_driver/config/study_config.cpp).
constexpr double kMaxResamples = 100'000;
// Counts are exact in a double up to 2^53.
constexpr double kMaxCount = 9007199254740992.0;

InvalidInput malformed(const std::string& file, const std::string& what) {
  return InvalidInput(file + ": " + what + " (not the layout blockfrag writes)");
}

std::vector<std::int64_t> read_counts(const Hdf5Reader& file, const std::string& path,
                                      std::size_t levels) {
  if (!file.has_object(path)) throw malformed(file.name(), path + " is missing");
  const std::vector<double> values = file.number_dataset(path, kMaxRiskLevels);
  if (values.size() != levels) {
    throw malformed(file.name(), path + " holds " + std::to_string(values.size()) + " values for " +
                                     std::to_string(levels) + " levels");
  }
  std::vector<std::int64_t> result;
  for (const double value : values) {
    if (!(value >= 0.0 && value <= kMaxCount && std::floor(value) == value)) {
      throw malformed(file.name(), path + " holds a value that is not a count");
    }
    result.push_back(static_cast<std::int64_t>(value));
  }
  return result;
}

StateCounts state_counts(const Hdf5Reader& file, const FragilityFit& fit) {
  const std::string group = "/fragility/" + fit.name;
  StateCounts state;
  state.trials = read_counts(file, group + "/trials", fit.im.size());
  state.exceedances = read_counts(file, group + "/exceedances", fit.im.size());
  for (std::size_t j = 0; j < fit.im.size(); ++j) {
    if (state.exceedances[j] > state.trials[j]) {
      throw malformed(file.name(),
                      group + " has more exceedances than trials at level " + std::to_string(j));
    }
  }
  if (file.has_attribute(group, "bootstrap_resamples")) {
    const double resamples = file.number_attribute(group, "bootstrap_resamples");
    if (!(resamples >= 0.0 && resamples <= kMaxResamples && std::floor(resamples) == resamples)) {
      throw malformed(file.name(), group + " attribute bootstrap_resamples is not 0 to 100000");
    }
    state.bootstrap_resamples = static_cast<int>(resamples);
  }
  return state;
}

std::uint64_t config_seed(const Hdf5Reader& file) {
  const std::string text = file.string_attribute("/", "config", kMaxConfigText);
  const auto config = nlohmann::json::parse(text, nullptr, false);
  if (config.is_discarded() || !config.is_object() || !config.contains("seed") ||
      !config["seed"].is_number_unsigned()) {
    throw malformed(file.name(), "the config attribute of / is not a study config with a seed");
  }
  return config["seed"].get<std::uint64_t>();
}

nlohmann::json risk_study_json(const std::filesystem::path& path) {
  const FragilityFits fits = read_fragility_fits(path);
  const Hdf5Reader file(path);
  nlohmann::json states = nlohmann::json::array();
  for (const auto& fit : fits.states) {
    const StateCounts state = state_counts(file, fit);
    states.push_back({{"trials", state.trials},
                      {"exceedances", state.exceedances},
                      {"bootstrap_resamples", state.bootstrap_resamples}});
  }
  const bool cloud = file.has_attribute("/fragility", "scaling") &&
                     file.string_attribute("/fragility", "scaling", 1024).rfind("none", 0) == 0;
  return {{"fits", fits_to_json(fits)},
          {"counts", states},
          {"seed", config_seed(file)},
          {"cloud", cloud}};
}

}  // namespace

RiskStudy read_risk_study_isolated(const std::filesystem::path& path,
                                   std::chrono::milliseconds limit) {
  const std::string answer = read_in_child(path.string(), limit, fits_memory_bytes,
                                           [&] { return risk_study_json(path).dump(); });
  const auto json = nlohmann::json::parse(answer);
  RiskStudy study;
  study.fits = fits_from_json(json.at("fits"), path.string());
  for (const auto& state : json.at("counts")) {
    study.counts.push_back({state.at("trials").get<std::vector<std::int64_t>>(),
                            state.at("exceedances").get<std::vector<std::int64_t>>(),
                            state.at("bootstrap_resamples").get<int>()});
  }
  study.seed = json.at("seed").get<std::uint64_t>();
  study.cloud = json.at("cloud").get<bool>();
  return study;
}

}  // namespace blockfrag
