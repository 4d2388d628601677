// The solver settings the work-precision study compares: a method and its one accuracy parameter
// (the step for rk4, the tolerance for the step-size-controlled methods).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "engine/errors.hpp"
#include "engine/scene/scene.hpp"

namespace blockfrag {

struct SolverSetting {
  Method method = Method::adaptive;
  double parameter = 1e-8;  // dt in s for rk4, the tolerance otherwise

  friend bool operator==(const SolverSetting&, const SolverSetting&) = default;
};

// The names the scene JSON uses: "rk4", "adaptive", "gsl_rkf45", "gsl_rk8pd".
std::string method_label(Method method);

// "rk4 dt=0.00025", "adaptive tol=1e-08": short, unique per setting, for tables and plots.
std::string setting_label(const SolverSetting& setting);

// `base` (its budgets) with the setting's method and parameter.
SolverSettings with_setting(SolverSettings base, const SolverSetting& setting);

// The production default: what a scene that names no solver gets.
SolverSetting default_setting();

// The full study: rk4 at dt = 1e-3 ... 1e-5 s (the paper's 2.5e-4 included); adaptive, gsl_rkf45
// and gsl_rk8pd at tolerances 1e-3 ... 1e-12, one per decade.
std::vector<SolverSetting> full_accuracy_settings();

// Parses "METHOD:VALUE", e.g. "rk4:0.00025" or "adaptive:1e-8"; throws InvalidInput with a
// message naming what is wrong (unknown method, a value that is not a positive finite number, a
// tolerance above 0.1).
SolverSetting parse_solver_setting(std::string_view text);

}  // namespace blockfrag
