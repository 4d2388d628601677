#include "mpi_driver/study/fragility_summary.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "postproc/fragility/curve_set.hpp"

namespace blockfrag {
namespace {

// A fit is rejected when data this far from it would arise less often than this by chance.
constexpr double kRejectedAt = 0.05;

std::string three_digits(double value) {
  std::ostringstream text;
  text << std::setprecision(3) << value;
  return text.str();
}

std::string no_fit_text(const FragilityCurve& curve) {
  std::string text = "no fit (" + curve.fit_status + ")";
  const bool has_low = curve.median_low > 0, has_high = std::isfinite(curve.median_high);
  if (has_low && has_high) {
    text += ": the data place the median between " + three_digits(curve.median_low) + " and " +
            three_digits(curve.median_high);
  } else if (has_low) {
    text += ": the data place the median above " + three_digits(curve.median_low);
  } else if (has_high) {
    text += ": the data place the median below " + three_digits(curve.median_high);
  }
  return text;
}

std::string interval_text(double low, double high) {
  std::ostringstream text;
  text << std::setprecision(3) << '[' << low << ", " << high << ']';
  return text.str();
}

// One line per limit state, the least severe first: its median and beta, or why it has none.
void print_curve_lines(std::ostream& out, const StudyConfig& config,
                       const StudyFragility& fragility, std::size_t width) {
  for (const std::size_t k : fragility.severity) {
    const FragilityCurve& curve = fragility.curves[k];
    out << "  " << std::left << std::setw(static_cast<int>(width)) << config.limit_states[k].name
        << std::right << "  ";
    if (curve.fit_status != "ok") {
      out << no_fit_text(curve) << '\n';
      continue;
    }
    const BootstrapResult& boot = curve.bootstrap;
    out << "median " << three_digits(curve.median);
    if (boot.fitted > 0) out << ' ' << interval_text(boot.median_low, boot.median_high);
    out << "  beta " << three_digits(curve.beta);
    if (boot.fitted > 0) out << ' ' << interval_text(boot.beta_low, boot.beta_high);
    if (curve.gof_dof > 0) out << "  fit p = " << three_digits(curve.gof_p_value);
    out << '\n';
  }
}

// A curve the data reject, or whose intervals stand on fewer resamples than were drawn.
void print_curve_warnings(std::ostream& out, const StudyConfig& config,
                          const StudyFragility& fragility) {
  for (std::size_t k = 0; k < fragility.curves.size(); ++k) {
    const FragilityCurve& curve = fragility.curves[k];
    if (curve.gof_dof > 0 && curve.gof_p_value < kRejectedAt) {
      out << "warning: the data of \"" << config.limit_states[k].name
          << "\" are not lognormal (deviance " << three_digits(curve.deviance) << " on "
          << curve.gof_dof << " degrees of freedom, p = " << three_digits(curve.gof_p_value)
          << "): a point lies " << three_digits(curve.max_misfit)
          << " from the fitted curve; use its points, not its median and beta\n";
    }
    const BootstrapResult& boot = curve.bootstrap;
    if (curve.fit_status == "ok" && boot.resamples > 0 && boot.fitted < boot.resamples) {
      out << "note: " << boot.resamples - boot.fitted << " of " << boot.resamples
          << " bootstrap resamples of \"" << config.limit_states[k].name
          << "\" had no fit (too few exceedances or none missing); its intervals are of the "
          << boot.fitted << " others\n";
    }
  }
}

void print_surface_lines(std::ostream& out, const StudyConfig& config,
                         const StudyFragility& fragility, std::size_t width,
                         const std::string& unit) {
  if (!fragility.surfaces.empty()) {
    out << "fragility surfaces (each level's curve above sums its cells over every period): "
           "median "
        << im_label(config.intensity) << " = m (T / 1 s)^c, +- one standard error:\n";
    for (const std::size_t k : fragility.severity) {
      const SurfaceFit& fit = fragility.surfaces[k].fit;
      out << "  " << std::left << std::setw(static_cast<int>(width)) << config.limit_states[k].name
          << std::right << "  ";
      if (fit.status != SurfaceFitStatus::ok) {
        out << "no fit (" << surface_fit_status_name(fit.status) << ")\n";
        continue;
      }
      out << "m " << three_digits(std::exp(fit.ln_median_intercept)) << ' ' << unit << "  c "
          << three_digits(fit.ln_median_slope) << " +- " << three_digits(fit.ln_median_slope_se)
          << "  beta " << three_digits(fit.beta1) << " +- " << three_digits(fit.beta1_se) << '\n';
    }
  }
}

void print_crossing_warnings(std::ostream& out, const StudyConfig& config,
                             const StudyFragility& fragility, const std::string& unit) {
  for (const auto& [i, j] : fragility.crossings) {
    const FragilityCurve& a = fragility.curves[i];
    const FragilityCurve& b = fragility.curves[j];
    out << "warning: the fitted curves of \"" << config.limit_states[i].name << "\" and \""
        << config.limit_states[j].name << "\" cross at " << im_label(config.intensity) << " "
        << three_digits(crossing_intensity(a.median, a.beta, b.median, b.beta)) << ' ' << unit
        << ": as damage states of one component they would give a negative probability there\n";
  }
}

}  // namespace

void print_fragility_summary(std::ostream& out, const StudyConfig& config,
                             const StudyFragility& fragility) {
  const std::string unit = im_unit(config.intensity.type);
  out << "fragility of " << im_label(config.intensity) << " (" << unit << ")";
  if (config.bootstrap_resamples > 0) out << ", 95 % bootstrap intervals";
  out << ":\n";
  std::size_t width = 0;
  for (const auto& state : config.limit_states) width = std::max(width, state.name.size());
  print_curve_lines(out, config, fragility, width);
  print_curve_warnings(out, config, fragility);
  print_surface_lines(out, config, fragility, width, unit);
  print_crossing_warnings(out, config, fragility, unit);
}

}  // namespace blockfrag
