#include "mpi_driver/io/fragility_export.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include <nlohmann/json.hpp>

#include "blockfrag/version.hpp"
#include "engine/errors.hpp"

namespace blockfrag {
namespace {

// The limits of OpenQuake's identifiers (valid.py: MAX_ID_LENGTH).
constexpr std::size_t max_identifier_length = 75;

// The measure as a tool names it, and the factor from blockfrag's unit to the tool's.
struct ToolMeasure {
  std::string pelicun_type;
  std::string pelicun_unit;
  std::string openquake_imt;
  std::string openquake_unit;
  double openquake_scale = 1.0;
};

std::string brief(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.4g", value);
  return buffer;
}

// A period as both tools write it: shortest fixed notation, with a decimal point ("1.0", "0.2").
std::string period_text(double period) {
  char buffer[64];
  const auto result =
      std::to_chars(buffer, buffer + sizeof buffer, period, std::chars_format::fixed);
  // Too long in fixed notation (no study's period is): the shortest notation then.
  if (result.ec != std::errc()) return exact_number(period);
  std::string text(buffer, result.ptr);
  if (text.find('.') == std::string::npos) text += ".0";
  return text;
}

ToolMeasure tool_measure(const FragilityFits& fits, const std::string& tool) {
  const auto refuse = [&](const std::string& why) {
    return InvalidInput(fits.source + ": " + why + ", so its fits cannot be exported to " + tool);
  };
  const auto require_unit = [&](const std::string& unit) {
    if (fits.im_units != unit) {
      throw refuse("the intensity measure " + fits.im_name + " is in \"" + fits.im_units +
                   "\", not \"" + unit + "\"");
    }
  };
  ToolMeasure measure;
  if (fits.im_name == "pga") {
    require_unit("g");
    measure = {"Peak Ground Acceleration", "g", "PGA", "g", 1.0};
  } else if (fits.im_name == "pgv") {
    require_unit("m/s");
    measure = {"Peak Ground Velocity", "mps", "PGV", "cm/s", 100.0};
  } else if (fits.im_name == "sa") {
    require_unit("g");
    if (!fits.im_period_s || !(*fits.im_period_s > 0.0) || !std::isfinite(*fits.im_period_s)) {
      throw refuse("its Sa has no period (attribute im_period_s of /fragility)");
    }
    if (!fits.im_damping || std::abs(*fits.im_damping - 0.05) > 1e-9) {
      throw refuse("its Sa is at " +
                   (fits.im_damping ? brief(*fits.im_damping * 100.0) + " %" : "an unknown") +
                   " damping, while pelicun's and OpenQuake's spectral accelerations are 5 % "
                   "damped");
    }
    const std::string period = period_text(*fits.im_period_s);
    measure = {"Peak Spectral Acceleration|" + period, "g", "SA(" + period + ")", "g", 1.0};
  } else if (fits.im_name == "pulse_amplitude") {
    throw refuse(
        "its intensity measure is the pulse amplitude, which neither pelicun nor OpenQuake knows; "
        "name \"pga\", \"pgv\" or \"sa\" in the study's intensity_measure");
  } else if (fits.im_name == "pga_over_g_tan_alpha") {
    throw refuse("its intensity measure " + fits.im_label +
                 " is dimensionless (PGA scaled by the block's own g tan alpha), which neither "
                 "pelicun nor OpenQuake knows; name \"pga\", \"pgv\" or \"sa\" in the study's "
                 "intensity_measure");
  } else {
    throw refuse("its intensity measure \"" + fits.im_name + "\" is not one blockfrag exports");
  }
  return measure;
}

void require_fitted(const FragilityFits& fits) {
  if (fits.states.empty()) throw ContractViolation("export: no limit state to export");
  for (const auto& state : fits.states) {
    if (!state.fitted()) {
      throw ContractViolation("export: limit state " + state.name + " has no fit");
    }
  }
}

// The range of the study's levels over the exported states.
std::pair<double, double> level_range(const FragilityFits& fits) {
  double low = std::numeric_limits<double>::infinity();
  double high = -low;
  for (const auto& state : fits.states) {
    for (const double level : state.im) {
      if (!std::isfinite(level) || level <= 0.0) continue;
      low = std::min(low, level);
      high = std::max(high, level);
    }
  }
  if (!(low <= high)) {
    throw InvalidInput(fits.source + ": no positive finite level in the im datasets of /fragility");
  }
  return {low, high};
}

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (const char c : text) {
    if (c == '"') quoted += '"';
    quoted += c;
  }
  return quoted + "\"";
}

std::string xml_escaped(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string unit_in_prose(const std::string& unit) { return unit == "1" ? "" : " " + unit; }

// One line per limit state: what the fit says and how well the data place it.
std::string fit_comment(const FragilityFit& state, const std::string& unit) {
  std::string text = state.name + " (" + limit_state_description(state) + "): median " +
                     brief(state.median) + unit_in_prose(unit);
  if (state.median_ci.size() == 2) {
    text += " (95 % bootstrap interval " + brief(state.median_ci[0]) + " to " +
            brief(state.median_ci[1]) + ")";
  }
  text += ", beta " + brief(state.beta);
  if (state.beta_ci.size() == 2) {
    text += " (" + brief(state.beta_ci[0]) + " to " + brief(state.beta_ci[1]) + ")";
  }
  if (state.deviance) text += ", deviance " + brief(*state.deviance);
  if (state.gof_p_value) text += ", goodness-of-fit p value " + brief(*state.gof_p_value);
  return text + ".";
}

std::string first_segment(const std::string& id) { return id.substr(0, id.find('.')); }

}  // namespace

std::string exact_number(double value) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

LognormalMoments lognormal_moments(double median, double beta) {
  const double variance = beta * beta;
  const double mean = median * std::exp(0.5 * variance);
  return {mean, mean * std::sqrt(std::expm1(variance))};
}

std::string limit_state_description(const FragilityFit& fit) {
  if (fit.type == "overturning") return "overturned";
  std::string text = fit.type;
  if (fit.type == "max_rotation") text = "max |theta| > " + exact_number(fit.threshold) + " alpha";
  if (fit.type == "residual_slide") text = "residual slide > " + exact_number(fit.threshold) + " m";
  if (fit.type == "post_earthquake_unstable") {
    text = "post-earthquake safety factor < " + exact_number(fit.threshold);
  }
  return fit.overturned_exceeds ? text + ", or overturned" : text;
}

FragilityFits exportable_fits(const FragilityFits& fits, bool fitted_only,
                              std::vector<std::string>& left_out) {
  FragilityFits kept = fits;
  kept.states.clear();
  std::string unfitted;
  for (const auto& state : fits.states) {
    if (state.fitted()) {
      kept.states.push_back(state);
      continue;
    }
    left_out.push_back(state.name);
    if (!unfitted.empty()) unfitted += "; ";
    unfitted += state.name + " (fit_status: " +
                (state.fit_status.empty() ? std::string("none") : state.fit_status) + ")";
  }
  if (!unfitted.empty() && !fitted_only) {
    throw InvalidInput(fits.source + ": no lognormal fit for " + unfitted +
                       ": a limit state without a fit cannot be exported (--fitted-only exports "
                       "the fitted ones without it)");
  }
  if (kept.states.empty()) {
    throw InvalidInput(fits.source + ": no limit state has a lognormal fit: nothing to export (" +
                       unfitted + ")");
  }
  for (std::size_t k = 1; k < kept.states.size(); ++k) {
    const auto& previous = kept.states[k - 1];
    const auto& state = kept.states[k];
    if (state.median < previous.median) {
      throw InvalidInput(fits.source +
                         ": the limit states are not in order of severity: " + previous.name +
                         " (median " + exact_number(previous.median) + ") comes before " +
                         state.name + " (median " + exact_number(state.median) + ")");
    }
  }
  return kept;
}

FragilityFits nested_fits(const FragilityFits& fits) {
  if (fits.nested_status.empty()) {
    throw InvalidInput(fits.source +
                       ": has no nested fit (no /fragility attribute nested_status): rerun the "
                       "study with a blockfrag that fits one");
  }
  if (fits.nested_status != "ok") {
    throw InvalidInput(fits.source + ": its nested fit does not exist (" + fits.nested_status +
                       ")");
  }
  FragilityFits nested = fits;
  nested.common_beta = true;
  nested.crossing_pairs.clear();  // curves of one beta never cross
  for (auto& state : nested.states) {
    if (std::isnan(state.nested_median)) {
      state.fit_status = "not in the nested fit (fit_status " + state.fit_status + ")";
    } else {
      state.median = state.nested_median;
      state.beta = fits.nested_beta;
    }
    state.median_ci.clear();
    state.beta_ci.clear();
    state.deviance.reset();
    state.gof_p_value.reset();
  }
  return nested;
}

std::string default_export_id(const FragilityFits& fits) { return "BF.BLOCK." + fits.config_hash; }

void check_export_id(const std::string& id) {
  const bool allowed = std::all_of(id.begin(), id.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' ||
           c == '_';
  });
  if (id.empty() || !allowed || id.size() > max_identifier_length || id.front() == '.' ||
      id.back() == '.') {
    throw InvalidInput("--id: \"" + id + "\" must be 1 to " +
                       std::to_string(max_identifier_length) +
                       " letters, digits, '.' or '_', neither starting nor ending with '.'");
  }
}

PelicunDamageModel pelicun_damage_model(const FragilityFits& fits, const std::string& id) {
  require_fitted(fits);
  check_export_id(id);
  const ToolMeasure measure = tool_measure(fits, "pelicun");

  std::string header = "ID,Incomplete,Demand-Type,Demand-Unit,Demand-Offset,Demand-Directional";
  std::string row = csv_field(id) + ",0," + csv_field(measure.pelicun_type) + "," +
                    csv_field(measure.pelicun_unit) + ",0,1";
  for (std::size_t k = 0; k < fits.states.size(); ++k) {
    const std::string ls = "LS" + std::to_string(k + 1);
    header += "," + ls + "-Family," + ls + "-Theta_0," + ls + "-Theta_1";
    row += ",lognormal," + exact_number(fits.states[k].median) + "," +
           exact_number(fits.states[k].beta);
  }

  using Json = nlohmann::ordered_json;
  Json limit_states = Json::object();
  std::string comments = "Lognormal fits to the study's samples, least severe first. ";
  for (std::size_t k = 0; k < fits.states.size(); ++k) {
    const auto& state = fits.states[k];
    const std::string number = std::to_string(k + 1);
    limit_states["LS" + number]["DS" + number]["Description"] =
        state.name + ": " + limit_state_description(state);
    if (k > 0) comments += ' ';
    comments += fit_comment(state, fits.im_units);
  }
  const std::string subject = "a free-standing rigid block (blockfrag study, config hash " +
                              fits.config_hash + ") versus " + fits.im_label +
                              " of the ground motion in the block's plane";
  Json model;
  model["_GeneralInformation"] = {
      {"ShortName", "blockfrag study " + fits.config_hash},
      {"Description", "Lognormal fragility functions of " + subject + ", fitted by blockfrag " +
                          (fits.common_beta ? "jointly with one common beta (nested: the curves "
                                              "do not cross) "
                                            : "") +
                          "to its Monte Carlo study and exported by blockfrag export."},
      {"Version", kVersion},
      {"ComponentGroups", {{first_segment(id) + " - blockfrag rigid blocks", Json::array({id})}}}};
  model[id] = {{"Description", "Free-standing rigid block of blockfrag study " + fits.config_hash +
                                   ": lognormal fragility versus " + fits.im_label +
                                   " of the ground motion in the block's plane"},
               {"Comments", comments},
               {"SuggestedComponentBlockSize", "1 EA"},
               {"RoundUpToIntegerQuantity", "True"},
               {"LimitStates", limit_states}};
  return {header + "\n" + row + "\n", model.dump(2) + "\n"};
}

std::string openquake_fragility_model(const FragilityFits& fits, const std::string& id) {
  require_fitted(fits);
  check_export_id(id);
  const ToolMeasure measure = tool_measure(fits, "OpenQuake");
  const auto [low, high] = level_range(fits);
  std::string names;
  std::string meanings;
  for (const auto& state : fits.states) {
    if (state.name.size() > max_identifier_length) {
      throw InvalidInput(fits.source + ": the limit state name " + state.name + " is longer than " +
                         std::to_string(max_identifier_length) +
                         " characters, which OpenQuake refuses");
    }
    if (!names.empty()) names += ' ';
    names += state.name;
    if (!meanings.empty()) meanings += "; ";
    meanings += state.name + ": " + limit_state_description(state);
  }
  std::string model_id = id;
  std::replace(model_id.begin(), model_id.end(), '.', '_');  // OpenQuake's model ids have no '.'
  const std::string description = "blockfrag study " + fits.config_hash + ": lognormal fragility" +
                                  (fits.common_beta ? " with one common beta (nested)" : "") +
                                  " of a free-standing rigid block versus " + fits.im_label + " (" +
                                  measure.openquake_unit +
                                  "); limit states, least severe first: " + meanings;
  std::ostringstream out;
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<nrml xmlns=\"http://openquake.org/xmlns/nrml/0.5\">\n"
      << "  <fragilityModel id=\"" << xml_escaped(model_id)
      << "\" assetCategory=\"buildings\" lossCategory=\"structural\">\n"
      << "    <description>" << xml_escaped(description) << "</description>\n"
      << "    <limitStates>" << xml_escaped(names) << "</limitStates>\n"
      << "    <fragilityFunction id=\"" << xml_escaped(id)
      << "\" format=\"continuous\" shape=\"logncdf\">\n"
      << "      <imls imt=\"" << xml_escaped(measure.openquake_imt) << "\" minIML=\""
      << exact_number(low * measure.openquake_scale) << "\" maxIML=\""
      << exact_number(high * measure.openquake_scale) << "\" noDamageLimit=\"0\"/>\n";
  for (const auto& state : fits.states) {
    const LognormalMoments moments =
        lognormal_moments(state.median * measure.openquake_scale, state.beta);
    out << "      <params ls=\"" << xml_escaped(state.name) << "\" mean=\""
        << exact_number(moments.mean) << "\" stddev=\"" << exact_number(moments.stddev) << "\"/>\n";
  }
  out << "    </fragilityFunction>\n"
      << "  </fragilityModel>\n"
      << "</nrml>\n";
  return out.str();
}

}  // namespace blockfrag
