#include "sampling/sampling_plan.hpp"

#include <string>
#include <utility>
#include <variant>

#include "engine/errors.hpp"
#include "sampling/philox_stream.hpp"

namespace blockfrag {
namespace {

std::vector<std::uint32_t> streams_of(const SamplingPlan& plan) {
  std::vector<std::uint32_t> streams;
  streams.reserve(plan.inputs.size());
  for (const auto& input : plan.inputs) streams.push_back(stream_id(input.name));
  return streams;
}

std::string input_path(std::size_t k) { return "inputs/" + std::to_string(k); }

std::string quoted(const std::string& text) { return "\"" + text + "\""; }

void validate_inputs(const SamplingPlan& plan, std::vector<Violation>& violations) {
  for (std::size_t k = 0; k < plan.inputs.size(); ++k) {
    const auto& input = plan.inputs[k];
    const std::string name_path = input_path(k) + "/name";
    if (input.name.empty()) {
      violations.push_back({name_path, "must not be empty"});
    }
    for (std::size_t other = 0; other < k && !input.name.empty(); ++other) {
      const auto& earlier = plan.inputs[other];
      if (earlier.name == input.name) {
        violations.push_back(
            {name_path, "duplicates " + input_path(other) + "/name (" + quoted(input.name) + ")"});
        break;
      }
      if (stream_id(earlier.name) == stream_id(input.name)) {
        violations.push_back({name_path, quoted(input.name) + " and " + quoted(earlier.name) +
                                             " (" + input_path(other) +
                                             ") hash to the same random stream: rename one"});
        break;
      }
    }
    for (auto& violation : validate(input.distribution)) {
      violation.field =
          violation.field.empty() ? input_path(k) : input_path(k) + "/" + violation.field;
      violations.push_back(std::move(violation));
    }
  }
}

}  // namespace

std::uint64_t sample_count(const SamplingPlan& plan) {
  return static_cast<std::uint64_t>(plan.levels) * plan.samples_per_level;
}

SamplePosition position(const SamplingPlan& plan, std::uint64_t index) {
  if (index >= sample_count(plan)) {
    throw ContractViolation("sample index " + std::to_string(index) + " outside a study of " +
                            std::to_string(sample_count(plan)) + " samples");
  }
  return {static_cast<std::uint32_t>(index / plan.samples_per_level),
          static_cast<std::uint32_t>(index % plan.samples_per_level)};
}

std::vector<Violation> validate(const SamplingPlan& plan) {
  std::vector<Violation> violations;
  if (plan.samples_per_level == 0 || plan.samples_per_level > reserved_draw_flag) {
    violations.push_back({"samples_per_level", "must be in [1, 2147483648] (got " +
                                                   std::to_string(plan.samples_per_level) + ")"});
  }
  if (plan.levels == 0) {
    violations.push_back({"levels", "must be >= 1 (got 0)"});
  }
  if (plan.design != Design::monte_carlo && plan.design != Design::latin_hypercube) {
    violations.push_back({"design", "must be monte_carlo or latin_hypercube"});
  }
  validate_inputs(plan, violations);
  return violations;
}

void check(const SamplingPlan& plan) {
  auto violations = validate(plan);
  if (!violations.empty()) throw SamplingError(std::move(violations));
}

std::vector<double> draw_sample(const SamplingPlan& plan, std::uint64_t index) {
  position(plan, index);  // throws for an index outside the study
  std::vector<double> values;
  values.reserve(plan.inputs.size());
  for (const auto& input : plan.inputs) {
    if (const auto* fixed = std::get_if<Fixed>(&input.distribution)) {
      values.push_back(fixed->value);  // no permutation to build for a constant
      continue;
    }
    const double u = design_uniform(plan.design, plan.seed, stream_id(input.name),
                                    plan.samples_per_level, index);
    values.push_back(quantile(input.distribution, u));
  }
  return values;
}

Sampler::Sampler(SamplingPlan plan) : plan_(std::move(plan)), streams_(streams_of(plan_)) {
  check(plan_);
}

std::vector<double> Sampler::draw(std::uint64_t index) {
  const SamplePosition where = position(plan_, index);
  if (plan_.design == Design::latin_hypercube && (!level_ || level_->level() != where.level)) {
    level_.emplace(plan_.seed, streams_, where.level, plan_.samples_per_level);
  }
  std::vector<double> values;
  values.reserve(plan_.inputs.size());
  for (std::size_t k = 0; k < plan_.inputs.size(); ++k) {
    const double u = plan_.design == Design::latin_hypercube
                         ? level_->uniform(k, where.member)
                         : monte_carlo_uniform(plan_.seed, streams_[k], index);
    values.push_back(quantile(plan_.inputs[k].distribution, u));
  }
  return values;
}

}  // namespace blockfrag
