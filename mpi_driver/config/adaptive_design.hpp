// Adaptive stripes: a study that runs in batches and places each batch's levels where they inform
// the lognormal fit of one limit state most, until the 95 % interval of its median is narrow
// enough or the sample budget is spent. The form:
//   "design": {"adaptive": {"base": "latin_hypercube", "limit_state": "overturn",
//                           "target_relative_width": 0.05, "pair_probability": 0.128,
//                           "max_samples": 100000}}
// The study's intensity levels are the first batch; each later batch adds two levels of
// samples_per_level samples each. The rule that places them is
// mpi_driver/study/adaptive_levels.hpp.
#pragma once

#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "mpi_driver/config/config_reader.hpp"
#include "sampling/designs.hpp"

namespace blockfrag {

struct AdaptiveDesign {
  Design base = Design::latin_hypercube;  // within each level
  std::string limit_state;                // whose median the batches narrow (default: the first)
  double target_relative_width = 0.05;    // (high - low) / median of the median's 95 % interval
  double pair_probability = 0.128;        // a batch's levels: where the fit is this and 1 - it
  std::int64_t max_samples = 0;           // in all batches, the first included
};

// Its numbers' domains: engine/scene/parameter_domains.hpp.

// The most batches a budget may allow: each costs a round of messages, a checkpoint and a fit.
inline constexpr std::int64_t kMaxAdaptiveBatches = 10'000;

// Reads "design"'s "adaptive" object; the limit state's name is checked by the caller, which
// knows the limit states.
AdaptiveDesign read_adaptive_design(ObjectReader reader);
nlohmann::json adaptive_design_to_json(const AdaptiveDesign& design);

}  // namespace blockfrag
