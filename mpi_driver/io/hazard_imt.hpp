// The intensity measure of a hazard curve, as the hazard tools spell it, and whether it is a
// study's: PGA with PGA, PGV with PGV, SA(T) with Sa at the same T and 5 % damping (the damping
// every hazard tool's spectral acceleration has). OpenQuake writes "PGA", "PGV", "SA(0.2)"; the
// USGS hazard service "PGA", "PGV", "SA0P2", "SA1P0" (nshmp-haz's Imt names); --imt takes either.
// Both tools give PGA and SA in g and PGV in cm/s.
#pragma once

#include <optional>
#include <string>

namespace blockfrag {

struct HazardImt {
  enum class Kind { pga, pgv, sa };
  Kind kind = Kind::pga;
  double period_s = 0.0;  // SA only

  // "PGA", "PGV", "SA(0.2)": OpenQuake's name, for messages and outputs.
  std::string name() const;
};

// An OpenQuake or USGS spelling; nullopt for anything else.
std::optional<HazardImt> parse_hazard_imt(const std::string& text);

// The study's measure, from its output's /fragility attributes (im_name, im_period_s,
// im_damping); throws InvalidInput naming `source` for a measure no hazard tool has
// (pulse_amplitude, pga_over_g_tan_alpha) or Sa at a damping other than 5 %.
HazardImt study_imt(const std::string& source, const std::string& im_name,
                    std::optional<double> period_s, std::optional<double> damping);

// Whether the two are one measure (SA periods equal to 1e-9 relative).
bool same_imt(const HazardImt& a, const HazardImt& b);

// The factor from the hazard tools' unit of the measure to the study's: 0.01 for PGV (cm/s to
// m/s), 1 for PGA and SA (g).
double hazard_unit_to_study(const HazardImt& imt);

}  // namespace blockfrag
