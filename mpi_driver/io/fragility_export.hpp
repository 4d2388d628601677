// A study's lognormal fragility fits as the damage models of two loss-assessment tools: pure
// functions from the fits (fragility_fits.hpp) to the files' text.
//
// pelicun (its damage-model database format, as its bundled damage_DB_*.csv/.json have it):
//   fragility.csv   ID,Incomplete,Demand-Type,Demand-Unit,Demand-Offset,Demand-Directional,
//                   LS1-Family,LS1-Theta_0,LS1-Theta_1,LS2-...: one row; Incomplete 0, offset 0,
//                   directional 1 (the measure is of the motion in the block's plane); each limit
//                   state "lognormal" with Theta_0 the median and Theta_1 beta, least severe first.
//                   Demand: "Peak Ground Acceleration" in "g", "Peak Ground Velocity" in "mps",
//                   "Peak Spectral Acceleration|T" (T the period, s) in "g".
//   fragility.json  _GeneralInformation (ShortName, Description, Version, ComponentGroups) and,
//                   for the ID, Description, Comments, SuggestedComponentBlockSize,
//                   RoundUpToIntegerQuantity and LimitStates {"LSk": {"DSk": {"Description"}}}.
// OpenQuake (NRML 0.5): one fragilityModel, one fragilityFunction format="continuous"
//   shape="logncdf" whose imls carry imt ("PGA" in g, "PGV" in cm/s, "SA(T)" in g), minIML and
//   maxIML (the study's level range) and noDamageLimit="0" (no cut-off), then one
//   params ls= mean= stddev= per limit state, least severe first. OpenQuake's mean and stddev are
//   those of the measure itself: mean = median exp(beta^2 / 2), stddev = mean sqrt(exp(beta^2) -
//   1).
// Refused (InvalidInput): a measure the tools do not know (pulse_amplitude, pga_over_g_tan_alpha),
// Sa at a damping other than 5 %, units that do not match the measure.
#pragma once

#include <string>
#include <vector>

#include "mpi_driver/io/fragility_fits.hpp"

namespace blockfrag {

// The limit states an export keeps: the fitted ones, least severe first. Unless fitted_only, a
// limit state without a fit is refused (InvalidInput naming each, with its fit_status); with it,
// their names go to left_out. No fitted state at all, or fitted medians that do not increase in
// the order of severity, is refused either way.
FragilityFits exportable_fits(const FragilityFits& fits, bool fitted_only,
                              std::vector<std::string>& left_out);

// export --nested: the fits with the study's common-beta fit in place of each state's own (median
// nested_median, beta nested_beta; intervals and goodness of fit, which are the separate fits',
// dropped; no crossings). A state not in it gets a fit_status saying so, which exportable_fits
// then treats as unfitted. Throws InvalidInput for an output without a nested fit or whose
// nested fit does not exist.
FragilityFits nested_fits(const FragilityFits& fits);

// "BF.BLOCK.<config hash>". An ID is letters, digits, '.' and '_' (pelicun splits names on '-'),
// at most 75 characters (OpenQuake's identifier limit); check_export_id throws InvalidInput.
std::string default_export_id(const FragilityFits& fits);
void check_export_id(const std::string& id);

// What the limit state means, for a human: "residual slide > 0.05 m, or overturned".
std::string limit_state_description(const FragilityFit& fit);

struct LognormalMoments {
  double mean = 0.0;
  double stddev = 0.0;
};
// The mean and standard deviation of a lognormal variable of this median and beta.
LognormalMoments lognormal_moments(double median, double beta);

// The shortest decimal text that reads back as the same double ("0.1", "1e-05").
std::string exact_number(double value);

struct PelicunDamageModel {
  std::string csv;   // fragility.csv
  std::string json;  // fragility.json
};
// `fits` holds fitted states only (exportable_fits).
PelicunDamageModel pelicun_damage_model(const FragilityFits& fits, const std::string& id);
std::string openquake_fragility_model(const FragilityFits& fits, const std::string& id);

}  // namespace blockfrag
