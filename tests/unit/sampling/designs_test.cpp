// Designs and plans: exact Latin hypercube stratification, the documented Fisher-Yates, and the
// purity that makes samples independent of order, rank count and of the other inputs.
#include "sampling/designs.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "engine/errors.hpp"
#include "sampling/philox_stream.hpp"
#include "sampling/sampling_plan.hpp"

namespace blockfrag {
namespace {

constexpr std::uint64_t kDesignsSeed = 20240611;

std::vector<std::uint32_t> identity(std::uint32_t n) {
  std::vector<std::uint32_t> values(n);
  std::iota(values.begin(), values.end(), 0u);
  return values;
}

std::uint32_t stratum_of(double u, std::uint32_t n) {
  return static_cast<std::uint32_t>(std::floor(u * n));
}

TEST(Designs, MonteCarloUsesTheSampleIndexAsCounter) {
  for (std::uint64_t index = 0; index < 100; ++index) {
    EXPECT_EQ(design_uniform(Design::monte_carlo, kDesignsSeed, 5, 10, index),
              uniform_open01(kDesignsSeed, 5, index));
  }
}

TEST(Designs, PermutationFollowsTheDocumentedFisherYates) {
  // Rebuilt here from the description in designs.hpp: swap k with
  // floor(bits (k + 1) / 2^64), k = n-1 .. 1, bits counted by (level, reserved bit | k).
  for (const std::uint32_t n : {1u, 2u, 3u, 10u}) {
    for (std::uint64_t level = 0; level < 5; ++level) {
      auto expected = identity(n);
      for (std::uint32_t k = n - 1; k > 0; --k) {
        const std::uint64_t bits = random_bits(kDesignsSeed, 9, level, 0x8000'0000u + k);
        __extension__ using Wide = unsigned __int128;
        const auto r = static_cast<std::uint32_t>((Wide{bits} * (k + 1)) >> 64);
        std::swap(expected[k], expected[r]);
      }
      EXPECT_EQ(latin_hypercube_permutation(kDesignsSeed, 9, level, n), expected)
          << n << " " << level;
    }
  }
}

TEST(Designs, EveryLevelAndInputFillsEachStratumExactlyOnce) {
  const std::vector<std::uint32_t> streams = {stream_id("friction"), stream_id("restitution"),
                                              stream_id("half_width"), 0u, 0xffffffffu};
  for (const std::uint32_t n : {1u, 2u, 7u, 100u, 1000u}) {
    for (std::uint64_t level = 0; level < 4; ++level) {
      const LatinHypercubeLevel hypercube(kDesignsSeed, streams, level, n);
      for (std::size_t dimension = 0; dimension < streams.size(); ++dimension) {
        std::vector<int> hits(n, 0);
        for (std::uint32_t j = 0; j < n; ++j) {
          const double u = hypercube.uniform(dimension, j);
          ASSERT_GT(u, 0.0);
          ASSERT_LT(u, 1.0);
          ASSERT_EQ(stratum_of(u, n), hypercube.stratum(dimension, j));
          ++hits[stratum_of(u, n)];
        }
        EXPECT_TRUE(std::all_of(hits.begin(), hits.end(), [](int h) { return h == 1; }))
            << "n " << n << " level " << level << " dimension " << dimension;
      }
    }
  }
}

TEST(Designs, PositionInsideTheStratumIsTheSamplesOwnUniform) {
  const std::uint32_t n = 50;
  const std::uint64_t level = 3;
  const auto permutation = latin_hypercube_permutation(kDesignsSeed, 4, level, n);
  for (std::uint32_t j = 0; j < n; ++j) {
    const double u = latin_hypercube_uniform(kDesignsSeed, 4, level, n, j);
    EXPECT_NEAR(u * n - permutation[j], uniform_open01(kDesignsSeed, 4, level * n + j), 1e-13);
  }
}

TEST(Designs, TopStratumNeverReachesOne) {
  // Why the design clamps: with v the largest uniform, (n - 1) + v rounds to n, so u would be 1.
  EXPECT_EQ((2 + max_open01) / 3, 1.0);
  for (const std::uint32_t n : {3u, 1000u, 0x8000'0000u}) {
    for (std::uint64_t index = 0; index < 1000; ++index) {
      EXPECT_LT(latin_hypercube_uniform_in_stratum(kDesignsSeed, 1, index, n - 1, n), 1.0);
      EXPECT_GT(latin_hypercube_uniform_in_stratum(kDesignsSeed, 1, index, 0, n), 0.0);
    }
  }
}

TEST(Designs, PermutationsDifferBetweenLevelsStreamsAndSeeds) {
  const std::uint32_t n = 50;  // two equal permutations by chance: 1 in 50! ~ 3e64
  const auto base = latin_hypercube_permutation(kDesignsSeed, 1, 0, n);
  EXPECT_NE(base, identity(n));
  EXPECT_NE(latin_hypercube_permutation(kDesignsSeed, 1, 1, n), base);
  EXPECT_NE(latin_hypercube_permutation(kDesignsSeed, 2, 0, n), base);
  EXPECT_NE(latin_hypercube_permutation(kDesignsSeed + 1, 1, 0, n), base);
  EXPECT_EQ(latin_hypercube_permutation(kDesignsSeed, 1, 0, n), base);
}

TEST(Designs, SingleSampleFunctionEqualsThePrecomputedLevel) {
  const std::vector<std::uint32_t> streams = {11u, stream_id("mu")};
  const std::uint32_t n = 64;
  for (std::uint64_t level = 0; level < 3; ++level) {
    const LatinHypercubeLevel hypercube(kDesignsSeed, streams, level, n);
    for (std::size_t dimension = 0; dimension < streams.size(); ++dimension) {
      for (std::uint32_t j = 0; j < n; ++j) {
        const double single =
            latin_hypercube_uniform(kDesignsSeed, streams[dimension], level, n, j);
        EXPECT_EQ(hypercube.uniform(dimension, j), single);
        EXPECT_EQ(design_uniform(Design::latin_hypercube, kDesignsSeed, streams[dimension], n,
                                 level * n + j),
                  single);
      }
    }
  }
}

TEST(Designs, RefusesAnEmptyLevelAndOutOfRangeSamples) {
  EXPECT_THROW(latin_hypercube_permutation(kDesignsSeed, 1, 0, 0), ContractViolation);
  EXPECT_THROW(latin_hypercube_uniform(kDesignsSeed, 1, 0, 4, 4), ContractViolation);
  const LatinHypercubeLevel hypercube(kDesignsSeed, {1u}, 0, 4);
  EXPECT_THROW(hypercube.uniform(1, 0), ContractViolation);
  EXPECT_THROW(hypercube.uniform(0, 4), ContractViolation);
}

SamplingPlan example_plan(Design design) {
  SamplingPlan plan;
  plan.seed = kDesignsSeed;
  plan.design = design;
  plan.samples_per_level = 20;
  plan.levels = 5;
  plan.inputs = {{"friction", Normal{0.6, 0.1, 0.0, std::nullopt}},
                 {"restitution", Uniform{0.0, 1.0}},
                 {"half_width", Fixed{0.5}},
                 {"scale", LogNormal{1.0, 0.3}}};
  return plan;
}

TEST(SamplingPlan, SampleValuesAreQuantilesOfTheDesignsUniforms) {
  for (const Design design : {Design::monte_carlo, Design::latin_hypercube}) {
    const SamplingPlan plan = example_plan(design);
    for (const std::uint64_t index : {0ull, 19ull, 20ull, 57ull, 99ull}) {
      const auto values = draw_sample(plan, index);
      ASSERT_EQ(values.size(), plan.inputs.size());
      for (std::size_t k = 0; k < plan.inputs.size(); ++k) {
        const double u = design_uniform(design, plan.seed, stream_id(plan.inputs[k].name),
                                        plan.samples_per_level, index);
        EXPECT_EQ(values[k], quantile(plan.inputs[k].distribution, u));
      }
      EXPECT_EQ(values[2], 0.5);
    }
  }
}

TEST(SamplingPlan, SamplerGivesTheSameValuesInAnyOrder) {
  for (const Design design : {Design::monte_carlo, Design::latin_hypercube}) {
    const SamplingPlan plan = example_plan(design);
    const std::uint64_t count = sample_count(plan);
    std::vector<std::vector<double>> in_order;
    for (std::uint64_t index = 0; index < count; ++index)
      in_order.push_back(draw_sample(plan, index));

    // Visit the indices in a scrambled order (37 is coprime with 100), jumping between levels, as
    // a dynamically scheduled rank would.
    Sampler sampler(plan);
    for (std::uint64_t step = 0; step < count; ++step) {
      const std::uint64_t index = (step * 37 + 11) % count;
      EXPECT_EQ(sampler.draw(index), in_order[index]) << index;
    }
    Sampler backwards(plan);
    for (std::uint64_t index = count; index-- > 0;)
      EXPECT_EQ(backwards.draw(index), in_order[index]);
  }
}

TEST(SamplingPlan, AnInputsValuesDependOnlyOnItsNameAndDistribution) {
  for (const Design design : {Design::monte_carlo, Design::latin_hypercube}) {
    const SamplingPlan plan = example_plan(design);
    SamplingPlan changed = plan;
    std::reverse(changed.inputs.begin(), changed.inputs.end());   // reorder
    changed.inputs.push_back({"amplitude", Uniform{0.1, 2.0}});   // add
    changed.inputs.erase(changed.inputs.begin() + 1);             // remove half_width
    std::get<Uniform>(changed.inputs[1].distribution).max = 0.9;  // change restitution
    ASSERT_EQ(changed.inputs[0].name, "scale");
    ASSERT_EQ(changed.inputs[2].name, "friction");
    for (std::uint64_t index = 0; index < sample_count(plan); ++index) {
      const auto before = draw_sample(plan, index);
      const auto after = draw_sample(changed, index);
      EXPECT_EQ(after[0], before[3]) << index;
      EXPECT_EQ(after[2], before[0]) << index;
      EXPECT_NE(after[1], before[1]) << index;
    }
  }
}

TEST(SamplingPlan, DifferentSeedsGiveDifferentSamples) {
  SamplingPlan plan = example_plan(Design::latin_hypercube);
  const auto first = draw_sample(plan, 7);
  plan.seed += 1;
  const auto second = draw_sample(plan, 7);
  EXPECT_NE(first[0], second[0]);
  EXPECT_NE(first[3], second[3]);
}

TEST(SamplingPlan, PositionSplitsTheIndexIntoLevelAndMember) {
  const SamplingPlan plan = example_plan(Design::monte_carlo);
  EXPECT_EQ(sample_count(plan), 100u);
  EXPECT_EQ(position(plan, 0).level, 0u);
  EXPECT_EQ(position(plan, 57).level, 2u);
  EXPECT_EQ(position(plan, 57).member, 17u);
  EXPECT_EQ(position(plan, 99).level, 4u);
  EXPECT_THROW(position(plan, 100), ContractViolation);
  EXPECT_THROW(draw_sample(plan, 100), ContractViolation);
  Sampler sampler(plan);
  EXPECT_THROW(sampler.draw(100), ContractViolation);
}

TEST(SamplingPlan, ValidationReportsEveryProblemWithItsPath) {
  SamplingPlan plan = example_plan(Design::latin_hypercube);
  EXPECT_TRUE(validate(plan).empty());
  plan.samples_per_level = 0;
  plan.levels = 0;
  plan.inputs.push_back({"friction", Uniform{0.0, 1.0}});
  plan.inputs.push_back({"", Normal{0.0, -2.0}});
  // These two names hash to the same FNV-1a value, 0xa361be57 (found by an offline search).
  ASSERT_EQ(stream_id("input_18839"), stream_id("input_766682"));
  plan.inputs.push_back({"input_18839", Fixed{1.0}});
  plan.inputs.push_back({"input_766682", Fixed{2.0}});
  const auto violations = validate(plan);
  std::vector<std::string> lines;
  for (const auto& violation : violations)
    lines.push_back(violation.field + ": " + violation.message);
  const std::vector<std::string> expected = {
      "samples_per_level: must be in [1, 2147483648] (got 0)",
      "levels: must be >= 1 (got 0)",
      "inputs/4/name: duplicates inputs/0/name (\"friction\")",
      "inputs/5/name: must not be empty",
      "inputs/5/std_dev: must be > 0 (got -2)",
      "inputs/7/name: \"input_766682\" and \"input_18839\" (inputs/6) hash to the same random "
      "stream: rename one",
  };
  EXPECT_EQ(lines, expected);
  try {
    check(plan);
    ADD_FAILURE() << "check accepted an invalid plan";
  } catch (const SamplingError& error) {
    EXPECT_EQ(error.violations().size(), expected.size());
    EXPECT_NE(std::string(error.what()).find("inputs/5/std_dev: must be > 0 (got -2)"),
              std::string::npos);
  }
  EXPECT_THROW(Sampler{plan}, SamplingError);
}

}  // namespace
}  // namespace blockfrag
