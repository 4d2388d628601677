#include "mpi_driver/io/isolated_fits.hpp"

#include <charconv>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/errors.hpp"
#include "engine/number_text.hpp"
#include "mpi_driver/io/read_in_child.hpp"

namespace blockfrag {
namespace {

using Json = nlohmann::json;

// Numbers travel as their shortest exact text: JSON has no NaN (an unfitted median) or infinity.
Json number_text(double value) { return format_number(value); }

double text_number(const Json& text) {
  const auto& value = text.get_ref<const std::string&>();
  double number = 0.0;
  const auto result = std::from_chars(value.data(), value.data() + value.size(), number);
  if (result.ec != std::errc() || result.ptr != value.data() + value.size()) {
    throw ContractViolation("isolated fits: \"" + value + "\" is not a number");
  }
  return number;
}

Json numbers_text(const std::vector<double>& values) {
  Json list = Json::array();
  for (const double value : values) list.push_back(number_text(value));
  return list;
}

std::vector<double> text_numbers(const Json& list) {
  std::vector<double> values;
  values.reserve(list.size());
  for (const auto& text : list) values.push_back(text_number(text));
  return values;
}

Json optional_text(const std::optional<double>& value) {
  return value ? number_text(*value) : Json(nullptr);
}

std::optional<double> text_optional(const Json& text) {
  if (text.is_null()) return std::nullopt;
  return text_number(text);
}

}  // namespace

// The reader's texts are printable ASCII; the source, a path, is not sent.
Json fits_to_json(const FragilityFits& fits) {
  Json states = Json::array();
  for (const auto& state : fits.states) {
    states.push_back({{"name", state.name},
                      {"type", state.type},
                      {"threshold", number_text(state.threshold)},
                      {"median", number_text(state.median)},
                      {"beta", number_text(state.beta)},
                      {"fit_status", state.fit_status},
                      {"median_ci", numbers_text(state.median_ci)},
                      {"beta_ci", numbers_text(state.beta_ci)},
                      {"deviance", optional_text(state.deviance)},
                      {"gof_p_value", optional_text(state.gof_p_value)},
                      {"overturned_exceeds", state.overturned_exceeds},
                      {"im", numbers_text(state.im)},
                      {"nested_median", number_text(state.nested_median)}});
  }
  return {{"config_hash", fits.config_hash},
          {"im_name", fits.im_name},
          {"im_units", fits.im_units},
          {"im_label", fits.im_label},
          {"im_period_s", optional_text(fits.im_period_s)},
          {"im_damping", optional_text(fits.im_damping)},
          {"states", states},
          {"crossing_pairs", fits.crossing_pairs},
          {"nested_status", fits.nested_status},
          {"nested_beta", number_text(fits.nested_beta)},
          {"common_beta", fits.common_beta}};
}

FragilityFits fits_from_json(const Json& json, const std::string& source) {
  FragilityFits fits;
  fits.source = source;
  fits.config_hash = json.at("config_hash").get<std::string>();
  fits.im_name = json.at("im_name").get<std::string>();
  fits.im_units = json.at("im_units").get<std::string>();
  fits.im_label = json.at("im_label").get<std::string>();
  fits.im_period_s = text_optional(json.at("im_period_s"));
  fits.im_damping = text_optional(json.at("im_damping"));
  for (const auto& state : json.at("states")) {
    FragilityFit fit;
    fit.name = state.at("name").get<std::string>();
    fit.type = state.at("type").get<std::string>();
    fit.threshold = text_number(state.at("threshold"));
    fit.median = text_number(state.at("median"));
    fit.beta = text_number(state.at("beta"));
    fit.fit_status = state.at("fit_status").get<std::string>();
    fit.median_ci = text_numbers(state.at("median_ci"));
    fit.beta_ci = text_numbers(state.at("beta_ci"));
    fit.deviance = text_optional(state.at("deviance"));
    fit.gof_p_value = text_optional(state.at("gof_p_value"));
    fit.overturned_exceeds = state.at("overturned_exceeds").get<bool>();
    fit.im = text_numbers(state.at("im"));
    fit.nested_median = text_number(state.at("nested_median"));
    fits.states.push_back(std::move(fit));
  }
  fits.crossing_pairs =
      json.at("crossing_pairs").get<std::vector<std::pair<std::string, std::string>>>();
  fits.nested_status = json.at("nested_status").get<std::string>();
  fits.nested_beta = text_number(json.at("nested_beta"));
  fits.common_beta = json.at("common_beta").get<bool>();
  return fits;
}

FragilityFits read_fragility_fits_isolated(const std::filesystem::path& path,
                                           std::chrono::milliseconds limit) {
  const std::string answer = read_in_child(path.string(), limit, fits_memory_bytes, [&] {
    return fits_to_json(read_fragility_fits(path)).dump();
  });
  return fits_from_json(Json::parse(answer), path.string());
}

}  // namespace blockfrag
