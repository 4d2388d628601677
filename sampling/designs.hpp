// Sampling designs: how the uniform u of input `stream` for sample `index` is chosen.
//
// A study has `levels` intensity levels of n = samples_per_level samples each, and sample index
// i = level n + j (0 <= j < n). Both designs give every input its own u, a pure function of
// (seed, stream, index) and the plan's n:
//
// - Monte Carlo: u = uniform_open01(seed, stream, index).
// - Latin hypercube: within each level and each input, the n samples fill the n
//   equal-probability strata [s/n, (s+1)/n) exactly once: sample j gets stratum s = pi[j], where
//   pi is a permutation of 0..n-1 that depends only on (seed, stream, level), and
//   u = (s + uniform_open01(seed, stream, index)) / n.
//
// The permutation is a Fisher-Yates shuffle with counter-based swaps: starting from the identity,
// for k = n-1 down to 1, swap pi[k] with pi[r] where
//   r = index_below(random_bits(seed, stream, level, reserved_draw_flag | k), k + 1).
// Its trip count is n - 1 whatever the random numbers, and its draws (counted by level, with the
// reserved draw bit) never coincide with a sample's own draws (counted by sample index).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace blockfrag {

enum class Design { monte_carlo, latin_hypercube };

double monte_carlo_uniform(std::uint64_t seed, std::uint32_t stream, std::uint64_t index);

// The Latin hypercube permutation pi of 0..n-1 for one (seed, stream, level); n >= 1.
std::vector<std::uint32_t> latin_hypercube_permutation(std::uint64_t seed, std::uint32_t stream,
                                                       std::uint64_t level, std::uint32_t n);

// u for one Latin hypercube sample from its stratum: strictly inside (0, 1), inside
// [stratum / n, (stratum + 1) / n].
double latin_hypercube_uniform_in_stratum(std::uint64_t seed, std::uint32_t stream,
                                          std::uint64_t index, std::uint32_t stratum,
                                          std::uint32_t n);

// u of sample j of `level` for one input, computed from scratch: O(n) (it builds the
// permutation). For tests and single look-ups; LatinHypercubeLevel draws a whole level in O(n).
double latin_hypercube_uniform(std::uint64_t seed, std::uint32_t stream, std::uint64_t level,
                               std::uint32_t n, std::uint32_t j);

// u of input `stream` for sample `index` under either design, computed from scratch.
double design_uniform(Design design, std::uint64_t seed, std::uint32_t stream,
                      std::uint32_t samples_per_level, std::uint64_t index);

// One level's Latin hypercube permutations for a list of inputs (dimensions), computed once:
// then every u of the level costs one Philox call. Equal to latin_hypercube_uniform.
class LatinHypercubeLevel {
 public:
  LatinHypercubeLevel(std::uint64_t seed, std::vector<std::uint32_t> streams, std::uint64_t level,
                      std::uint32_t samples_per_level);

  std::uint64_t level() const { return level_; }
  std::uint32_t stratum(std::size_t dimension, std::uint32_t j) const;
  double uniform(std::size_t dimension, std::uint32_t j) const;

 private:
  std::uint64_t seed_;
  std::vector<std::uint32_t> streams_;
  std::uint64_t level_;
  std::uint32_t samples_per_level_;
  std::vector<std::uint32_t> strata_;  // dimension-major: strata_[dimension n + j] = pi[j]
};

}  // namespace blockfrag
