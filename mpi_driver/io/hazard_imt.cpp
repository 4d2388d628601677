#include "mpi_driver/io/hazard_imt.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "engine/errors.hpp"
#include "engine/number_text.hpp"

namespace blockfrag {
namespace {

// A period written as digits with at most one '.', finite and > 0.
std::optional<double> period_text(const std::string& text) {
  if (text.empty() || text.size() > 16) return std::nullopt;
  double value = 0.0;
  const auto end = text.data() + text.size();
  const auto result = std::from_chars(text.data(), end, value, std::chars_format::fixed);
  if (result.ec != std::errc() || result.ptr != end) return std::nullopt;
  if (!(std::isfinite(value) && value > 0.0)) return std::nullopt;
  return value;
}

}  // namespace

std::string HazardImt::name() const {
  switch (kind) {
    case Kind::pga: return "PGA";
    case Kind::pgv: return "PGV";
    case Kind::sa: return "SA(" + format_number(period_s) + ")";
  }
  return "?";
}

std::optional<HazardImt> parse_hazard_imt(const std::string& text) {
  if (text == "PGA") return HazardImt{HazardImt::Kind::pga, 0.0};
  if (text == "PGV") return HazardImt{HazardImt::Kind::pgv, 0.0};
  std::optional<double> period;
  if (text.size() > 4 && text.rfind("SA(", 0) == 0 && text.back() == ')') {
    period = period_text(text.substr(3, text.size() - 4));
  } else if (text.size() > 4 && text.rfind("SA", 0) == 0) {
    // nshmp-haz's SA0P2, SA1P0, SA0P075: P for the decimal point.
    std::string digits = text.substr(2);
    const auto point = digits.find('P');
    if (point == std::string::npos || digits.find('.') != std::string::npos) return std::nullopt;
    digits[point] = '.';
    period = period_text(digits);
  }
  if (!period) return std::nullopt;
  return HazardImt{HazardImt::Kind::sa, *period};
}

HazardImt study_imt(const std::string& source, const std::string& im_name,
                    std::optional<double> period_s, std::optional<double> damping) {
  if (im_name == "pga") return {HazardImt::Kind::pga, 0.0};
  if (im_name == "pgv") return {HazardImt::Kind::pgv, 0.0};
  if (im_name == "sa") {
    if (!period_s || !damping || !(std::isfinite(*period_s) && *period_s > 0.0)) {
      throw InvalidInput(source +
                         ": /fragility has im_name \"sa\" without a valid im_period_s "
                         "and im_damping");
    }
    if (std::abs(*damping - 0.05) > 1e-9) {
      throw InvalidInput(source + ": the study's Sa is at " + format_number(*damping * 100) +
                         " % damping; hazard curves are of 5 % damped spectral acceleration");
    }
    return {HazardImt::Kind::sa, *period_s};
  }
  throw InvalidInput(source + ": the study's intensity measure is " + im_name +
                     ", which no hazard curve has; rerun the study with \"type\": \"pga\", "
                     "\"pgv\" or \"sa\" in its intensity_measure");
}

bool same_imt(const HazardImt& a, const HazardImt& b) {
  if (a.kind != b.kind) return false;
  return a.kind != HazardImt::Kind::sa ||
         std::abs(a.period_s - b.period_s) <= 1e-9 * std::max(a.period_s, b.period_s);
}

double hazard_unit_to_study(const HazardImt& imt) {
  return imt.kind == HazardImt::Kind::pgv ? 0.01 : 1.0;
}

}  // namespace blockfrag
