// `blockfrag risk`'s numbers: each study's limit states integrated against the site's hazard
// curve (postproc/risk/risk_integral.hpp), from the lognormal fit and from the observed points,
// with 95 % intervals from the study's own bootstrap (its resamples drawn again from the output's
// counts and seed, and checked against the intervals it stored), and the studies combined by
// their weights (the shares of the year of pool levels, say).
#pragma once

#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "mpi_driver/io/hazard_file.hpp"
#include "mpi_driver/io/risk_study.hpp"
#include "postproc/risk/risk_integral.hpp"

namespace blockfrag {

// The probabilities in t years reported for every frequency.
inline constexpr double kRiskYears[] = {1.0, 50.0, 100.0};

// One way of integrating one limit state: its lambda, what of it lies beyond the study's levels,
// its bins, and its bootstrap interval.
struct RiskEstimate {
  static constexpr double nan = std::numeric_limits<double>::quiet_NaN();

  RiskIntegral integral;
  // lambda of each bootstrap resample (NaN where a resample has no fit).
  std::vector<double> resample_lambda;
  double lambda_low = nan, lambda_high = nan;  // 2.5 % and 97.5 % of resample_lambda
  std::string interval_note;                   // why there is no interval, when there is none
};

struct LimitStateRisk {
  std::string name;
  double median = 0.0, beta = 0.0;  // NaN without a fit
  std::string fit_status;
  std::optional<RiskEstimate> fit;          // with a fit
  std::optional<RiskEstimate> points;       // with a level that has trials
  std::vector<double> levels, probability;  // the points: levels with trials
};

struct StudyRisk {
  std::string file;
  double weight = 1.0;
  std::string config_hash, im_label, im_units;
  bool cloud = false;
  std::vector<LimitStateRisk> states;
};

struct WeightedStudy {
  RiskStudy study;
  std::string file;
  double weight = 1.0;
};

// Every limit state of one study.
StudyRisk assess_study(const WeightedStudy& study, const HazardCurve& hazard);

// The studies' limit states weighted and summed (every study has the same names, in the first's
// order); a method is combined only where every study has it, an interval only where every
// study has one (resample b of each summed: the studies' bootstraps are independent).
std::vector<LimitStateRisk> combine_studies(const std::vector<StudyRisk>& studies);

}  // namespace blockfrag
