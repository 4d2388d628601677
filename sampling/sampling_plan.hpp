// A study's random inputs and how they are sampled: (plan, sample index) -> the inputs' values.
//
// Input k's values come from stream stream_id(name_k) (FNV-1a of its name, see philox_stream.hpp),
// not from its position: adding, removing or reordering inputs leaves every other input's values
// bit-for-bit unchanged, and so does changing another input's distribution.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "sampling/designs.hpp"
#include "sampling/distributions.hpp"
#include "sampling/validation.hpp"

namespace blockfrag {

struct RandomInput {
  std::string name;
  Distribution distribution;
};

struct SamplingPlan {
  std::uint64_t seed = 0;
  Design design = Design::monte_carlo;
  std::uint32_t samples_per_level = 1;  // n
  std::uint32_t levels = 1;             // intensity levels; sample index = level n + j
  std::vector<RandomInput> inputs;
};

// Where a sample index sits in the study.
struct SamplePosition {
  std::uint32_t level = 0;
  std::uint32_t member = 0;  // j, 0 <= j < samples_per_level
};

std::uint64_t sample_count(const SamplingPlan& plan);

// Throws ContractViolation unless index < sample_count(plan).
SamplePosition position(const SamplingPlan& plan, std::uint64_t index);

// Every rule the plan breaks, with fields as paths inside the plan ("samples_per_level",
// "inputs/2/name", "inputs/0/std_dev"): n in [1, 2^31], levels >= 1, non-empty and unique input
// names, no two names with the same stream id, and each input's distribution rules.
std::vector<Violation> validate(const SamplingPlan& plan);

// Throws SamplingError with every violation, if there is any.
void check(const SamplingPlan& plan);

// The inputs' values for one sample, in the plan's input order: value k is
// quantile(distribution_k, u_k) with u_k = design_uniform(design, seed, stream_id(name_k), n,
// index). A pure function; for the Latin hypercube it rebuilds each input's permutation (O(n)), so
// drawing many samples of a level is faster through a Sampler. The plan must be valid (check).
std::vector<double> draw_sample(const SamplingPlan& plan, std::uint64_t index);

// Draws samples of a checked plan, keeping the Latin hypercube permutations of the level last
// drawn from, so a level's n samples cost O(n) per input in all. Gives exactly draw_sample's
// values, whatever the order of the requests. Not safe to share between threads (one per rank).
class Sampler {
 public:
  explicit Sampler(SamplingPlan plan);  // checks the plan

  const SamplingPlan& plan() const { return plan_; }
  std::vector<double> draw(std::uint64_t index);

 private:
  SamplingPlan plan_;
  std::vector<std::uint32_t> streams_;
  std::optional<LatinHypercubeLevel> level_;
};

}  // namespace blockfrag
