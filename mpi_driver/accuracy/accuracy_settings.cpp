#include "mpi_driver/accuracy/accuracy_settings.hpp"

#include <cmath>
#include <cstdio>

#include "engine/scene/parameter_domains.hpp"

namespace blockfrag {

std::string method_label(Method method) {
  switch (method) {
    case Method::rk4: return "rk4";
    case Method::adaptive: return "adaptive";
    case Method::gsl_rkf45: return "gsl_rkf45";
    case Method::gsl_rk8pd: return "gsl_rk8pd";
  }
  return "unknown";
}

std::string setting_label(const SolverSetting& setting) {
  char value[32];
  std::snprintf(value, sizeof value, "%.3g", setting.parameter);
  return method_label(setting.method) + (setting.method == Method::rk4 ? " dt=" : " tol=") + value;
}

SolverSettings with_setting(SolverSettings base, const SolverSetting& setting) {
  base.method = setting.method;
  if (setting.method == Method::rk4) {
    base.dt = setting.parameter;
  } else {
    base.tolerance = setting.parameter;
  }
  return base;
}

SolverSetting default_setting() {
  const SolverSettings defaults;
  return {defaults.method, defaults.method == Method::rk4 ? defaults.dt : defaults.tolerance};
}

std::vector<SolverSetting> full_accuracy_settings() {
  std::vector<SolverSetting> settings;
  for (double dt : {1e-3, 5e-4, 2.5e-4, 1e-4, 5e-5, 2.5e-5, 1e-5})
    settings.push_back({Method::rk4, dt});
  for (Method method : {Method::adaptive, Method::gsl_rkf45, Method::gsl_rk8pd}) {
    for (int exponent = 3; exponent <= 12; ++exponent) {
      settings.push_back({method, std::pow(10.0, -exponent)});
    }
  }
  return settings;
}

SolverSetting parse_solver_setting(std::string_view text) {
  const auto colon = text.find(':');
  if (colon == std::string_view::npos) {
    throw InvalidInput("setting \"" + std::string(text) +
                       "\": expected METHOD:VALUE, e.g. rk4:0.00025");
  }
  const std::string name(text.substr(0, colon));
  const std::string value_text(text.substr(colon + 1));
  SolverSetting setting;
  bool known = false;
  for (Method method : {Method::rk4, Method::adaptive, Method::gsl_rkf45, Method::gsl_rk8pd}) {
    if (name == method_label(method)) {
      setting.method = method;
      known = true;
    }
  }
  if (!known) {
    throw InvalidInput("setting \"" + std::string(text) +
                       "\": the method must be rk4, adaptive, gsl_rkf45 or gsl_rk8pd");
  }
  std::size_t used = 0;
  double value = NAN;
  try {
    value = std::stod(value_text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != value_text.size() || !std::isfinite(value) || value <= 0) {
    throw InvalidInput("setting \"" + std::string(text) +
                       "\": the value must be a positive number");
  }
  // The ranges a scene's solver takes: a setting outside them would fail every scene later.
  const bool rk4 = setting.method == Method::rk4;
  const Domain& range = rk4 ? domain::rk4_step : domain::tolerance;
  if (!range.contains(value)) {
    throw InvalidInput("setting \"" + std::string(text) +
                       "\": " + (rk4 ? "a step dt " : "a tolerance ") + range.rule() +
                       (range.unit[0] ? std::string(" ") + range.unit : std::string()));
  }
  setting.parameter = value;
  return setting;
}

}  // namespace blockfrag
