// A study output's lognormal fragility fits, read back from its HDF5 file (study_output.hpp writes
// it) for `blockfrag export`. What is read:
//   /                  attributes config, config_hash (their presence marks a blockfrag output)
//   /fragility         attributes im_name, im_units, im_label; im_period_s and im_damping (sa);
//                      severity_order: the limit-state names, comma-separated, least severe first
//                      optionally crossing_pairs ("a,b;c,d": limit states whose fits cross)
//   /fragility/<name>  attributes type, threshold, median, beta, fit_status; optionally
//                      median_ci, beta_ci (2 values), deviance, gof_p_value, overturned_exceeds
//                      (0 or 1), nested_median (NaN when not in the nested fit); dataset im
//                      (levels)
//   /fragility         optionally nested_status, nested_beta: the common-beta fit
// A file without severity_order has its groups ordered by fitted median (unfitted ones last, by
// name); groups that severity_order does not name follow the ones it names.
// Nothing is trusted: every member of /fragility is a limit state name by the study's rule, every
// text read is printable ASCII of a bounded length, config_hash is 16 hexadecimal digits, im holds
// at most a study's number of levels (checked before it is read), each finite and > 0, a
// a threshold (max_rotation's, residual_slide's, post_earthquake_unstable's) is finite and > 0, and
// a fit with status "ok" has a median in [1e-6, 1e6] (the measure's unit) and a beta in [1e-6, 10].
// Objects are reached through hard links only (hdf5_reader.hpp).
#pragma once

#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace blockfrag {

struct FragilityFit {
  std::string name;
  // "overturning", "max_rotation", "residual_slide", "post_earthquake_unstable"
  std::string type;
  // theta/alpha for max_rotation, m for residual_slide, the safety factor for
  // post_earthquake_unstable
  double threshold = 0.0;
  double median = 0.0;            // in the measure's unit; NaN without a fit
  double beta = 0.0;              // the logarithmic standard deviation; NaN without a fit
  std::string fit_status;         // "ok" when the fit exists, otherwise why not
  std::vector<double> median_ci;  // 95 % bootstrap interval (2 values), or empty
  std::vector<double> beta_ci;
  std::optional<double> deviance;
  std::optional<double> gof_p_value;
  // Whether an overturned block exceeds this limit state whatever its measure; without the
  // attribute (older outputs), what blockfrag then did: max_rotation yes, residual_slide no.
  bool overturned_exceeds = true;
  std::vector<double> im;  // the levels
  // Its median in the fit of one common beta; NaN when not in it or the output has none.
  double nested_median = std::numeric_limits<double>::quiet_NaN();

  bool fitted() const { return fit_status == "ok"; }
};

struct FragilityFits {
  std::string source;  // the file, for messages
  std::string config_hash;
  std::string im_name;   // "pga", "pgv", "sa", "pga_over_g_tan_alpha", "pulse_amplitude"
  std::string im_units;  // "g", "m/s", "1"
  std::string im_label;  // "PGA", "Sa(1 s, 5 %)", ...
  std::optional<double> im_period_s;
  std::optional<double> im_damping;
  std::vector<FragilityFit> states;  // least severe first
  // Pairs of limit states whose fitted curves cross in the levels' range.
  std::vector<std::pair<std::string, std::string>> crossing_pairs;
  // The fit of one common beta: its status ("ok" or why not; empty when the output has none) and
  // beta. common_beta: the states' median and beta are that fit's (export --nested).
  std::string nested_status;
  double nested_beta = std::numeric_limits<double>::quiet_NaN();
  bool common_beta = false;
};

// Throws InvalidInput naming the file (and the object) when it is missing, not a regular file, not
// HDF5, truncated or damaged, not a blockfrag study output, has no /fragility, or breaks the
// layout and rules above; a quoted text is a short printable excerpt.
FragilityFits read_fragility_fits(const std::filesystem::path& path);

}  // namespace blockfrag
